#pragma once
// The load-dependent pressure (physics/pressure_response.hpp) on the spring-block lattice: before
// every step the friction law's per-site strengths (mu_s,i F_n,i and mu_k,i F_n,i) are rescaled
// by the block's normal force factor 1 + mu g_i, mu = F/(p L^2) the global friction the
// friction-history observer holds at the start of the step (the slider-force sum of the previous
// step's state: explicit in time, one step behind). The kernels keep their per-site strengths
// interface; only the law's numbers change between steps. PETSc-free.
#include "gradfric/physics/friction_law.hpp"

#include <cstdint>
#include <vector>

namespace gradfric::sbm {

// What the coupling saw over a run (for the run's record and the tests).
struct PressureCouplingRecord {
  bool active = false;
  std::int64_t updates = 0;          // steps whose strengths were rescaled
  double largestForceError = 0.0;    // max over steps |sum F_n,i / (p L^2) - 1|
  double largestMomentError = 0.0;   // max over steps |sum s_i dF_n,i / (H p L^2) - mu| (dF_n: the load's part)
  double smallestFactor = 1.0;       // min over steps and blocks of 1 + mu g_i (before clamping at 0)
  std::int64_t clampedSites = 0;     // site-steps whose factor was clamped at 0 (the block lifts off)
};

class PressureCoupling {
public:
  // base: the law's strengths at the static pressure p_i^0 (any layout); shape g_i, sliding
  // coordinates s_i [m] and weights p_i^0 / p per block (row-major, N_b^2); thickness H [m].
  PressureCoupling(const FrictionSites& base, int blocksPerSide, std::vector<double> shape,
                   std::vector<double> coordinates, std::vector<double> weights, double thickness);
  // The base strengths, one per block (the layout the rescaled strengths need).
  const FrictionSites& perSite() const { return base_; }
  const std::vector<double>& shape() const { return shape_; }
  // Strengths no larger than any the blocks have while mu(t) <= muBound: the base ones times
  // max(0, 1 + muBound min(g_i, 0)). A lattice built on them predicts a quiet phase (the jump
  // of Motion::skipIdle) that ends no later than the first slip under the rising load, so the
  // jump stays exact (model.cpp).
  FrictionSites quietPhaseSites(double muBound) const;
  // Sets sites' strengths to the base ones times max(0, 1 + mu g_i) and checks the totals.
  void apply(double mu, FrictionSites& sites);
  const PressureCouplingRecord& record() const { return record_; }

private:
  FrictionSites base_;
  std::vector<double> shape_, coordinates_, weights_;
  double thickness_ = 0.0, staticMoment_ = 0.0;
  double lastMu_ = -1.0;
  PressureCouplingRecord record_;
};

}  // namespace gradfric::sbm
