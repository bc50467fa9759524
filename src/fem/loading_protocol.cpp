#include "gradfric/fem/loading_protocol.hpp"

#include <algorithm>
#include <cmath>

namespace gradfric::fem {

double LoadingProtocol::pressureAt(double t) const {
  const double p = q_.plate.pressure;
  if (sliding() || q_.rampTime <= 0) return p;
  return p * std::min(1.0, t / q_.rampTime);
}

bool LoadingProtocol::peakDampingDue(bool peakConfirmed, bool slipping, double mu, double peak) const {
  using Start = FemParameters::DampingStart;
  return peakConfirmed || q_.peakDampingStart == Start::Sliding ||
         (q_.peakDampingStart == Start::Drop && slipping && mu < (1.0 - q_.measurement.peakDrop) * peak);
}

bool LoadingProtocol::startPeakDamping() {
  if (peakDampingOn_ || !sliding()) return false;
  peakDampingOn_ = true;
  return q_.peakDamping > 0 || q_.peakStiffnessDamping > 0;
}

SlidingDamping LoadingProtocol::massDamping() const {
  SlidingDamping d;
  if (!sliding()) {
    d.lab = q_.settleDamping;
    return d;
  }
  d.lab = q_.slideDamping;
  if (peakDampingOn_) {
    const double theta = q_.plate.angleRadians();
    d.slider = q_.peakDamping;
    d.sliderVelocity[0] = q_.plate.velocity * std::cos(theta);
    d.sliderVelocity[1] = q_.plate.velocity * std::sin(theta);
  }
  return d;
}

double LoadingProtocol::stiffnessDamping() const {
  return peakDampingOn_ && q_.peakStiffnessDamping > 0 ? q_.stiffnessDamping + q_.peakStiffnessDamping
                                                        : q_.stiffnessDamping;
}

}  // namespace gradfric::fem
