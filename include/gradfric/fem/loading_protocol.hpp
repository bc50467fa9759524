#pragma once
// The paper's loading protocol in one place: step 1, the pressure ramped linearly over rampTime
// and held while the plate settles (mass damping c_s/H); step 2 from rampTime + settleTime, the
// top slides at v (theta) for at most slideTime; from the confirmed static peak (or as
// -fem_peak_damping_start says) the damping of the sliding plate (sliding_damping.hpp, and the
// stiffness-proportional part). The layers read it through their LayerContext; the experiment
// (simulation.cpp) asks it when to switch.
#include "gradfric/core/state_archive.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/fem/sliding_damping.hpp"

namespace gradfric::fem {

enum class Phase { Pressure, Sliding };

class LoadingProtocol {
public:
  explicit LoadingProtocol(const FemParameters& resolved) : q_(resolved) {}

  Phase phase() const { return phase_; }
  bool sliding() const { return phase_ == Phase::Sliding; }
  void setPhase(Phase phase) { phase_ = phase; }

  // The top pressure at t: ramped over rampTime while pressing, held after, full once sliding.
  double pressureAt(double t) const;
  // Step 1 is over at t (step dt): time to start sliding.
  bool settled(double t, double dt) const { return t >= q_.rampTime + q_.settleTime - 0.5 * dt; }
  // Step 2 has lasted its longest (tSliding since its start).
  bool slideOver(double tSliding, double dt) const { return tSliding >= q_.slideTime - 0.5 * dt; }

  // Whether the damping of the sliding plate is due after this step: at the confirmed peak, or
  // with -fem_peak_damping_start at the first drop of mu after the first slip (mu below
  // (1 - peakDrop) x the running peak) or at once.
  bool peakDampingDue(bool peakConfirmed, bool slipping, double mu, double peak) const;
  // Switches it on (once, sliding only); true if any damping was switched on.
  bool startPeakDamping();
  bool peakDampingOn() const { return peakDampingOn_; }
  // The mass damping of the current phase (sliding_damping.hpp).
  SlidingDamping massDamping() const;
  // The stiffness-proportional (Rayleigh beta) damping of the current phase [s].
  double stiffnessDamping() const;
  // The phase and the damping switch saved or restored (checkpoints).
  void archive(StateArchive& a) {
    a.field("protocol.phase", phase_);
    a.field("protocol.peakDampingOn", peakDampingOn_);
  }

private:
  const FemParameters& q_;
  Phase phase_ = Phase::Pressure;
  bool peakDampingOn_ = false;
};

}  // namespace gradfric::fem
