#pragma once
// One way to measure friction, for both models: an observer of the global friction history
// mu(t) = |F(t)| / (p L^2), fed once per time step. It finds the static peak and confirms it,
// averages the kinetic window after it, notes the first slip, keeps the sampled history and says
// when the observables asked for are known (a run then stops). PETSc-free.
#include "gradfric/core/state_archive.hpp"

#include <cstddef>
#include <limits>
#include <vector>

namespace gradfric {

// What to measure and the rules that decide it (the -friction_ options, friction_options.hpp).
struct FrictionMeasurement {
  bool kinetic = true;           // mu_k over the window after the peak (else: stop at the confirmed peak)
  bool firstSlipMap = true;      // per-site first-slip times (the models record them; SBM map, FEM nodes)
  double peakDrop = 0.01;        // the peak is confirmed once mu(t) fell this fraction below it ...
  double peakHold = 0.0;         // ... or has not been exceeded for this long [s], once every site slipped
  double kineticDelay = 0.0;     // the kinetic window starts this long after the peak [s]
  double kineticWidth = 0.0;     // and lasts this long [s]
  // Steady window (0: off, the fixed window above, the SBM's default): the window is steady once
  // the means of its kSteadyBatches equal parts spread by at most this fraction of its mean; until
  // then it slides forward (the run goes on), its start at most kineticLatestDelay after the peak.
  double kineticSteadyTolerance = 0.0;
  double kineticLatestDelay = 0.0;  // [s]; below kineticDelay: kineticDelay
  double historyInterval = 0.0;  // sampling of the stored history [s]; 0: every observation
};

struct FrictionSummary {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double muStatic = kNaN;        // the maximum of mu(t) (the static peak once confirmed)
  double peakTime = kNaN;        // its time [s]
  bool peakConfirmed = false;    // false: the run ended before the rule confirmed the peak
  double muKinetic = kNaN;       // mean of mu(t) over the kinetic window; NaN if not asked or incomplete
  bool kineticComplete = false;  // the window was observed to its end
  double kineticFrom = kNaN, kineticTo = kNaN;  // the window averaged [s]
  // Spread of the window's batch means, (max - min)/mean: the steadiness and error bar of mu_k.
  double kineticSpread = kNaN;
  bool kineticSteadyTested = false;  // the steady rule was on (tolerance > 0)
  bool kineticSteady = false;        // ... and the window met it (false at the cap: not steady)
  double firstSlipTime = kNaN;   // first observation at which some site had slipped [s]
  // First observation at which every site had slipped (the detachment front crossed the plate) [s];
  // the peak is confirmed only after it, so a confirmed peak has one.
  double detachmentTime = kNaN;
  // The sampled history: time [s], mu, and the tangential force components [N].
  std::vector<double> time, mu, forceX, forceY;
};

// Saves or restores a summary (checkpoints).
void archiveSummary(StateArchive& a, FrictionSummary& summary);

// The kinetic window is split into this many equal batches for its steadiness and error bar.
constexpr int kSteadyBatches = 4;

class FrictionHistory {
public:
  // normalForce: p L^2 [N]; timeStep: the models' fixed step [s] (the window's end tolerance).
  FrictionHistory(const FrictionMeasurement& measurement, double normalForce, double timeStep);

  // One observation per step, at increasing times t: the total tangential force (fx, fy) [N];
  // anySlipped: some site has slipped by now; allSlipped: every site has (the detachment front
  // crossed the plate: only then can the peak be confirmed). Returns mu(t).
  double observe(double t, double fx, double fy, bool anySlipped, bool allSlipped);

  bool peakConfirmed() const { return confirmed_; }
  double peak() const { return maximum_; }
  double peakTime() const { return peakTime_; }
  // Everything asked for is determined: the peak is confirmed and the kinetic window (if asked
  // for) has been observed to its end.
  bool known() const;
  FrictionSummary summary() const;
  // Saves or restores everything observed so far (checkpoints).
  void archive(StateArchive& a);

private:
  struct Window {
    double from, to, mean, spread;
  };
  Window windowStats(double from, double to) const;  // mean and batch spread of the samples in [from, to]
  void advanceSteadyWindow(double t);                 // steady rule: test the window ending at t
  double latestStart() const;

  FrictionMeasurement rule_;
  double normalForce_, timeStep_;
  double maximum_ = -1.0, peakTime_ = 0.0, lastTime_ = 0.0, firstSlip_ = FrictionSummary::kNaN;
  double detachment_ = FrictionSummary::kNaN;
  bool confirmed_ = false, observed_ = false;
  bool windowDecided_ = false, windowSteady_ = false;  // steady rule: the window is chosen
  double windowFrom_ = 0.0;
  double nextSample_ = 0.0;
  // Observations since the current maximum (the kinetic window lies after it).
  std::vector<double> sinceTime_, sinceMu_;
  std::vector<double> prefix_ = {0.0};  // steady rule: running sums of sinceMu_ (batch means in O(1))
  FrictionSummary history_;
};

}  // namespace gradfric
