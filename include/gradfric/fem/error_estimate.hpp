#pragma once
// The error bar printed and stored with every FEM result: the discretisation error of mu_s for the
// mesh, thickness, time step, contact and scene of the run, computed from the convergence study's
// measurements (docs/fem_study.tsv; docs/accuracy_fem.md, "Convergence of mu_s"): outside the
// studied settings, or where the study shows no convergence, the answer is "not measured".
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/grading.hpp"

#include <string>

namespace gradfric::fem {

struct ErrorTerm {
  bool measured = false;
  double relative = 0;  // |mu / mu_converged - 1| bound of this term (fraction)
  std::string basis;    // what was measured, or why it was not
  bool filtered = false;  // measured with the run's Prakash-Clifton filter (else without it)
};

struct DiscretisationError {
  ErrorTerm mesh, thickness, timeStep, contact;  // mu_s terms
  bool measured = false;              // every term measured
  double relative = 0;                // sum of the terms (a bound: their signs are not known)
  std::string basis;                  // the terms, or the first one not measured
  std::string kineticBasis;           // mu_k carries no bar: why, and what its study measured
                                      // (kinetic_error_estimate.hpp)
};

// params as resolved (PlateModel::params()); dtRatio = dt / stable step of the run.
DiscretisationError discretisationError(const FemParameters& params, const Grading& grading, double dtRatio);
// The same from another study table (the text of a fem_study.tsv): the rules checked on ladders of
// known limit (tests).
DiscretisationError discretisationError(const FemParameters& params, const Grading& grading, double dtRatio,
                                        const std::string& studyTable);

// "0.883912 +- 1.3 % (discretisation: mesh 0.5 %, ...)" or "0.883912 (discretisation error not
// measured: ...)".
std::string withErrorBar(double mu, const DiscretisationError& error);
std::string withKineticErrorBar(double mu, const DiscretisationError& error);

}  // namespace gradfric::fem
