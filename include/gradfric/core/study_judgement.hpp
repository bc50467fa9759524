#pragma once
// Every ladder of a study table judged by the one procedure (core/verification.hpp), as gradfric-study
// -study_judge prints and writes it: the docs' tables are this output (scripts/regenerate_docs_tables.sh).
// PETSc-free.
#include "gradfric/core/study_table.hpp"

#include <string>
#include <vector>

namespace gradfric::study {

// Markdown: one row per ladder of three or more members (observable, scene, meshes, values, the
// verdict's fields and each member's U relative to its value), then a line counting the rows that
// make no such ladder.
std::string judgementMarkdown(const std::vector<StudyRow>& rows);
// The bars of a sweep's points, one line each: "  bar point 0 mu_s: +- 0.77 % (...)" (the dry runs
// print them; tests/golden/scene_bars.txt keeps those of the shipped scenes).
std::string pointBarLines(const std::vector<StudyBar>& muStatic, const std::vector<StudyBar>& muKinetic);

// Tab-separated, one line per member of every ladder (smaller ones too), with a header line.
std::string judgementTsv(const std::vector<StudyRow>& rows);

}  // namespace gradfric::study
