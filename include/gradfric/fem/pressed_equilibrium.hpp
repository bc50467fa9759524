#pragma once
// The static pressure step (-fem_pressure_step static): instead of ramping the pressure over
// 20 H/c_s and letting the plate settle for 10 H/c_s (step 1 of the paper's experiment), solve the
// pressed equilibrium directly: the elastic operator plus the penalty contact springs of every
// bottom node (normal k_n, tangential k_t anchored where the node stands at rest), loaded by the
// layers' dead loads (the top pressure p, the weight with -fem_gravity), (K + P) u = f,
// matrix-free (MatShell on the specialised kernel, KSPCG with a Jacobi preconditioner). That
// system is linear as long as every bottom node stays in contact and sticks
// (|k_t u_t| <= mu_s k_n |u_z|): the solution is then checked with the contact law itself (one
// right-hand side evaluation) and committed as the contact state, the plate at rest. Otherwise (a
// node lifts off or would slip) the solution does not hold and the caller runs the dynamic step
// instead.
#include "gradfric/fem/plate_model.hpp"

#include <string>

namespace gradfric::fem {

struct PressedEquilibrium {
  bool holds = false;     // every bottom node in contact and sticking: X is the pressed state
  int iterations = 0;     // CG iterations
  double residual = 0;    // final preconditioned residual norm over the initial one
  double normalForce = 0; // total contact normal force [N] (summed over ranks)
  long long slipping = 0, open = 0;
  std::string why;        // when it does not hold
};

// Collective. X: a zero state of the model (global); on success X = [u, 0] and the contact state
// is committed. relativeTolerance: CG's relative residual tolerance.
PressedEquilibrium solvePressedEquilibrium(PlateModel& model, Vec X, double relativeTolerance = 1e-12);

}  // namespace gradfric::fem
