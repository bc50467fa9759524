// Per-step rescaling of the friction strengths by the load-dependent pressure (pressure_coupling.hpp).
#include "gradfric/sbm/pressure_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace gradfric::sbm {

PressureCoupling::PressureCoupling(const FrictionSites& base, int nb, std::vector<double> shape,
                                   std::vector<double> coordinates, std::vector<double> weights, double thickness)
    : shape_(std::move(shape)), coordinates_(std::move(coordinates)), weights_(std::move(weights)),
      thickness_(thickness) {
  const std::size_t n = std::size_t(nb) * nb;
  base_.layout = SiteLayout::PerSite;
  base_.columns = nb;
  base_.staticStrength.resize(n);
  base_.kineticStrength.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int slot = base.slotOfSite(static_cast<int>(i));
    base_.staticStrength[i] = base.staticAt(slot);
    base_.kineticStrength[i] = base.kineticAt(slot);
  }
  if (weights_.empty()) weights_.assign(n, 1.0);
  for (std::size_t i = 0; i < n; ++i) staticMoment_ += weights_[i] * coordinates_[i];
  record_.active = true;
}

FrictionSites PressureCoupling::quietPhaseSites(double muBound) const {
  FrictionSites sites = base_;
  for (std::size_t i = 0; i < shape_.size(); ++i) {
    const double factor = std::max(0.0, 1.0 + muBound * std::min(shape_[i], 0.0));
    sites.staticStrength[i] *= factor;
    sites.kineticStrength[i] *= factor;
  }
  return sites;
}

void PressureCoupling::apply(double mu, FrictionSites& sites) {
  if (mu == lastMu_) return;  // the same load: the same strengths
  lastMu_ = mu;
  ++record_.updates;
  const std::size_t n = shape_.size();
  double force = 0.0, moment = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double raw = 1.0 + mu * shape_[i];
    record_.smallestFactor = std::min(record_.smallestFactor, raw);
    if (raw < 0.0) ++record_.clampedSites;
    const double factor = std::max(raw, 0.0);  // a block whose pressure would turn negative lifts off
    sites.staticStrength[i] = base_.staticStrength[i] * factor;
    sites.kineticStrength[i] = base_.kineticStrength[i] * factor;
    force += weights_[i] * factor;
    moment += weights_[i] * coordinates_[i] * factor;
  }
  const double blocks = static_cast<double>(n);
  record_.largestForceError = std::max(record_.largestForceError, std::fabs(force / blocks - 1.0));
  record_.largestMomentError =
      std::max(record_.largestMomentError, std::fabs((moment - staticMoment_) / (blocks * thickness_) - mu));
}

}  // namespace gradfric::sbm
