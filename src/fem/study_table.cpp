#include "gradfric/fem/study_table.hpp"

#include "gradfric/core/data_table.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace gradfric::fem {

namespace {

// "penalty" or "penalty,pc=1e-6/0.1": the contact method, then the Prakash-Clifton filter if any.
void splitContact(StudyRow& r) {
  const std::size_t comma = r.contact.find(",pc=");
  if (comma == std::string::npos) return;
  const std::string filter = r.contact.substr(comma + 4);
  r.contact.resize(comma);
  const std::size_t slash = filter.find('/');
  r.filter.length = std::stod(filter.substr(0, slash));
  r.filter.speed = slash == std::string::npos ? 0.0 : std::stod(filter.substr(slash + 1));
}

}  // namespace

std::vector<StudyRow> parseStudyTable(const std::string& text, StudyColumns columns) {
  const bool kinetic = columns == StudyColumns::KineticWithSpread;
  std::vector<StudyRow> parsed;
  forEachDataRow(text, kinetic ? "the FEM mu_k study table (docs/fem_study_kinetic.tsv)"
                               : "the FEM study table (docs/fem_study.tsv)",
                 [&](std::istringstream& fields) {
                   StudyRow r;
                   if (!(fields >> r.law >> r.slipLength >> r.property >> r.delta >> r.n >> r.nz >> r.edgeRatio >>
                         r.edgeBand >> r.element >> r.dtSafety >> r.contact >> r.mu))
                     return false;
                   if (kinetic && !(fields >> r.spread)) return false;
                   splitContact(r);
                   parsed.push_back(r);
                   return true;
                 });
  return parsed;
}

StudiedPlate studiedPlate(const Grading& g, double slidingAngleDegrees) {
  StudiedPlate plate;
  if (g.active()) {
    plate = {toString(g.property), g.delta};
    if (g.profile != GradingProfile::Linear) plate.property += std::string(",") + toString(g.profile);
  }
  // Sliding across a linear grading, the plate at -Delta is the mirror image (x -> L - x) of the one
  // at +Delta: the same mu_s to the last digit (docs/reproduction.md, Figure 8), so one study.
  if (slidingAngleDegrees == 90.0 && g.profile == GradingProfile::Linear) plate.delta = std::fabs(plate.delta);
  if (slidingAngleDegrees != 0.0) {
    char angle[40];
    std::snprintf(angle, sizeof angle, ",theta=%g", slidingAngleDegrees);
    plate.property += angle;
  }
  return plate;
}

StudySettings meshStudySettings(const FemParameters& q, const Grading& g) {
  StudySettings s;
  s.plate = studiedPlate(g, q.plate.slidingAngle);
  s.edge = q.edge;
  s.filter = q.normalFilter;
  return s;
}

namespace {

bool sameEdgeGrading(const StudyRow& r, const EdgeGrading& edge) {
  if (edge.uniform()) return r.edgeRatio == 1.0;
  return sameStudiedValue(r.edgeRatio, edge.ratio) && sameStudiedValue(r.edgeBand, edge.band);
}

}  // namespace

bool studyRowMatches(const StudyRow& r, const FemParameters& q, const StudySettings& s, int n, int nz) {
  return r.law == q.frictionLaw.name && sameStudiedValue(r.slipLength, q.frictionLaw.slipLength) &&
         r.property == s.plate.property && std::fabs(r.delta - s.plate.delta) < 1e-9 && r.n == n && r.nz == nz &&
         sameEdgeGrading(r, s.edge) && r.element == elementTypeName(q.element) &&
         std::fabs(r.dtSafety - s.dtSafety) < 1e-9 && r.contact == s.contact &&
         sameStudiedValue(r.filter.length, s.filter.length) && sameStudiedValue(r.filter.speed, s.filter.speed);
}

const StudyRow* findStudyRow(const std::vector<StudyRow>& rows, const FemParameters& q, const StudySettings& s, int n,
                             int nz) {
  for (const StudyRow& r : rows)
    if (studyRowMatches(r, q, s, n, nz)) return &r;
  return nullptr;
}

bool findMeshLadder(const std::vector<StudyRow>& rows, const FemParameters& q, const StudySettings& s, int n, int nz,
                    bool allDirections, const StudyRow* (&m)[3]) {
  bool complete = true;
  for (int k = 0; k < 3; ++k)
    complete = (m[k] = findStudyRow(rows, q, s, n << k, allDirections ? nz << k : nz)) != nullptr && complete;
  return complete;
}

std::string ladderMeshes(int n, int nz, bool allDirections) {
  char text[100];
  if (allDirections)
    std::snprintf(text, sizeof text, "%dx%dx%d/%dx%dx%d/%dx%dx%d", n, n, nz, 2 * n, 2 * n, 2 * nz, 4 * n, 4 * n, 4 * nz);
  else
    std::snprintf(text, sizeof text, "%dx%d/%d/%d x %d", n, n, 2 * n, 4 * n, nz);
  return text;
}

std::string percentText(double fraction) {
  char text[32];
  const double value = 100 * fraction;
  std::snprintf(text, sizeof text, value != 0.0 && std::fabs(value) < 0.1 ? "%.2g %%" : "%.2f %%", value);
  return text;
}

}  // namespace gradfric::fem
