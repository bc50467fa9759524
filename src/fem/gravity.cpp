#include "gradfric/fem/gravity.hpp"

#include "gradfric/fem/state_view.hpp"

#include <cstdio>

namespace gradfric::fem {

void Gravity::readOptions(OptionReader& o, FemParameters& q) {
  q.gravity = o.real("gravity", q.gravity, "m/s^2",
                     "the plate's own weight: body force -m g on every node, m its lumped mass (9.81 on Earth; "
                     "0: off)");
  o.requireNonNegative("gravity", q.gravity, "m/s^2");
}

Gravity::Gravity(const LumpedMass& mass, const FemParameters& q)
    : g_(q.gravity), weightPressure_(weightPressure(q)), pressure_(q.plate.pressure) {
  for (double m : mass.perBlock()) weight_.push_back(m * g_);
}

void Gravity::addWeight(Vec F) const {
  const WriteState f(F);
  for (PetscInt b = 0; b < static_cast<PetscInt>(weight_.size()); ++b) f.force(b)[2] -= weight_[b];
}

// The energy the weight put in is counted as the pressure's (energy_monitor.cpp: p = 0 before the
// first step), the trapezoid from no weight over the first accepted step: sum m g (-du_z) over the
// steps is then -(m g u_z now) + (m g u_z at the first step) / 2. In a dynamic run that first step
// moves the plate by g dt^2 / 2 (a negligible share); after the static pressure step it is the
// work of the weight loaded with the pressure, half m g u_z, as the elastic energy it holds.
void Gravity::addForce(const LayerContext&, Vec X, Vec F, ContactSums&) {
  addWeight(F);
  pending_ = ExactSum();
  pendingHalf_ = ExactSum();
  const ReadState x(X);
  for (PetscInt b = 0; b < static_cast<PetscInt>(weight_.size()); ++b) {
    const double potential = weight_[b] * x.displacement(b)[2];
    pending_.add(potential);
    if (!started_) pendingHalf_.add(-0.5 * potential);
  }
}

// The right-hand side of the accepted step saw its end state (gfverlet: one evaluation a step).
void Gravity::postStep(double) {
  committed_ = pending_;
  if (!started_) firstHalf_ = pendingHalf_;
  started_ = true;
}

LayerWork Gravity::work() const {
  LayerWork w;
  w.rankShare = committed_;
  w.rankShare += firstHalf_;
  return w;
}

std::string Gravity::describe() const {
  char text[200];
  std::snprintf(text, sizeof text,
                "own weight, g %.4g m/s^2: rho g H = %.4g Pa (%.3g of p) on the plane, -m g on each node (no "
                "stiffness: the stable step unchanged)",
                g_, weightPressure_, weightPressure_ / pressure_);
  return text;
}

}  // namespace gradfric::fem
