// gradfric-study: what accuracy costs in time. Runs ladders of settings from a scene and reports
// the error of the global mu_s and mu_k against the finest setting, with the wall time.
//
//   mpiexec -n 2 gradfric-study -options_file input/study_sbm.opts -output study.h5
//   mpiexec -n 2 gradfric-study -options_file input/study_fem.opts -output study_fem.h5   (-study_model fem)
//   python3 scripts/plot_accuracy.py study.h5 docs/     (work-precision plots)
//   gradfric-study -study_judge docs/fem_study.tsv [-output verdicts.tsv]   (every ladder's bar)
#include "gradfric/core/driver.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/study/fem_study.hpp"
#include "gradfric/study/judge_table.hpp"
#include "gradfric/study/sbm_study.hpp"

static const char help[] =
    "gradfric-study: error of mu_s and mu_k against wall time for ladders of time step, integrator,\n"
    "lattice size and number of realisations (-study_model sbm), or of mesh, time-step safety factor per\n"
    "integrator and penalty stiffnesses (-study_model fem); or, with -study_judge TABLE, every ladder of a\n"
    "study table judged by the verification procedure (docs/verification.md). -help lists all options.\n\n";

int main(int argc, char** argv) {
  return gradfric::runDriver(argc, argv, help, [](MPI_Comm comm) {
    gradfric::RunParameters record;
    gradfric::OptionReader o(comm, "study_", "Accuracy-cost study: which model", &record);
    const std::string judge = o.path("judge", "",
                                     "a study table (docs/fem_study.tsv, docs/sbm_study.tsv): print every ladder's "
                                     "verdict by the verification procedure, run nothing (-output: also as TSV)");
    if (!judge.empty() && !gradfric::helpRequested()) return gradfric::study::judgeStudyTable(comm, judge, &record);
    const std::string model = o.choice("model", "sbm", {"sbm", "fem"}, "model of the study: spring blocks or finite elements");
    if (model == "fem")
      gradfric::study::runFiniteElementStudy(comm, &record);
    else
      gradfric::study::runSpringBlockStudy(comm, &record);
  });
}
