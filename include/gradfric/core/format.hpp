#pragma once
// Numbers in messages and option records: 10 significant digits, no PETSc.
#include <cstdio>
#include <string>

namespace gradfric {

inline std::string formatReal(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

}  // namespace gradfric
