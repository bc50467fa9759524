#pragma once
// Is a file given to -resume (or to an extension) a results file of this campaign? Checked on
// rank 0 with HDF5's error printing off, before any rank opens it in parallel: a foreign,
// truncated or damaged file, or one of another scene, is one InputError on every rank naming
// the option and what is wrong with the file (src/campaign/resume_check.cpp).
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/io/results_file.hpp"

#include <mpi.h>

#include <functional>
#include <string>
#include <vector>

namespace gradfric::campaign {

// What a file to resume must match, for any writer of the results layout (the spring-block
// scene, the FEM sweep): its /scene record and layout (format included), and the options the
// messages name.
struct ResumeTarget {
  std::vector<io::Attribute> sceneAttributes;
  io::EnsembleLayout layout;
  std::string resumeOption = "-resume";
  std::string overwriteOption = "-output_overwrite";
};

// What extending a finished file may change (options of /scene it may differ in) and the model's
// further check of the file's points and realisations ("" if they fit).
struct Extension {
  std::string option = "-ensemble_extend";
  std::function<bool(const std::string& sceneOption)> mayChange;
  std::function<std::string(const io::ResultsFile& file)> mismatch;
};

// Collective: throws InputError on every rank when the file cannot be continued.
void checkResumable(MPI_Comm comm, const ResumeTarget& target, const std::string& path);
// Collective: the same for a complete file to extend.
void checkExtendable(MPI_Comm comm, const ResumeTarget& target, const Extension& extension, const std::string& path);

}  // namespace gradfric::campaign
