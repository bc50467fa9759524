#pragma once
// The plate's own weight (-fem_gravity g [m/s^2]; 0, the default: off, the layer not built): a
// body force -m_b g on the z of every node, m_b its lumped mass (lumped_mass.hpp, rho V_cell / 8
// from each cell), so the plane carries p L^2 + rho g H L^2 at rest. It matters for a soft thick
// plate under a small dead load (rho g H = 0.59 Pa at the defaults against p = 1e4 Pa, 59 Pa at
// H = 5 mm). A dead load: it adds no stiffness, so the stable step (stable_step.cpp) is unchanged.
// The layer owns its option: the -fem_ reader calls readOptions, PlateModel builds it when wanted.
#include "gradfric/core/exact_sum.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/fem/layer.hpp"
#include "gradfric/fem/lumped_mass.hpp"
#include "gradfric/fem/parameters.hpp"

#include <vector>

namespace gradfric::fem {

class Gravity : public Layer {
public:
  // Reads -fem_gravity into q.gravity and refuses a negative value (a non-finite one is refused by
  // the reader), naming the option, before any work.
  static void readOptions(OptionReader& o, FemParameters& q);
  static bool wanted(const FemParameters& q) { return q.gravity > 0; }
  // The weight's pressure on the plane, rho g H [Pa] (0 without -fem_gravity).
  static double weightPressure(const FemParameters& q) { return q.plate.density * q.gravity * q.plate.thickness; }

  Gravity(const LumpedMass& mass, const FemParameters& q);

  const char* name() const override { return "gravity"; }
  void addForce(const LayerContext& ctx, Vec X, Vec F, ContactSums& sums) override;
  void addDeadLoad(Vec F) const override { addWeight(F); }
  void postStep(double) override;
  // Minus the work of the weight: m g u_z summed (the work of a constant force along any path),
  // less half of its value at the first accepted step.
  LayerWork work() const override;
  std::string describe() const override;

private:
  void addWeight(Vec F) const;

  std::vector<double> weight_;  // m_b g per owned block [N]
  double g_, weightPressure_, pressure_;  // g [m/s^2], rho g H and p [Pa] (the description)
  // This rank's sum of m g u_z at the state of the last right-hand side (pending) and of the last
  // accepted step; -m g u_z / 2 at the first accepted step.
  ExactSum pending_, pendingHalf_, committed_, firstHalf_;
  bool started_ = false;
};

}  // namespace gradfric::fem
