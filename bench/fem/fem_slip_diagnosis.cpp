// Node-scale diagnosis of the sliding after the peak (docs/studies/fem-steady-sliding.md, "Steady
// sliding after the peak"): one FEM run with the ordinary -plate_/-grading_/-fem_/-friction_ options; over a
// window of the sliding step (-diag_from, -diag_to [s] after the confirmed peak, default the
// kinetic window), every step, it counts the bottom nodes that stick, slip or are open, sorts the
// nodes' tangential speeds into a histogram in units of the slider speed v, and splits the friction
// force between sticking and slipping nodes. With -fem_slip_length it also reports the nodes'
// strengths (the slip state). Prints mu(t)'s window mean against Eq. 1 at v.
//   nice -n 10 bench/fem/bench_fem_slip_diagnosis -fem_nx 20 -fem_ny 20 -fem_contact kinematic
#include "gradfric/core/driver.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/fem/plate_model.hpp"
#include "gradfric/fem/plate_ts.hpp"
#include "gradfric/fem/scene_options.hpp"
#include "gradfric/fem/simulation.hpp"

#include <petscsys.h>

#include <array>
#include <cmath>
#include <vector>

static const char help[] = "bench_fem_slip_diagnosis: stick/slip fractions and node speeds after the peak\n";

namespace {

// Histogram bins of |v_t| / v (upper edges; the last bin is open).
constexpr std::array<double, 7> kEdges = {1e-3, 0.1, 0.5, 0.9, 1.1, 2.0, 10.0};
constexpr int kBins = static_cast<int>(kEdges.size()) + 1;

struct Tally {
  double steps = 0, stick = 0, slip = 0, open = 0;  // node-steps
  std::array<double, kBins> speed{};                  // node-steps per speed bin
  double forceStick = 0, forceSlip = 0;               // sum over steps of the x friction force [N]
  double normal = 0, normalStick = 0, normalSlip = 0;  // sums over steps of the normal force [N]
  double strength = 0, strengthMin = 1e300, strengthMax = -1e300;  // slip state (node-steps)
  double mu = 0;  // sum of mu(t)
};

}  // namespace

int main(int argc, char** argv) {
  using namespace gradfric;
  using namespace gradfric::fem;
  return runDriver(argc, argv, help, [](MPI_Comm comm) {
    RunParameters record;
    FemScene scene = readFemScene(comm, &record);  // gradfric-fem's options, fields included
    const Plate& plate = scene.plate;
    FemParameters& params = scene.params;
    OptionReader o(comm, "diag_", "Slip diagnosis window", &record);
    const double from = o.real("from", params.measurement.kineticDelay, "s", "window start after the confirmed peak");
    const double to = o.real("to", params.measurement.kineticDelay + params.measurement.kineticWidth, "s",
                             "window end after the confirmed peak");
    if (helpRequested()) return;
    checkFemScene(comm, scene, &record, {"diag_"});  // the driver's checks, before any work
    params.verbose = false;
    PlateModel model(comm, params, scene.grading);
    const double v = plate.velocity;
    double confirmed = -1;  // time after the start of sliding the damping (the confirmed peak) began
    Tally tally;
    auto observe = [&](double t, Vec X) {
      if (confirmed < 0 && model.peakDampingOn()) confirmed = t;
      if (confirmed < 0 || t < confirmed + from || t > confirmed + to) return;
      const PetscScalar* x = nullptr;
      GF_CALL(VecGetArrayRead(X, &x));
      const auto& nodes = model.contact().nodes();
      Tally local;
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const auto& n = nodes[i];
        const PetscScalar* xb = x + 6 * n.block;
        const double speed = std::hypot(xb[3], xb[4]) / v;
        int bin = 0;
        while (bin < kBins - 1 && speed >= kEdges[bin]) ++bin;
        local.speed[bin] += 1;
        if (n.state == ContactState::Stick) {
          local.stick += 1;
          local.forceStick += n.force[0];
          local.normalStick += n.force[2];
        } else if (n.state == ContactState::Slip) {
          local.slip += 1;
          local.forceSlip += n.force[0];
          local.normalSlip += n.force[2];
        } else {
          local.open += 1;
        }
        local.normal += n.force[2];
        const double s = model.contact().committedStrength(static_cast<int>(i));
        local.strength += s;
        local.strengthMin = std::min(local.strengthMin, s);
        local.strengthMax = std::max(local.strengthMax, s);
      }
      GF_CALL(VecRestoreArrayRead(X, &x));
      std::vector<double> sums = {local.stick, local.slip, local.open, local.forceStick, local.forceSlip, local.normal,
                                  local.strength,   local.normalStick, local.normalSlip};
      sums.insert(sums.end(), local.speed.begin(), local.speed.end());
      GF_CALL_MPI(MPI_Allreduce(MPI_IN_PLACE, sums.data(), int(sums.size()), MPI_DOUBLE, MPI_SUM, comm));
      double range[2] = {local.strengthMin, -local.strengthMax};
      GF_CALL_MPI(MPI_Allreduce(MPI_IN_PLACE, range, 2, MPI_DOUBLE, MPI_MIN, comm));
      tally.steps += 1;
      tally.stick += sums[0];
      tally.slip += sums[1];
      tally.open += sums[2];
      tally.forceStick += sums[3];
      tally.forceSlip += sums[4];
      tally.normal += sums[5];
      tally.strength += sums[6];
      tally.normalStick += sums[7];
      tally.normalSlip += sums[8];
      for (int b = 0; b < kBins; ++b) tally.speed[b] += sums[9 + b];
      tally.strengthMin = std::min(tally.strengthMin, range[0]);
      tally.strengthMax = std::max(tally.strengthMax, -range[1]);
      tally.mu += std::fabs(sums[3] + sums[4]) / (plate.pressure * plate.length * plate.length);
    };
    const FemRunResult r = runPlateExperiment(model, observe);
    const double eq1 = plate.muKinetic + (plate.muStatic - plate.muKinetic) * std::exp(-v / params.frictionLaw.criticalVelocity);
    const double nodeSteps = tally.stick + tally.slip + tally.open;
    PetscPrintf(comm,
                "bench_fem_slip_diagnosis: mesh %dx%dx%d, contact %s, slip length %.3g m, dt %.4e s\n"
                "  mu_s %.6f, mu_k %.6f (kinetic window after the peak), peak confirmed at %.4e s; window [%.3e, "
                "%.3e] s after it: %.0f steps; steps %ld, wall %.1f s\n",
                params.nx, params.ny, params.nz, contactMethodName(params.contactMethod), params.slipLength, r.dt,
                r.friction.muStatic, r.friction.muKinetic, confirmed, from, to, tally.steps, r.steps,
                r.wallPressure + r.wallSliding);
    if (tally.steps < 1) {
      PetscPrintf(comm, "  the window holds no step (run longer: -fem_stop_when_known false -fem_slide_time)\n");
      return;
    }
    PetscPrintf(comm,
                "  mean mu %.5f (Eq. 1 at v: %.5f, %+.2f %%)\n"
                "  node-steps: stick %.3f, slip %.3f, open %.3f\n"
                "  friction share: sticking nodes %.3f, slipping nodes %.3f (traction/pressure: sticking %.4f, slipping %.4f)\n"
                "  node strength (slip state): mean %.4f, range %.4f-%.4f\n"
                "  node speed |v_t|/v histogram:",
                tally.mu / tally.steps, eq1, 100 * (tally.mu / tally.steps / eq1 - 1), tally.stick / nodeSteps,
                tally.slip / nodeSteps, tally.open / nodeSteps,
                tally.forceStick / (tally.forceStick + tally.forceSlip), tally.forceSlip / (tally.forceStick + tally.forceSlip),
                tally.normalStick > 0 ? std::fabs(tally.forceStick) / tally.normalStick : 0.0,
                tally.normalSlip > 0 ? std::fabs(tally.forceSlip) / tally.normalSlip : 0.0,
                tally.strength / nodeSteps, tally.strengthMin, tally.strengthMax);
    for (int b = 0; b < kBins; ++b) {
      const double lo = b == 0 ? 0.0 : kEdges[b - 1];
      if (b < kBins - 1) PetscPrintf(comm, " [%g,%g) %.3f", lo, kEdges[b], tally.speed[b] / nodeSteps);
      else PetscPrintf(comm, " >=%g %.3f", lo, tally.speed[b] / nodeSteps);
    }
    PetscPrintf(comm, "\n");
  });
}
