// The element study (docs/studies/fem-element-and-mesh.md): one FEM run to its confirmed peak with the ordinary
// -plate_/-grading_/-fem_/-friction_ options, printing one line: the element, the mesh, mu_s, the
// peak time, and at the step of the peak the contact pressure on the trailing edge, the centre
// line and the leading edge, and the moment balance sum (x - L/2) p_c A / (H F_t).
//   mpiexec -n 2 bench/fem/bench_fem_element_study -fem_element q1i -friction_observables mu_s
#include "gradfric/core/driver.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/fem/contact_resultants.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/fem/plate_model.hpp"
#include "gradfric/fem/plate_ts.hpp"
#include "gradfric/fem/scene_options.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/fem/stable_step.hpp"

#include <petscsys.h>

#include <cmath>
#include <optional>

static const char help[] = "bench_fem_element_study: mu_s, edge pressures and moment balance at the peak of one FEM run\n";

int main(int argc, char** argv) {
  using namespace gradfric;
  using namespace gradfric::fem;
  return runDriver(argc, argv, help, [](MPI_Comm comm) {
    RunParameters record;
    const std::optional<FemScene> scene = readCheckedFemScene(comm, &record);  // the driver's options and checks
    if (!scene) return;  // -help
    const Grading& grading = scene->grading;
    FemParameters params = scene->params;
    params.verbose = false;
    PlateModel model(comm, params, grading);
    const double normal = model.params().plate.normalForce(), H = model.params().plate.thickness;
    double best = -1;
    ContactResultants atPeak;
    const double wall0 = MPI_Wtime();
    const FemRunResult r = runPlateExperiment(model, [&](double, Vec) {
      const ContactResultants c = contactResultants(model);
      const double mu = std::hypot(c.forceX, c.forceY) / normal;
      if (mu > best) best = mu, atPeak = c;
    });
    const double wall = MPI_Wtime() - wall0;
    const double p = model.params().plate.pressure;
    PetscPrintf(comm,
                "element %s mesh %dx%dx%d grading %s: mu_s %.5f peak %.4e s (confirmed %d); at the peak p_c/p trailing "
                "%.4f centre %.4f leading %.4f, moment / (H F_t) %.4f; dt %.3e s, %ld steps, wall %.1f s\n",
                elementTypeName(params.element), params.nx, params.ny, params.nz, describe(grading).c_str(),
                r.friction.muStatic, r.friction.peakTime, r.friction.peakConfirmed ? 1 : 0,
                atPeak.trailingEdgePressure / p, atPeak.centrePressure / p, atPeak.leadingEdgePressure / p,
                atPeak.momentAboutY / (H * std::hypot(atPeak.forceX, atPeak.forceY)), r.dt, r.steps, wall);
  });
}
