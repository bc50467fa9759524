#pragma once
// Where a run writes a result file, decided before any work, the same on every rank.
//
// Rank 0 checks the file system and broadcasts its decision; a refusal is thrown on every rank as
// the same InputError (exit 2, no hang). The run writes under a temporary name; commit() renames
// it onto the requested path (rename(2): atomic, the earlier result stays whole until then) and a
// failed rename is an error on every rank. A run that fails before commit() leaves an earlier
// result untouched: nothing is deleted before the new file is complete.
// Used by the ensemble (<output>.partial, resumable), the FEM driver (history and snapshot files,
// .tmp) and the accuracy studies (.partial).
#include <mpi.h>

#include <functional>
#include <string>

namespace gradfric::io {

struct OutputRequest {
  std::string option = "-output";                      // the option naming the path, for messages
  std::string path;                                    // the file the user asked for
  std::string value;                                   // the option's value, if not path itself
  std::string temporarySuffix = ".tmp";                // the run writes path + suffix
  bool overwrite = false;                              // replace an existing file (on success)
  std::string overwriteOption = "-output_overwrite";   // the option that allows it
  bool resume = false;                                 // continue an interrupted (or finished) run
  std::string resumeOption;                            // non-empty: the temporary can be resumed
  bool extend = false;                                 // extend the finished file (into the temporary)
  std::string extendOption;                            // the option that asks for it
};

// How the run starts.
enum class OutputStart {
  Fresh,              // a new temporary file
  ContinueTemporary,  // resume: the temporary of an interrupted run exists
  ContinueFinished,   // resume: only the finished file exists; the run works on it in place
  ExtendFinished,     // extend: a new temporary starts from the finished file, replaces it when complete
};

class OutputPlan {
public:
  // Collective over comm. Refuses (InputError on every rank) a path that is empty or a directory,
  // a folder that is missing or not writable (a probe file is created and removed), an existing
  // file without overwrite or resume, an interrupted run's temporary without resume or overwrite
  // (when resumable), overwrite together with resume, and a temporary that cannot be created.
  static OutputPlan decide(MPI_Comm comm, const OutputRequest& request);

  const std::string& path() const { return path_; }          // the final file
  const std::string& workPath() const { return workPath_; }  // where the run writes
  OutputStart start() const { return start_; }

  // Collective: rank 0 runs write(workPath()) (a serial writer); an exception there is agreed and
  // thrown on every rank as a CollectiveError. Nothing is renamed.
  void writeOnRank0(MPI_Comm comm, const std::function<void(const std::string& workPath)>& write) const;
  // Collective: renames workPath() onto path() on rank 0; a failure (naming both paths) is thrown
  // on every rank as a CollectiveError and leaves both files as they were.
  void commit(MPI_Comm comm) const;
  // Removes the temporary of a run that failed and cannot be resumed (rank 0; no communication,
  // so it may run while unwinding).
  void discard(MPI_Comm comm) const;

private:
  std::string path_, workPath_;
  OutputStart start_ = OutputStart::Fresh;
};

}  // namespace gradfric::io
