#pragma once
// The Prakash-Clifton normal-stress filter of the contact (-fem_pc_length, -fem_pc_speed): the
// friction strength of a node is mu times a filtered pressure p* that follows the contact pressure
// p over a slip length L rather than at once,
//   dp*/dt = (|V| + V*) (p - p*) / L,
// with V the node's slip rate and V* a reference speed (p* follows p at rest too, over L / V*).
// Why: a deformable body sliding on a rigid plane under Coulomb friction has a growing interface
// mode at about sqrt(2) c_s when mu > 1, with a growth rate proportional to the wavenumber (the
// problem is ill-posed: every finer mesh admits faster modes). Friction grading puts the local
// mu_s above 1 on one side of the plate. The filter bounds the growth at short wavelengths
// (Ranjith & Rice 2001; Cochard & Rice 2000; Kammer et al. 2014; the slip-based form, preferred by
// Scala et al. 2017, is SEM2DPACK's). docs/accuracy_fem.md, "Local mu_s above 1", measures it.
// The spring-block model needs no filter: a block's normal force does not change in time.
// Pure arithmetic, no PETSc.
#include <cmath>

namespace gradfric::fem {

struct NormalStressFilter {
  double length = 0.0;  // L [m] (-fem_pc_length); 0: off, the strength follows the pressure at once
  double speed = 0.0;   // V* [m/s] (-fem_pc_speed)

  bool active() const { return length > 0.0; }
  // p* after a step dt [s] at slip rate slipRate [m/s] under pressure p, from filtered: exact for a
  // constant slip rate and pressure over the step (so the step size does not enter the law).
  double relax(double filtered, double pressure, double slipRate, double dt) const {
    if (!active()) return pressure;
    const double decay = std::exp(-(std::fabs(slipRate) + speed) * dt / length);
    return pressure + (filtered - pressure) * decay;
  }
};

}  // namespace gradfric::fem
