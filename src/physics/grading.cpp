#include "gradfric/physics/grading.hpp"

#include <sstream>

namespace gradfric {

const char* toString(GradingProfile profile) {
  switch (profile) {
    case GradingProfile::Linear: return "linear";
    case GradingProfile::Triangular: return "triangular";
    default: return "none";
  }
}

const char* toString(GradedProperty property) {
  switch (property) {
    case GradedProperty::Friction: return "friction";
    case GradedProperty::Both: return "both";
    default: return "E";
  }
}

std::string describe(const Grading& g) {
  if (!g.active()) return "none (uniform plate)";
  std::ostringstream out;
  out << toString(g.profile) << " grading of " << toString(g.property) << ", Delta = " << g.delta << ", "
      << g.bands << " bands along x";
  return out.str();
}

}  // namespace gradfric
