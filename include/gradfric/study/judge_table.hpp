#pragma once
// gradfric-study -study_judge TABLE: every ladder of a study table judged by the one verification
// procedure (core/study_judgement.hpp), as Markdown on stdout and as TSV into -output if given.
// Runs nothing; the docs' tables are this output (scripts/regenerate_docs_tables.sh).
#include "gradfric/core/options.hpp"

#include <mpi.h>

#include <string>

namespace gradfric::study {

// Collective. A table that is missing or has a row that does not read is refused (InputError naming
// -study_judge) on every rank, before anything is written.
void judgeStudyTable(MPI_Comm comm, const std::string& table, RunParameters* record);

}  // namespace gradfric::study
