#include "gradfric/physics/grading.hpp"

#include <sstream>
#include <stdexcept>

namespace gradfric {

const GradingProfileRow& gradingProfileRow(GradingProfile profile) {
  for (const GradingProfileRow& row : kGradingProfiles)
    if (row.profile == profile) return row;
  throw std::logic_error("a grading profile without its row in kGradingProfiles");
}

GradingProfile parseGradingProfile(const std::string& name) {
  for (const GradingProfileRow& row : kGradingProfiles)
    if (name == row.name) return row.profile;
  throw std::invalid_argument("unknown grading profile '" + name + "'");
}

std::vector<std::string> gradingProfileNames() {
  std::vector<std::string> names;
  for (const GradingProfileRow& row : kGradingProfiles) names.emplace_back(row.name);
  return names;
}

const char* toString(GradingProfile profile) { return gradingProfileRow(profile).name; }

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
