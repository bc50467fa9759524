#include "gradfric/fem/thickness_dt_contact_terms.hpp"

#include "gradfric/core/data_table.hpp"
#include "gradfric/core/refinement_ladder.hpp"
#include "gradfric/fem/ladder_term.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gradfric::fem {

namespace {

// The plate and in-plane mesh on which a term's ladder was measured (the time-step and contact
// terms: the non-graded 100 x 100 plate).
struct PlateMesh {
  StudiedPlate plate;
  int n = 100;
};

// One run of a term's study on that plate.
struct StudyRung {
  int nz;
  double dtSafety;
  const char* contact;
};

// Every rung found with this filter into m (on the uniform mesh); false if one is missing.
template <std::size_t N>
bool findRungs(const std::vector<StudyRow>& rows, const FemParameters& q, const PlateMesh& on,
               const StudyRung (&rungs)[N], const NormalStressFilter& filter, const StudyRow* (&m)[N]) {
  bool complete = true;
  for (std::size_t k = 0; k < N; ++k) {
    const StudySettings s{on.plate, rungs[k].dtSafety, rungs[k].contact, EdgeGrading{}, filter};
    complete = (m[k] = findStudyRow(rows, q, s, on.n, rungs[k].nz)) != nullptr && complete;
  }
  return complete;
}

// The rungs with the run's Prakash-Clifton filter where the study has them all, else those without
// it (the thickness, time-step and contact studies were first made without the filter). Returns
// ", with the filter" or "" for the term's text; m[k] null where a rung is missing.
template <std::size_t N>
const char* studyRungs(const std::vector<StudyRow>& rows, const FemParameters& q, const PlateMesh& on,
                       const StudyRung (&rungs)[N], const StudyRow* (&m)[N]) {
  if (q.normalFilter.active() && findRungs(rows, q, on, rungs, q.normalFilter, m)) return ", with the filter";
  findRungs(rows, q, on, rungs, NormalStressFilter{}, m);
  return "";
}

std::string thicknessLadderName(const PlateMesh& on, const char* filter) {
  char text[160];
  if (on.plate.property == "none")
    std::snprintf(text, sizeof text, "nz 5/10/20 (non-graded %dx%d%s)", on.n, on.n, filter);
  else
    std::snprintf(text, sizeof text, "nz 5/10/20 (%s %+g, %dx%d%s)", on.plate.property.c_str(), on.plate.delta, on.n,
                  on.n, filter);
  return text;
}

}  // namespace

// The thickness error depends on the in-plane mesh (refined alone through the thickness, the corner
// singularity converges differently on each), hence the finer in-plane meshes' ladders and the
// largest of their bounds.
ErrorTerm thicknessTerm(const std::vector<StudyRow>& rows, const FemParameters& q, const Grading& g) {
  const int member = q.nz == 5 ? 0 : q.nz == 10 ? 1 : q.nz == 20 ? 2 : -1;
  if (member < 0) return {false, 0, "nz other than 5, 10 or 20 (the thickness study: 5/10/20)"};
  const StudyRung rungs[3] = {{5, 0.6, "penalty"}, {10, 0.6, "penalty"}, {20, 0.6, "penalty"}};
  std::vector<PlateMesh> plates;
  const StudiedPlate run = studiedPlate(g, q.plate.slidingAngle);
  if (run.property != "none") plates.push_back({run, q.nx});
  plates.push_back({StudiedPlate{}, q.nx});
  plates.push_back({StudiedPlate{}, 100});
  for (const PlateMesh& on : plates) {
    const StudyRow* m[3];
    const char* filter = studyRungs(rows, q, on, rungs, m);
    if (!m[0] || !m[1] || !m[2]) continue;
    ErrorTerm term = ladderTerm("thickness", thicknessLadderName(on, filter), m, member);
    term.filtered = *filter != '\0';
    const NormalStressFilter rowsFilter = term.filtered ? q.normalFilter : NormalStressFilter{};
    for (PlateMesh finer{on.plate, 2 * on.n}; term.measured && findRungs(rows, q, finer, rungs, rowsFilter, m);
         finer.n *= 2) {
      const ErrorTerm other = ladderTerm("thickness", thicknessLadderName(finer, filter), m, member);
      if (!other.measured)
        return {false, 0, other.basis + "; so the coarser " + thicknessLadderName(on, filter) + " proves no bar",
                term.filtered};
      term.relative = std::max(term.relative, other.relative);
      term.basis += "; " + other.basis + " (the larger bound taken)";
    }
    return term;
  }
  return {false, 0, "thickness ladder nz 5/10/20 not measured for this D_c"};
}

// As the mesh term: every finer ladder the study has (0.3/0.15/0.075, ...) must converge too, and
// where 0.6/0.3/0.15 does not, 0.6 is bounded through the finest step of the finer ones.
ErrorTerm timeStepTerm(const std::vector<StudyRow>& rows, const FemParameters& q, double dtRatio) {
  if (dtRatio > 0.6 + 1e-9) return {false, 0, "dt above 0.6 of the stable step"};
  const StudyRow* m[3];
  const char* filter =
      studyRungs(rows, q, PlateMesh{}, {{5, 0.6, "penalty"}, {5, 0.3, "penalty"}, {5, 0.15, "penalty"}}, m);
  if (!m[0] || !m[1] || !m[2]) return {false, 0, "dt ladder 0.6/0.3/0.15 not measured for this D_c"};
  const NormalStressFilter rowsFilter = *filter ? q.normalFilter : NormalStressFilter{};
  // The ladder 0.6/k, 0.3/k, 0.15/k (k = 1, 2, 4, ...).
  const auto ladderName = [&](int k) {
    char text[120];
    std::snprintf(text, sizeof text, "dt_safety %g/%g/%g (non-graded 100x100%s)", 0.6 / k, 0.3 / k, 0.15 / k, filter);
    return std::string(text);
  };
  const StudyRow* f[3];
  const auto findLadder = [&](int k) {
    const StudyRung rungs[3] = {{5, 0.6 / k, "penalty"}, {5, 0.3 / k, "penalty"}, {5, 0.15 / k, "penalty"}};
    return findRungs(rows, q, PlateMesh{}, rungs, rowsFilter, f);
  };
  ErrorTerm check, term;
  const FinerLadders finer = walkFinerLadders(
      1, findLadder, [&](int k) { return !(check = ladderTerm("dt", ladderName(k), f, 0)).measured; });
  if (finer.disproving) {
    term = {false, 0, check.basis + "; so the coarser " + ladderName(1) + " proves no bar"};
  } else {
    term = ladderTerm("dt", ladderName(1), m, 0);
    if (!term.measured && finer.finest > 1) {
      findLadder(finer.finest);  // the walk's last probe (one finer) left f partly filled
      term = throughFinerValue("dt", term, m[0]->mu, ladderTerm("dt", ladderName(finer.finest), f, 2), f[2]->mu);
    }
  }
  term.filtered = *filter != '\0';
  return term;
}

ErrorTerm contactTerm(const std::vector<StudyRow>& rows, const FemParameters& q) {
  if (q.contactMethod == ContactMethod::Kinematic) return {true, 0.0, "kinematic contact (the reference)"};
  const double defaultStiffness = defaultPenaltyStiffness(q.plate);
  if (!sameStudiedValue(q.kn, defaultStiffness) || !sameStudiedValue(q.kt, defaultStiffness))
    return {false, 0, "penalty stiffness other than 250 G/H"};
  const StudyRow* m[2];
  const char* filter = studyRungs(rows, q, PlateMesh{}, {{5, 0.6, "penalty"}, {5, 0.6, "kinematic"}}, m);
  if (!m[0] || !m[1]) return {false, 0, "penalty vs kinematic not measured for this D_c"};
  const double bound = 1.25 * std::fabs(m[0]->mu - m[1]->mu) / std::fabs(m[1]->mu);
  char text[200];
  std::snprintf(text, sizeof text, "penalty vs kinematic %.6f vs %.6f (non-graded 100x100%s)", m[0]->mu, m[1]->mu,
                filter);
  return {true, bound, text, *filter != '\0'};
}

}  // namespace gradfric::fem
