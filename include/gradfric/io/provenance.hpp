#pragma once
// Where a results file came from: the software (version, commit), the command line, the text of
// every -options_file it named, the date and the number of ranks. Stored as attributes of a group
// (/run in the ensemble file, /provenance in the FEM file); see docs/ensemble.md.
#include <mpi.h>
#include <hdf5.h>

#include <string>
#include <utility>
#include <vector>

namespace gradfric::io {

struct Provenance {
  std::string version;      // gradfric::kVersion
  std::string commit;       // gradfric::kCommit (git describe at configure time)
  std::string commandLine;  // argv as PETSc received it, shell-quoted where needed
  std::string date;         // UTC, ISO 8601, when the run started
  int ranks = 1;
  std::vector<std::pair<std::string, std::string>> optionsFiles;  // (path as given, its text)
};

// Collective: rank 0 collects, every rank returns the same record (HDF5 metadata is collective).
Provenance collectProvenance(MPI_Comm comm);

// Attributes software_version, software_commit, command_line, date (strings), ranks (int) of
// group, and a subgroup options_files with one attribute per file: name = the path as given,
// value = the file's text. Collective in a parallel file.
void writeProvenance(hid_t group, const Provenance& provenance);

}  // namespace gradfric::io
