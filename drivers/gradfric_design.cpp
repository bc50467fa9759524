// gradfric-design: from a target friction to a surface. Finds the free parameters of a family of
// graded plates (a grading amplitude, a field's exponent, a stripe pattern's period and duty, ...)
// whose spring-block ensemble gives a target global static friction mu_s, or a target relative
// variation against the non-graded plate, within a tolerance.
//
//   mpiexec -n 2 gradfric-design -options_file input/design_friction_delta.opts -output design.h5
//   mpiexec -n 2 gradfric-design -options_file input/design_stripes_tao.opts -design_tao_type pounders
//   python3 scripts/plot_design.py design.h5
//
// One free parameter: a stochastic root finder; several: PETSc TAO. Each evaluation is a
// spring-block ensemble, or with -design_model fem one FEM run. Then a fresh verification
// ensemble with independent streams (spring blocks), the other model at the design, the
// spring-block variants the designer names (-design_variants), and the
// parameter's interval from each source of uncertainty. Exit status: 0 design found
// (and verified), 4 target unreachable within the bounds, 5 not converged, 6 found but the verification misses the
// target, 2 bad input (docs/design.md).
#include "gradfric/core/driver.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/design/design_file.hpp"
#include "gradfric/design/evaluator.hpp"
#include "gradfric/design/fem_evaluator.hpp"
#include "gradfric/design/known_runs.hpp"
#include "gradfric/design/mesh_refinement.hpp"
#include "gradfric/design/problem.hpp"
#include "gradfric/design/root_finder.hpp"
#include "gradfric/design/tao_search.hpp"
#include "gradfric/design/uncertainty.hpp"

#include <petscsys.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

static const char help[] =
    "gradfric-design: the parameters of a graded plate that give a target global static friction\n"
    "(spring-block ensembles; one parameter: root finder, several: PETSc TAO, -design_tao_type nm|pounders).\n"
    "-help lists all options.\n\n";

int main(int argc, char** argv) {
  return gradfric::runDriver(argc, argv, help, [](MPI_Comm comm) {
    using namespace gradfric;
    using namespace gradfric::design;
    RunParameters record;
    const std::optional<Problem> problem = readProblem(comm, &record);  // every option, checked
    if (!problem) return 0;                                               // -help
    const io::OutputPlan plan = planDesignFile(comm, *problem);         // before any work
    const std::vector<KnownFemRun> known = readKnownFemRuns(comm, problem->reuse, *problem, record);  // -design_reuse
    record.print(comm, "gradfric-design parameters");
    if (problem->coarseFem)
      PetscPrintf(comm, "Every evaluation is one FEM run to its confirmed peak: the search on %d x %d x %d hexahedra, "
                  "then at most %d run(s) on %d x %d x %d.\n", problem->coarseFem->parameters.nx,
                  problem->coarseFem->parameters.ny, problem->coarseFem->parameters.nz, problem->fineEvaluations,
                  problem->fem->parameters.nx, problem->fem->parameters.ny, problem->fem->parameters.nz);
    else if (problem->model == "fem")
      PetscPrintf(comm, "Every evaluation is one FEM run to its confirmed peak (%d x %d x %d hexahedra).\n",
                  problem->fem->parameters.nx, problem->fem->parameters.ny, problem->fem->parameters.nz);
    else
      PetscPrintf(comm, "Every realisation measures mu_s only and stops at its confirmed peak (%d x %d blocks, dt %.4g s).\n",
                  problem->parameters.blocksPerSide, problem->parameters.blocksPerSide, problem->parameters.timeStep);
    const double start = MPI_Wtime();
    Evaluator springBlocks(comm, *problem);
    std::optional<FemEvaluator> femRuns, coarseRuns;  // the FEM on the -fem_* mesh, and on the coarse one
    if (problem->fem) femRuns.emplace(comm, *problem, *problem->fem, problem->tolerance);
    if (problem->coarseFem) coarseRuns.emplace(comm, *problem, *problem->coarseFem, problem->coarse);
    for (auto* runs : {&femRuns, &coarseRuns})
      if (*runs) (*runs)->know(known);
    if (!problem->reuse.empty())
      PetscPrintf(comm, "-design_reuse: %zu earlier FEM run(s) known; an evaluation there is taken, not run again.\n",
                  known.size());
    DesignModel& model = problem->model != "fem" ? static_cast<DesignModel&>(springBlocks)
                         : coarseRuns           ? static_cast<DesignModel&>(*coarseRuns)
                                                : static_cast<DesignModel&>(*femRuns);
    SearchLog log(comm, *problem);
    SearchResult search = problem->method == "root" ? findRoot(model, *problem, log)
                                                    : searchWithTao(comm, model, *problem, log);
    if (coarseRuns) search = refineOnFineMesh(*femRuns, *problem, log, search);  // confirmed on the -fem_* mesh
    std::optional<Evaluation> verification;
    if (problem->verify)  // independent streams (seed, 1, r), to the tolerance
      verification = springBlocks.evaluate(search.design.x, problem->tolerance, "verify", 1);
    const SearchResult result = settleOnVerification(search, verification, problem->target);  // "found" needs it
    // The other model at the design: the FEM (a variation target: against its own non-graded
    // plate), or with the FEM as the design's model, a spring-block ensemble.
    std::optional<FemVerification> fem;
    std::optional<Evaluation> otherSpringBlocks;
    if (problem->model == "fem")
      otherSpringBlocks = springBlocks.evaluate(result.design.x, problem->tolerance, "model_form");
    else if (femRuns)
      fem = femRuns->check(result.design.x);
    const double otherValue = fem ? femTargetValue(*problem, *fem) : otherSpringBlocks ? otherSpringBlocks->value : NAN;
    // The spring-block variants the designer names, paired with the verification (its streams).
    long variantRealisations = 0;
    const std::vector<Evaluation> variants =
        evaluateVariants(comm, *problem, result.design.x, verification ? 1 : 0, &variantRealisations);
    const DesignUncertainty uncertainty =
        designUncertainty(*problem, result, otherValue, designStudyBar(*problem, record, result.design.x), variants,
                          verification ? &*verification : nullptr);
    RunCounts runs{springBlocks.realisationsRun() + variantRealisations, 0};
    for (const auto* fe : {&femRuns, &coarseRuns})
      if (*fe) runs.femRuns += (*fe)->realisationsRun(), runs.femReused += (*fe)->runsReused();
    double wall = MPI_Wtime() - start;
    MPI_Bcast(&wall, 1, MPI_DOUBLE, 0, comm);
    saveDesignFile(comm, plan, *problem, record, log, result, verification, fem, otherSpringBlocks, variants, uncertainty,
                   runs);
    printDesign(comm, *problem, result, verification, fem, otherSpringBlocks, variants, uncertainty, runs, wall,
                plan.path());
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    if (problem->plot && rank == 0) {
      const std::string command = "/usr/bin/python3 '" GRADFRIC_SCRIPTS_DIR "/plot_design.py' '" + plan.path() + "'";
      if (std::system(command.c_str()) != 0)
        std::fprintf(stderr, "gradfric-design: warning: plotting failed (%s); the design file is complete\n", command.c_str());
    }
    return exitCode(result.status);  // the search's outcome
  });
}
