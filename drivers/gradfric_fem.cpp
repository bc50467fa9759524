// gradfric-fem: the paper's 3D finite-element experiment (issue 4). All options: -help.
#include <petscsection.h>
#include <petscsf.h>

#include "gradfric/core/driver.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/fem/output.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/fem/plate_model.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/physics/grading_options.hpp"

#include <petscsys.h>

#include <cmath>

static const char help[] =
    "gradfric-fem: explicit 3D FEM of an elastic plate sliding on a rigid plane with penalty contact and the\n"
    "velocity-weakening friction of the paper's Eq. 1; pressure step, then sliding; reports mu(t), mu_s,\n"
    "the peak time (vs Eq. 2) and mu_k. Options -fem_*, -grading_*, PETSc's -ts_type (default gfverlet).\n";

int main(int argc, char** argv) {
  return gradfric::runDriver(argc, argv, help, [](MPI_Comm comm) {
    using namespace gradfric;
    using namespace gradfric::fem;
    RunParameters record;
    const Grading grading = readGrading(comm, &record);
    const FemParameters params = readFemParameters(comm, &record);
    if (helpRequested()) return;
    checkUnusedOptions(comm, {"fem_", "grading_"});
    chooseTimeStep(params, grading);    // refuses a dt above the stable step before any work
    OutputFiles output(comm, params);  // refuses an existing file before any work
    PlateModel model(comm, params, grading);
    record.add({"-fem_dt (used)", formatReal(model.timeStep()), "s", "time step", OptionOrigin::Derived});
    record.add({"stable step", formatReal(model.stableTimeStep()), "s", "mesh, wave speed, penalty, damping",
                OptionOrigin::Derived});
    record.print(comm, "gradfric-fem: resolved parameters");
    const double eq2 = params.eq2PeakTime();
    int size = 1;
    MPI_Comm_size(comm, &size);
    PetscPrintf(comm,
                "Active effects: grading %s; %d x %d x %d hexahedra (%d cells) on %d rank(s), partitioner %s;\n"
                "  pressure ramp %.3g s + settle %.3g s (mass damping %.3g 1/s), sliding at %.3g m/s, theta %.3g deg;\n"
                "  contact penalty k_n %.3g, k_t %.3g Pa/m; Eq. 1 friction, v_c %.3g m/s; dt %.4g s (stable %.4g s)\n",
                describe(grading).c_str(), params.nx, params.ny, params.nz, static_cast<int>(model.globalCells()), size,
                params.partitioner.c_str(), params.rampTime, params.settleTime, params.settleDamping, params.v,
                params.thetaDeg, params.kn, params.kt, params.vC, model.timeStep(), model.stableTimeStep());
    StepObserver observer = output.snapshotObserver(model);
    const double wall0 = MPI_Wtime();
    const FemRunResult r = runPlateExperiment(model, observer);
    const double wall = MPI_Wtime() - wall0;
    output.writeHistory(model, r, record);
    output.finish();
    PetscPrintf(comm,
                "Results (FEM):\n"
                "  settled normal force / (p L^2)  %.6f\n"
                "  mu_s (global)                   %.6f\n"
                "  peak time after sliding start   %.6e s   (Eq. 2: %.6e s, ratio %.4f)\n"
                "  first slip after sliding start  %.6e s\n"
                "  mu_k (kinetic window)           %.6f%s\n"
                "  steps %ld, dt %.4e s, wall %.2f s (pressure %.2f s, sliding %.2f s), %.3f ms/step\n",
                r.settledNormalForce, r.muS, r.peakTime, eq2, r.peakTime / eq2, r.firstSlipTime, r.muK,
                r.windowComplete ? "" : "  (window incomplete)", r.steps, r.dt, wall, r.wallPressure, r.wallSliding,
                1e3 * wall / std::max(1L, r.steps));
  });
}
