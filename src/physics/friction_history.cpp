#include "gradfric/physics/friction_history.hpp"

#include <cmath>

namespace gradfric {

FrictionHistory::FrictionHistory(const FrictionMeasurement& measurement, double normalForce, double timeStep)
    : rule_(measurement), normalForce_(normalForce), timeStep_(timeStep) {}

double FrictionHistory::observe(double t, double fx, double fy, bool anySlipped, bool allSlipped) {
  const double mu = std::hypot(fx, fy) / normalForce_;
  lastTime_ = t;
  observed_ = true;
  if (anySlipped && std::isnan(firstSlip_)) firstSlip_ = t;
  if (!confirmed_) {
    if (mu > maximum_) {
      maximum_ = mu;
      peakTime_ = t;
      // The window lies after the maximum: what came before it can no longer be in it.
      sinceTime_.clear();
      sinceMu_.clear();
    }
    if (allSlipped && (mu < (1.0 - rule_.peakDrop) * maximum_ || t - peakTime_ >= rule_.peakHold)) confirmed_ = true;
  }
  if (rule_.kinetic && t <= peakTime_ + rule_.kineticDelay + rule_.kineticWidth) {
    sinceTime_.push_back(t);
    sinceMu_.push_back(mu);
  }
  if (t >= nextSample_ - 0.5 * timeStep_) {
    history_.time.push_back(t);
    history_.mu.push_back(mu);
    history_.forceX.push_back(fx);
    history_.forceY.push_back(fy);
    nextSample_ += rule_.historyInterval > 0 ? rule_.historyInterval : timeStep_;
  }
  return mu;
}

bool FrictionHistory::known() const {
  return confirmed_ && (!rule_.kinetic || lastTime_ >= peakTime_ + rule_.kineticDelay + rule_.kineticWidth);
}

FrictionSummary FrictionHistory::summary() const {
  FrictionSummary s = history_;
  if (!observed_) return s;
  s.muStatic = maximum_;
  s.peakTime = peakTime_;
  s.peakConfirmed = confirmed_;
  s.firstSlipTime = firstSlip_;
  if (rule_.kinetic && confirmed_) {
    const double from = peakTime_ + rule_.kineticDelay, to = from + rule_.kineticWidth;
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < sinceTime_.size(); ++i)
      if (sinceTime_[i] >= from && sinceTime_[i] <= to) {
        sum += sinceMu_[i];
        ++count;
      }
    s.kineticComplete = count > 0 && lastTime_ >= to - timeStep_;
    if (s.kineticComplete) s.muKinetic = sum / double(count);
  }
  return s;
}

}  // namespace gradfric
