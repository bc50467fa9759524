#include "gradfric/core/format.hpp"

#include <cstdio>

namespace gradfric {

std::string formatReal(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

}  // namespace gradfric
