#pragma once
// The discretisation bar printed and stored next to the statistical interval of every spring-block
// ensemble mean: the lattice (N_b) and time-step error of mu_s and mu_k at the run's setting,
// computed from the spring-block study's own measurements (docs/sbm_study.tsv, embedded at build
// time; docs/accuracy.md, "The discretisation bar"). Outside the studied settings, or where the
// study shows no convergence, the answer is "not measured": never a bar the study does not prove.
// Pure functions: part of the PETSc-free core (the FEM's counterpart is fem/error_estimate.hpp).
#include "gradfric/physics/friction_history.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/sbm/parameters.hpp"

#include <string>
#include <vector>

namespace gradfric::ensemble {

// One row of the study table.
//   kind "lattice": an ensemble mean at N_b blocks (value) with its standard error over R
//                   realisations, at the default step rule (dt "default");
//   kind "dt":      the relative error of one step (dt [s]) against RK4 at 1e-9 s, the largest over
//                   R same-seed realisations (stdError 0: paired, no statistical error).
struct SbmStudyRow {
  std::string kind, law, grading;  // grading: "none" or "friction" (linear, 10 bands)
  double delta = 0;
  int blocks = 0;  // N_b
  std::string observable;  // mu_s or mu_k
  int realisations = 0;
  double value = 0, stdError = 0;
  double dt = 0;  // kind dt: the step [s]; lattice: 0 (the default rule)
};

// The rows of a table in the format of docs/sbm_study.tsv ('#' lines are comments); a row that does
// not read throws std::invalid_argument naming its line (core/data_table.hpp).
std::vector<SbmStudyRow> parseSbmStudy(const std::string& text);
// The embedded docs/sbm_study.tsv.
const std::vector<SbmStudyRow>& sbmStudy();

struct SbmBarTerm {
  bool measured = false;
  double relative = 0;  // bound of |mu / mu_converged - 1| (fraction)
  std::string basis;    // what was measured, or why it was not
};

// The bound of member 0, 1 or 2 of a lattice ladder (N_b, 2 N_b, 4 N_b ensemble means), or none,
// by the rule both models share (core/refinement_ladder.hpp: each difference must exceed its 95 %
// statistical half-width; GCI or bracket widened by the half-width). ladder: its name in the basis.
SbmBarTerm latticeLadderTerm(const SbmStudyRow* const ladder[3], int member);

struct SbmDiscretisation {
  SbmBarTerm lattice, timeStep;
  bool measured = false;  // both terms measured
  double relative = 0;    // their sum (a bound: their signs are not known)
  std::string basis;      // the ladder, or every reason a term lacks a bound
};

// The bar of one sweep point's mu_s (kinetic false) or mu_k: parameters and grading of the point,
// measurement as resolved. study: the table (the embedded one by default).
SbmDiscretisation sbmDiscretisationError(const sbm::Parameters& parameters, const Grading& grading,
                                         const FrictionMeasurement& measurement, bool kinetic,
                                         const std::vector<SbmStudyRow>& study = sbmStudy());

// "discretisation +- 1.10 % (lattice 1.00 %, dt 0.10 %)" or "discretisation error not measured:
// <why>".
std::string describeBar(const SbmDiscretisation& bar);

}  // namespace gradfric::ensemble
