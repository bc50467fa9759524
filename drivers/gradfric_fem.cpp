// gradfric-fem: the paper's 3D finite-element experiment. All options: -help.
#include <petscsection.h>
#include <petscsf.h>

#include "gradfric/campaign/sweep_options.hpp"
#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/driver.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/core/study_judgement.hpp"
#include "gradfric/fem/checkpoint.hpp"
#include "gradfric/fem/output.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/fem/plate_model.hpp"
#include "gradfric/fem/plate_ts.hpp"
#include "gradfric/fem/run_estimate.hpp"
#include "gradfric/fem/scene_options.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/fem/sweep.hpp"
#include "gradfric/fem/verlet_ts.hpp"
#include "gradfric/physics/field_options.hpp"
#include "gradfric/physics/grading_options.hpp"
#include "gradfric/physics/observables.hpp"
#include "gradfric/physics/plate_options.hpp"
#include "gradfric/sbm/model.hpp"
#include "gradfric/sbm/parameter_options.hpp"
#include "gradfric/sbm/parameters.hpp"

#include <petscsys.h>

#include <algorithm>
#include <csignal>
#include <cmath>
#include <optional>
#include <cstdio>
#include <string>

static const char help[] =
    "gradfric-fem: explicit 3D FEM of an elastic plate sliding on a rigid plane with penalty contact and the\n"
    "velocity-weakening friction of a state law whose steady state is the paper's Eq. 1 (-friction_law);\n"
    "pressure step, then sliding; reports mu(t), mu_s,\n"
    "the peak time (vs Eq. 2) and mu_k. Options -fem_*, -plate_*, -friction_*, -grading_*, -field_*,\n"
    "-output; PETSc's TS options with the prefix fem_ (-fem_ts_type, default gfverlet). -help <prefix> (-help fem) lists the options of one prefix.\n";

namespace {

using namespace gradfric;
using namespace gradfric::fem;

// Every option of a gradfric-fem run.
struct FemRun {
  Grading grading;
  FemParameters params;
  bool compare = false;  // also one SBM realisation on the same grading
  bool dryRun = false;   // print the plan and the estimate, build nothing
  sbm::Parameters sbmParams;
  sbm::Request sbmRequest;
  SweepOptions sweep;  // -ensemble_ lists, -fem_sweep_*: a sweep of runs instead of one run
  CheckpointSettings checkpoints;  // a single run's (-checkpoint_*, -resume)
};

// Why a run has no checkpoints ("" if it has them).
std::string checkpointsOff(const FemRun& run) {
  if (run.sweep.requested) return "a sweep keeps each finished point in <-output>.partial and -resume skips them";
  if (!run.params.snapshotTimes.empty()) return "-fem_snapshot_times: the field snapshots' file cannot be resumed";
  char type[64] = "";
  PetscBool set = PETSC_FALSE;
  PetscOptionsGetString(nullptr, nullptr, "-fem_ts_type", type, sizeof type, &set);
  const std::string integrator = set ? type : run.params.integrator;
  if (integrator != TSGFVERLET) return "-fem_ts_type " + integrator + ": only gfverlet's state is saved";
  return "";
}

// Reads and checks every option (InputError on every rank alike); nullopt after -help.
std::optional<FemRun> readFemRun(MPI_Comm comm, RunParameters* record) {
  FemRun run;
  const FemScene scene = readFemScene(comm, record);  // -grading_, -plate_, -fem_, -field_
  const Plate& plate = scene.plate;  // one plate for both models
  run.grading = scene.grading;
  run.params = scene.params;
  OptionReader driverOptions(comm, "fem_", "gradfric-fem: both models", record);
  run.compare = driverOptions.flag(
      "compare_sbm", false, "also run one spring-block realisation (-sbm_ options) on the same grading, side by side");
  refuseRenamedOption("-fem_compare_seed", "-fem_seed",
                      "the compared spring-block realisation samples the FEM's random surface, of the FEM's seed");
  run.dryRun = driverOptions.flag("dry_run", false,
                                  "print the mesh size, memory, steps and estimated wall time, then stop (nothing built)");
  if (run.compare || helpRequested()) {
    // Each model keeps its own default dispersion (the spring blocks 2.8 %, the FEM none) on the
    // one surface of -fem_seed; the results file holds the FEM's run, so the record keeps the
    // FEM's reading of the -surface_ options.
    std::vector<ResolvedOption> surface;
    for (const ResolvedOption& o : record->all())
      if (o.name.rfind("-surface_", 0) == 0) surface.push_back(o);
    run.sbmParams = sbm::readParameters(comm, record, plate, run.grading);
    for (const ResolvedOption& o : surface) record->add(o);
    run.sbmRequest = sbm::readRequest(comm, record, run.sbmParams);
  }
  // The results file, named as in every driver (-resume with the sweep's options).
  OptionReader out(comm, "", "Results file", record);
  run.params.output = out.text("output", "",
                               "HDF5 results file (empty: none; a sweep: gradfric_fem_sweep.h5); snapshots go to "
                               "<name>_fields.h5 + .xmf");
  run.params.overwrite = out.flag("output_overwrite", false, "replace an existing results file");
  run.sweep = readSweepOptions(comm, record);
  run.checkpoints = readCheckpointSettings(comm, record, run.params.output, run.sweep.resume && !run.sweep.requested,
                                           run.params.overwrite, helpRequested() ? "" : checkpointsOff(run));
  if (helpRequested()) return std::nullopt;
  campaign::refuseOverriddenBaseOptions(*record);
  // Fields against the mesh, -fem_ts_ options, misspellings, the run length and the stable step.
  if (run.compare)
    checkFemScene(comm, scene, record, {"sbm_", "ensemble_"});
  else
    checkFemScene(comm, scene, record, {"ensemble_"});
  return run;
}

void printPlan(MPI_Comm comm, const FemRun& run, const PlateModel& model, RunParameters* record) {
  const FemParameters& params = run.params;
  record->add({"-fem_dt (used)", formatReal(model.timeStep()), "s", "time step", OptionOrigin::Derived});
  record->add({"stable step", formatReal(model.stableTimeStep()), "s", "mesh, wave speed, penalty, damping",
               OptionOrigin::Derived});
  record->add({"largest step", formatReal(largestTimeStep(params, model.grading())), "s",
               "the stable step with friction's coupling: the largest -fem_dt accepted", OptionOrigin::Derived});
  record->add({"penalty slope error", formatReal(-100.0 * params.penaltySlopeError()), "%",
               "loading slope lost to the penalty springs' compliance: G/(H k_t) + 12 G H/(k_n L^2)",
               OptionOrigin::Derived});
  record->add({"damping", describeDamping(params), "", "damping active in the sliding step", OptionOrigin::Derived});
  record->add({"friction_state", describeFrictionState(params), "", "the friction law and its state (-friction_law)",
               OptionOrigin::Derived});
  if (!params.edge.uniform())  // the uniform mesh's lines stay as they were
    record->add({"mesh", "x: " + describeEdgeGrading(params.edge, params.nx, params.plate.length) +
                             "; y: " + describeEdgeGrading(params.edge, params.ny, params.plate.length),
                 "", "the in-plane mesh graded toward the edges (-fem_edge_ratio, -fem_edge_band)",
                 OptionOrigin::Derived});
  record->print(comm, "gradfric-fem: resolved parameters");
  int size = 1;
  MPI_Comm_size(comm, &size);
  PetscPrintf(comm,
              "Active effects: grading %s; %d x %d x %d hexahedra (%d cells) on %d rank(s), partitioner %s;\n"
              "  pressure ramp %.3g s + settle %.3g s (mass damping %.3g 1/s), sliding at %.3g m/s, theta %.3g deg;\n"
              "  contact %s; friction law %s, v_c %.3g m/s, %s; dt %.4g s (stable %.4g s);\n"
              "  damping while sliding: %s\n",
              describe(run.grading).c_str(), params.nx, params.ny, params.nz, static_cast<int>(model.mesh().globalCells()),
              size, params.partitioner.c_str(), params.rampTime, params.settleTime, params.settleDamping,
              params.plate.velocity, params.plate.slidingAngle, describeContact(params).c_str(), params.frictionLaw.name.c_str(),
              params.frictionLaw.criticalVelocity,
              describeFrictionState(params).c_str(), model.timeStep(), model.stableTimeStep(), describeDamping(params).c_str());
  if (!params.edge.uniform())
    PetscPrintf(comm, "  in-plane mesh: %s\n", describeEdgeGrading(params.edge, params.nx, params.plate.length).c_str());
  for (const Layer* layer : model.layers())  // the physics terms of the right-hand side, in their order
    PetscPrintf(comm, "  layer %s: %s\n", layer->name(), layer->describe().c_str());
  if (run.grading.fields)
    for (const auto& line : describeFields(*run.grading.fields)) PetscPrintf(comm, "  %s\n", line.c_str());
  if (params.surface.dispersed())
    PetscPrintf(comm, "  %s\n", describeSurface(params.surface, model.mesh().hx()).c_str());
}

// The mu_k window used and its steadiness (docs/accuracy_fem.md, "The defaults and why").
std::string describeKineticWindow(const FrictionSummary& f, const FrictionMeasurement& m, double load) {
  if (!m.kinetic || !f.kineticComplete) return "";
  char text[400];
  const int n = std::snprintf(text, sizeof text,
                              "  mu_k window                     %.4e-%.4e s (%.2f-%.2f t_load after the peak), "
                              "quarters' means spread %.3f %%",
                              f.kineticFrom, f.kineticTo, (f.kineticFrom - f.peakTime) / load,
                              (f.kineticTo - f.peakTime) / load, 100 * f.kineticSpread);
  const std::string verdict =
      !f.kineticSteadyTested ? ": fixed window, steadiness not required (-friction_muk_steady_tol 0)\n"
      : f.kineticSteady      ? ": steady (tolerance " + formatReal(100 * m.kineticSteadyTolerance) + " %)\n"
                             : ": NOT steady by the latest start (-friction_muk_latest_delay; tolerance " +
                              formatReal(100 * m.kineticSteadyTolerance) + " %)\n";
  return std::string(text, std::min<std::size_t>(n, sizeof text - 1)) + verdict;
}

// The observables of the table (physics/observables.hpp) the lines above do not show with their
// error bar or Eq. 2, one line each: a new row appears here without a change to this driver.
std::string otherObservables(const FrictionSummary& f) {
  std::string lines;
  for (const Observable& o : observables()) {
    if (o.name == "mu_s" || o.name == "mu_k" || o.name == "peak_time") continue;
    char line[160];
    std::snprintf(line, sizeof line, "  %-31s %s\n", o.name.c_str(), formatObservable(o, o.take(f)).c_str());
    lines += line;
  }
  return lines;
}

// One quantity per line, its details on indented lines: the value, then its discretisation bar (the
// study's ladder of the run's scene and mesh) or why it has none.
std::string withBar(const char* name, double value, const study::StudyBar& bar, const std::string& note) {
  char line[160];
  std::snprintf(line, sizeof line, "  %-31s %.6f%s\n    discretisation ", name, value, note.c_str());
  return line + study::describeBar(bar) + "\n";
}

// Whether the run ended without confirming its peak although it could have: it ran to its default
// length (no -fem_slide_time, no -fem_stop_when_known false, no TS limit). Then mu_s is only the
// largest mu reached: exit 5.
bool peakMissed(const FemRun& run, const FemRunResult& r, const RunParameters& scene) {
  return !r.friction.peakConfirmed && !runLengthFixed(run.params, scene) && !r.stoppedByTS;
}

void printResults(MPI_Comm comm, const FemRun& run, const FemRunResult& r, double wall, const RunParameters& scene) {
  const double eq2 = run.params.eq2PeakTime();
  const FrictionSummary& f = r.friction;
  const std::string kinetic = f.kineticComplete ? "" : "  (window incomplete)";
  PetscPrintf(comm,
              "Results (FEM):\n"
              "  settled normal force / (p L^2)  %.6f\n"
              "%s"
              "  interface resolution            %s\n"
              "    %s\n"
              "  peak time after sliding start   %.6e s\n"
              "    Eq. 2: %.6e s, ratio %.4f\n"
              "  first slip after sliding start  %.6e s\n"
              "%s%s%s"
              "  steps %ld, dt %.4e s, wall %.2f s (pressure %.2f s, sliding %.2f s), %.3f ms/step\n",
              r.settledNormalForce,
              withBar("mu_s (global)", f.muStatic, femStudyBar(scene, nullptr, run.params, "mu_s"),
                      f.peakConfirmed ? "" : "  (peak NOT confirmed)").c_str(),
              r.resolution.verdict().c_str(), r.resolution.measures().c_str(), f.peakTime, eq2, f.peakTime / eq2, f.firstSlipTime,
              otherObservables(f).c_str(),
              run.params.measurement.kinetic
                  ? withBar("mu_k (kinetic window)", f.muKinetic, femStudyBar(scene, nullptr, run.params, "mu_k"), kinetic).c_str()
                  : "  mu_k (kinetic window)           not asked (-friction_observables)\n",
              describeKineticWindow(f, run.params.measurement, eq2).c_str(), r.steps, r.dt, wall, r.wallPressure,
              r.wallSliding, 1e3 * wall / std::max(1L, r.steps));
  if (r.checkpoints > 0 || r.resumedFromStep >= 0)
    PetscPrintf(comm, "  checkpoints %d written by this process in %.2f s (%.2f %% of its wall time)%s\n", r.checkpoints, r.checkpointWall,
                100.0 * r.checkpointWall / std::max(wall, 1e-9),
                r.resumedFromStep >= 0 ? ("; resumed from step " + std::to_string(r.resumedFromStep)).c_str() : "");
  if (r.stoppedByTS)
    PetscPrintf(comm, "  (the TS's limits -fem_ts_max_steps / -fem_ts_max_time ended the run %s)\n",
                r.time.empty() ? "before the sliding step" : "before the observables were known");
  if (!f.peakConfirmed)
    PetscPrintf(comm,
                "gradfric-fem: %s: the peak of mu(t) was not confirmed before the run ended at %.4e s: mu_s is the "
                "largest mu reached, not the static coefficient (not every site had slipped: a longer -fem_slide_time may "
                "confirm it)%s\n",
                peakMissed(run, r, scene) ? "error" : "warning", r.time.empty() ? 0.0 : r.time.back(),
                peakMissed(run, r, scene) ? "; exit 5" : "");
}

// -fem_compare_sbm: one SBM realisation on rank 0 (the SBM has no MPI inside), the same grading.
void compareWithSpringBlocks(MPI_Comm comm, const FemRun& run, const FemRunResult& r, double wall) {
  if (!run.compare) return;
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  double sbmValues[4] = {0, 0, 0, 0};
  std::string failure;  // on rank 0 only: agreed before the next collective call
  if (rank == 0) {
    try {
      const sbm::Result s = sbm::simulate(run.sbmParams, run.grading, run.sbmRequest, StreamKey{run.params.surface.seed, 0, 0});
      sbmValues[0] = s.friction.muStatic;
      sbmValues[1] = s.friction.muKinetic;
      sbmValues[2] = s.friction.peakTime;
      sbmValues[3] = s.wallSeconds;
    } catch (const std::exception& e) {
      failure = std::string("the spring-block run of -fem_compare_sbm failed: ") + e.what();
    }
  }
  agreeOnError(comm, failure);
  MPI_Bcast(sbmValues, 4, MPI_DOUBLE, 0, comm);
  PetscPrintf(comm,
              "Side by side (grading %s):\n"
              "                   FEM            SBM\n"
              "  mu_s        %12.6f   %12.6f\n"
              "  mu_k        %12.6f   %12.6f\n"
              "  peak time   %12.4e   %12.4e s   (FEM Eq. 2: %.4e s, SBM loading time: %.4e s)\n"
              "  wall        %12.2f   %12.2f s\n"
              "  sigma_s     %12.4g   %12.4g     (the random surface of seed %llu, realisation 0; l_c %.4g m)\n",
              describe(run.grading).c_str(), r.friction.muStatic, sbmValues[0], r.friction.muKinetic, sbmValues[1],
              r.friction.peakTime, sbmValues[2],
              run.params.eq2PeakTime(), run.sbmParams.loadingTime(), wall, sbmValues[3], run.params.surface.sigmaStatic,
              run.sbmParams.surface.sigmaStatic, static_cast<unsigned long long>(run.params.surface.seed),
              run.params.surface.correlationLength);
}

// The checkpoints of a single run, or why it has none.
void printCheckpointPlan(MPI_Comm comm, const CheckpointPlan& plan) {
  const CheckpointSettings& s = plan.settings;
  if (s.path.empty()) {
    PetscPrintf(comm, "Checkpoints: none (%s)\n", s.off.c_str());
    return;
  }
  if (s.interval > 0)
    PetscPrintf(comm, "Checkpoints: every %.4g s of wall time and on SIGINT/SIGTERM, to %s (-resume continues)\n",
                s.interval, s.path.c_str());
  else
    PetscPrintf(comm, "Checkpoints: on SIGINT/SIGTERM only (-checkpoint_interval 0), to %s\n", s.path.c_str());
  if (s.resume && !plan.resumeFrom)
    PetscPrintf(comm, "  -resume: no checkpoint %s yet: the run starts from the beginning\n", s.path.c_str());
}

// After SIGINT/SIGTERM: the checkpoint of the last step is written; nothing else is (the results
// file would be incomplete). Exit 128 + the signal, as a process ended by it.
int stopAfterCheckpoint(MPI_Comm comm, const CheckpointPlan& plan, const FemRunResult& r) {
  PetscPrintf(comm,
              "gradfric-fem: stopped by %s at step %ld (t - t0 = %.6e s): its checkpoint is in %s; continue with "
              "the same command and -resume\n",
              r.interruptedBy == SIGINT ? "SIGINT" : "SIGTERM", r.steps,
              r.time.empty() ? 0.0 : r.time.back(), plan.settings.path.c_str());
  return 128 + r.interruptedBy;
}

// -fem_dry_run: the run or sweep was checked; its bars (they depend on the settings only).
int printSweepDryRun(MPI_Comm comm, const FemSweep& sweep) {
  PetscPrintf(comm, "Dry run (-fem_dry_run): %d run(s) checked, nothing built, run or written\n", sweep.tasks());
  PetscPrintf(comm, "Discretisation bars (docs/verification.md):\n%s",
              study::pointBarLines(sweep.bars[0], sweep.bars[1]).c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return gradfric::runDriver(argc, argv, help, [](MPI_Comm comm) -> int {
    RunParameters record;
    const std::optional<FemRun> run = readFemRun(comm, &record);  // every option, checked
    if (!run) return 0;                                           // -help
    if (run->sweep.requested) {                                   // a sweep of runs over groups of ranks
      const FemSweep sweep = buildFemSweep(comm, run->params, run->grading, run->sweep, run->compare, record);
      if (run->dryRun) return printSweepDryRun(comm, sweep);      // -fem_dry_run: checked, nothing run
      return runFemSweep(comm, sweep, record);                    // 5: a peak not confirmed
    }
    int ranks = 1;
    MPI_Comm_size(comm, &ranks);
    const RunEstimate estimate = estimateRun(run->params, run->grading, ranks);
    PetscPrintf(comm, "Estimate: %s\n", estimate.describe().c_str());
    if (run->dryRun) return printSweepDryRun(comm, oneRunCampaign(run->params, run->grading, record));
    CheckpointPlan checkpoints{run->checkpoints, checkpointToResume(comm, run->checkpoints), {}};
    OutputFiles output(comm, run->params);                        // planned before any work
    PlateModel model(comm, run->params, run->grading);
    const RunParameters scene = record;                           // the options as a sweep stores them
    printPlan(comm, *run, model, &record);
    printCheckpointPlan(comm, checkpoints);
    const double wall0 = MPI_Wtime();
    const StepObserver observer = output.snapshotObserver(model);
    checkpoints.archiveObserver = [&output](StateArchive& a) { output.archiveObserver(a); };
    const FemRunResult result = runPlateExperiment(model, observer, &checkpoints);
    const double wall = MPI_Wtime() - wall0;
    if (result.interruptedBy) return stopAfterCheckpoint(comm, checkpoints, result);
    record.add({"interface resolution", result.resolution.describe(), "",
                "D_c, kappa = G D_c/(H p (mu_s - mu_k)), and whether D_c was resolved (docs/accuracy_fem.md)",
                OptionOrigin::Derived});
    output.writeResults(model, result, scene, record);
    output.finish();                                              // complete: renamed into place
    removeCheckpoint(comm, run->checkpoints);                     // the results hold everything
    printResults(comm, *run, result, wall, scene);
    compareWithSpringBlocks(comm, *run, result, wall);
    if (run->params.output.empty())  // every other driver writes a default file; a single run says so
      PetscPrintf(comm, "gradfric-fem: results not stored: no -output FILE was given (printed only)\n");
    return peakMissed(*run, result, scene) ? 5 : 0;                // a result that is not the one asked for
  });
}
