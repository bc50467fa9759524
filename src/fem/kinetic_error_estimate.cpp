#include "gradfric/fem/kinetic_error_estimate.hpp"

#include "gradfric/core/refinement_ladder.hpp"
#include "gradfric/fem/fem_study_data.hpp"  // generated: kFemKineticStudyTable, docs/fem_study_kinetic.tsv
#include "gradfric/fem/study_table.hpp"
#include "gradfric/physics/friction_history.hpp"  // kSteadyBatches
#include "gradfric/physics/state_weakening_law.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

namespace gradfric::fem {

double windowStandardError(double mean, double spread) {
  static_assert(kSteadyBatches == 4, "d2 = 2.059 is the expected range of 4 normal samples");
  return spread * std::fabs(mean) / (2.059 * std::sqrt(double(kSteadyBatches)));
}

namespace {

// The ladder refined in every direction (n x n x nz, 2n x 2n x 2nz, 4n x 4n x 4nz) holding the run's
// mesh, at the run's plate, dt / stable step, contact and filter; false if the study has none. Of
// several, the finest (the run its coarsest member), as for mu_s: Roache's likeliest asymptotic.
bool findLadder(const std::vector<StudyRow>& rows, const FemParameters& q, const Grading& g, double dtRatio,
                const StudyRow* (&m)[3], int& member) {
  StudySettings s = meshStudySettings(q, g);
  s.dtSafety = dtRatio;
  s.contact = contactMethodName(q.contactMethod);
  for (member = 0; member <= 2; ++member) {
    const int n = q.nx >> member, nz = q.nz >> member;
    if (n < 1 || nz < 1 || (n << member) != q.nx || (nz << member) != q.nz) continue;
    if (findMeshLadder(rows, q, s, n, nz, true, m))
      return true;
  }
  return false;
}

}  // namespace

std::string kineticErrorBasis(const FemParameters& q, const Grading& g, double dtRatio, const std::string& kineticTable) {
  const std::vector<StudyRow> rows = parseStudyTable(kineticTable, StudyColumns::KineticWithSpread);
  const StudyRow* m[3];
  int member = 0;
  if (!findLadder(rows, q, g, dtRatio, m, member))
    return "no mu_k ladder of this plate and mesh in the study (docs/fem_study_kinetic.tsv: the non-graded plate "
           "refined in every direction)";
  LadderRung rungs[3];
  for (int k = 0; k < 3; ++k) rungs[k] = {m[k]->mu, windowStandardError(m[k]->mu, m[k]->spread), kSteadyBatches};
  const LadderVerdict v = judgeLadder(rungs, member);
  char text[600];
  int used = std::snprintf(text, sizeof text, "mu_k ladder %s: %.6f, %.6f, %.6f (windows' spreads %s, %s, %s); ",
                           ladderMeshes(m[0]->n, m[0]->nz, true).c_str(), m[0]->mu, m[1]->mu, m[2]->mu,
                           percentText(m[0]->spread).c_str(),
                           percentText(m[1]->spread).c_str(), percentText(m[2]->spread).c_str());
  const double medium = m[1]->mu, coarse = m[0]->mu;
  if (v.outcome == LadderOutcome::NoSignal)
    used += std::snprintf(text + used, sizeof text - used,
                          "no mesh signal: the differences %+.3f %%, %+.3f %% lie within their 95 %% half-widths "
                          "%.3f %%, %.3f %%",
                          100 * v.first / coarse, 100 * v.second / medium, 100 * v.firstHalfWidth / coarse,
                          100 * v.secondHalfWidth / medium);
  else if (!v.converged())
    used += std::snprintf(text + used, sizeof text - used, "not converged: differences %+.3f %%, %+.3f %%",
                          100 * v.first / coarse, 100 * v.second / medium);
  else
    used += std::snprintf(text + used, sizeof text - used,
                          "the mesh ladder converges (bound %s of this mesh), but the time step and the contact are "
                          "not studied for mu_k",
                          percentText(v.bound).c_str());
  if (!g.active()) {
    StateWeakening law;  // the state law's steady state: Eq. 1 at the sliding speed
    law.slipLength = q.frictionLaw.slipLength;
    law.criticalVelocity = q.frictionLaw.criticalVelocity;
    const double exact = law.strengthBetween(q.plate.muStatic, q.plate.muKinetic,
                                             q.plate.velocity * law.slipLength / law.criticalVelocity);
    used += std::snprintf(text + used, sizeof text - used, "; against the exact steady value %.6f: %+.2f %%, %+.2f %%, %+.2f %%",
                          exact, 100 * (m[0]->mu / exact - 1), 100 * (m[1]->mu / exact - 1),
                          100 * (m[2]->mu / exact - 1));
  }
  return text;
}

std::string kineticErrorBasis(const FemParameters& q, const Grading& g, double dtRatio) {
  return kineticErrorBasis(q, g, dtRatio, kFemKineticStudyTable);
}

}  // namespace gradfric::fem
