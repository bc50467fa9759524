#pragma once
// The accuracy-study file (layout in docs/accuracy.md), shared by the SBM and FEM studies: root
// string attributes (format, model, every option), one group per ladder with described float64
// datasets along the ladder's dimension scale `rung` and string attributes, and the provenance
// record in /provenance. Planned before any work (io::OutputPlan: refused on every rank alike),
// written by rank 0 under <output>.partial and renamed into place when complete.
#include "gradfric/core/options.hpp"
#include "gradfric/io/output_plan.hpp"

#include <hdf5.h>
#include <mpi.h>

#include <string>
#include <utility>
#include <vector>

namespace gradfric::study {

// One ladder: a group of the file.
struct LadderTable {
  std::string name;
  std::vector<std::pair<std::string, std::string>> texts;                 // string attributes
  std::vector<std::pair<std::string, std::vector<double>>> columns;       // datasets, in order
};

struct StudyFile {
  std::vector<std::pair<std::string, std::string>> attributes;  // root string attributes, in order
  std::vector<LadderTable> ladders;
};

// Collective: -output and -output_overwrite as read by the study; refuses before any work.
io::OutputPlan planStudyFile(MPI_Comm comm, const std::string& output, bool overwrite);

// Root attributes: format = gradfric-accuracy-study, then every option of the record (leading dash
// dropped).
std::vector<std::pair<std::string, std::string>> studyAttributes(const RunParameters& record,
                                                                 const std::vector<std::pair<std::string, std::string>>& first);

// Collective: rank 0 writes the file under the plan's temporary name; then it is renamed into
// place. A failure is an error on every rank (CollectiveError) and leaves any earlier file whole.
void saveStudyFile(MPI_Comm comm, const io::OutputPlan& plan, const StudyFile& file);

}  // namespace gradfric::study
