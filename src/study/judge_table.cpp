#include "gradfric/study/judge_table.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/study_judgement.hpp"
#include "gradfric/io/output_plan.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace gradfric::study {

void judgeStudyTable(MPI_Comm comm, const std::string& table, RunParameters* record) {
  OptionReader out(comm, "", "Results file", record);
  const std::string output = out.text("output", "", "with -study_judge: the verdicts as TSV (empty: stdout only)");
  const bool overwrite = out.flag("output_overwrite", false, "replace an existing results file");
  checkUnusedOptions(comm, {"study_", "output"});
  std::ifstream in(table);
  if (!in) throw InputError("-study_judge", table, "a readable study table (docs/fem_study.tsv, docs/sbm_study.tsv)");
  std::stringstream text;
  text << in.rdbuf();
  std::vector<StudyRow> rows;
  try {
    rows = parseStudyTable(text.str(), table);
  } catch (const std::invalid_argument& e) {
    throw InputError("-study_judge", table, std::string("a study table whose rows read (") + e.what() + ")");
  }
  if (!output.empty()) {
    io::OutputRequest request;
    request.path = output;
    request.overwrite = overwrite;
    const io::OutputPlan plan = io::OutputPlan::decide(comm, request);
    plan.writeOnRank0(comm, [&](const std::string& work) {
      std::ofstream file(work);
      file << judgementTsv(rows);
      if (!file.flush()) throw std::runtime_error("could not write " + work);
    });
    plan.commit(comm);
  }
  GF_CALL(PetscPrintf(comm, "%s", judgementMarkdown(rows).c_str()));
}

}  // namespace gradfric::study
