#include "gradfric/physics/friction_history.hpp"

#include <algorithm>
#include <cmath>

namespace gradfric {

FrictionHistory::FrictionHistory(const FrictionMeasurement& measurement, double normalForce, double timeStep)
    : rule_(measurement), normalForce_(normalForce), timeStep_(timeStep) {}

double FrictionHistory::latestStart() const { return std::max(rule_.kineticDelay, rule_.kineticLatestDelay); }

double FrictionHistory::observe(double t, double fx, double fy, bool anySlipped, bool allSlipped) {
  const double mu = std::hypot(fx, fy) / normalForce_;
  lastTime_ = t;
  observed_ = true;
  if (anySlipped && std::isnan(firstSlip_)) firstSlip_ = t;
  if (allSlipped && std::isnan(detachment_)) detachment_ = t;
  if (!confirmed_) {
    if (mu > maximum_) {
      maximum_ = mu;
      peakTime_ = t;
      // The window lies after the maximum: what came before it can no longer be in it.
      sinceTime_.clear();
      sinceMu_.clear();
      prefix_.assign(1, 0.0);
    }
    if (allSlipped && (mu < (1.0 - rule_.peakDrop) * maximum_ || t - peakTime_ >= rule_.peakHold)) confirmed_ = true;
  }
  const bool steadyRule = rule_.kineticSteadyTolerance > 0;
  const double lastEnd = peakTime_ + (steadyRule ? latestStart() : rule_.kineticDelay) + rule_.kineticWidth;
  if (rule_.kinetic && !windowDecided_ && t <= lastEnd) {
    sinceTime_.push_back(t);
    sinceMu_.push_back(mu);
    if (steadyRule) prefix_.push_back(prefix_.back() + mu);
  }
  if (steadyRule && rule_.kinetic && confirmed_ && !windowDecided_) advanceSteadyWindow(t);
  if (t >= nextSample_ - 0.5 * timeStep_) {
    history_.time.push_back(t);
    history_.mu.push_back(mu);
    history_.forceX.push_back(fx);
    history_.forceY.push_back(fy);
    nextSample_ += rule_.historyInterval > 0 ? rule_.historyInterval : timeStep_;
  }
  return mu;
}

// The window ending now is tested once the first one has been observed; the last one allowed
// (starting latestStart() after the peak) decides either way.
void FrictionHistory::advanceSteadyWindow(double t) {
  if (t < peakTime_ + rule_.kineticDelay + rule_.kineticWidth) return;
  const double latest = peakTime_ + latestStart();
  const bool last = t - rule_.kineticWidth >= latest - 0.5 * timeStep_;
  const double from = last ? latest : t - rule_.kineticWidth;
  const Window w = windowStats(from, from + rule_.kineticWidth);
  if (!(w.spread <= rule_.kineticSteadyTolerance) && !last) return;
  windowDecided_ = true;
  windowSteady_ = w.spread <= rule_.kineticSteadyTolerance;
  windowFrom_ = from;
}

FrictionHistory::Window FrictionHistory::windowStats(double from, double to) const {
  auto index = [&](double time) {
    return static_cast<std::size_t>(std::lower_bound(sinceTime_.begin(), sinceTime_.end(), time) - sinceTime_.begin());
  };
  auto sum = [&](std::size_t a, std::size_t b) {
    if (prefix_.size() == sinceMu_.size() + 1) return prefix_[b] - prefix_[a];
    double s = 0.0;
    for (std::size_t i = a; i < b; ++i) s += sinceMu_[i];
    return s;
  };
  const std::size_t first = index(from), end = std::upper_bound(sinceTime_.begin(), sinceTime_.end(), to) - sinceTime_.begin();
  Window w{from, to, FrictionSummary::kNaN, FrictionSummary::kNaN};
  if (end <= first) return w;
  w.mean = sum(first, end) / double(end - first);
  double low = INFINITY, high = -INFINITY;
  for (int b = 0; b < kSteadyBatches; ++b) {
    const std::size_t a = b == 0 ? first : std::max(first, index(from + b * (to - from) / kSteadyBatches));
    const std::size_t z = b == kSteadyBatches - 1 ? end : std::max(a, index(from + (b + 1) * (to - from) / kSteadyBatches));
    if (z <= a) return w;  // a batch without samples: no spread
    const double m = sum(a, z) / double(z - a);
    low = std::min(low, m);
    high = std::max(high, m);
  }
  w.spread = (high - low) / std::fabs(w.mean);
  return w;
}

bool FrictionHistory::known() const {
  if (!confirmed_ || !rule_.kinetic) return confirmed_;
  if (rule_.kineticSteadyTolerance > 0) return windowDecided_;
  return lastTime_ >= peakTime_ + rule_.kineticDelay + rule_.kineticWidth;
}

FrictionSummary FrictionHistory::summary() const {
  FrictionSummary s = history_;
  if (!observed_) return s;
  s.muStatic = maximum_;
  s.peakTime = peakTime_;
  s.peakConfirmed = confirmed_;
  s.firstSlipTime = firstSlip_;
  s.detachmentTime = detachment_;
  if (rule_.kinetic && confirmed_) {
    const bool steadyRule = rule_.kineticSteadyTolerance > 0;
    const double from = steadyRule ? windowFrom_ : peakTime_ + rule_.kineticDelay, to = from + rule_.kineticWidth;
    // The mean is a plain sum in time order (the fixed window's result, bit for bit as before).
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < sinceTime_.size(); ++i)
      if (sinceTime_[i] >= from && sinceTime_[i] <= to) {
        sum += sinceMu_[i];
        ++count;
      }
    s.kineticComplete = steadyRule ? windowDecided_ && count > 0 : count > 0 && lastTime_ >= to - timeStep_;
    s.kineticSteadyTested = steadyRule;
    if (s.kineticComplete) {
      s.muKinetic = sum / double(count);
      s.kineticFrom = from;
      s.kineticTo = to;
      s.kineticSpread = windowStats(from, to).spread;
      s.kineticSteady = steadyRule && windowSteady_;
    }
  }
  return s;
}

void archiveSummary(StateArchive& a, FrictionSummary& s) {
  a.field("summary.muStatic", s.muStatic);
  a.field("summary.peakTime", s.peakTime);
  a.field("summary.peakConfirmed", s.peakConfirmed);
  a.field("summary.muKinetic", s.muKinetic);
  a.field("summary.kineticComplete", s.kineticComplete);
  a.field("summary.kineticFrom", s.kineticFrom);
  a.field("summary.kineticTo", s.kineticTo);
  a.field("summary.kineticSpread", s.kineticSpread);
  a.field("summary.kineticSteadyTested", s.kineticSteadyTested);
  a.field("summary.kineticSteady", s.kineticSteady);
  a.field("summary.firstSlipTime", s.firstSlipTime);
  a.field("summary.detachmentTime", s.detachmentTime);
  a.field("summary.time", s.time);
  a.field("summary.mu", s.mu);
  a.field("summary.forceX", s.forceX);
  a.field("summary.forceY", s.forceY);
}

void FrictionHistory::archive(StateArchive& a) {
  a.field("history.maximum", maximum_);
  a.field("history.peakTime", peakTime_);
  a.field("history.lastTime", lastTime_);
  a.field("history.firstSlip", firstSlip_);
  a.field("history.detachment", detachment_);
  a.field("history.confirmed", confirmed_);
  a.field("history.observed", observed_);
  a.field("history.windowDecided", windowDecided_);
  a.field("history.windowSteady", windowSteady_);
  a.field("history.windowFrom", windowFrom_);
  a.field("history.nextSample", nextSample_);
  a.field("history.sinceTime", sinceTime_);
  a.field("history.sinceMu", sinceMu_);
  a.field("history.prefix", prefix_);
  archiveSummary(a, history_);
}

}  // namespace gradfric
