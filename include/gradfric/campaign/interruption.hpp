#pragma once
// Ctrl-C or a scheduler's SIGTERM while the tasks of a resumable results file run: rank 0 says
// how many finished tasks the file keeps and how to continue, e.g.
//   gradfric: interrupted (SIGTERM): 5 of 15 tasks are finished and kept in out.h5.partial;
//   continue with the same command and -resume
// and the process ends by the signal. Nothing needs saving: a task is committed when it finishes
// (its data, then its done flag: io/results_file.hpp). mpiexec and srun send the signal to every
// rank, and mpiexec kills them a second later: so the line is printed from the handler itself,
// with the done flags counted by read(2) from the file and the text written by write(2) (both
// async-signal-safe; no MPI, no HDF5, no allocation). Every other rank ends 0.3 s later (when a
// rank ends, mpiexec kills the others at once, perhaps before rank 0 had its signal).
#include "gradfric/io/results_file.hpp"

#include <mpi.h>

#include <string>

namespace gradfric::campaign {

class InterruptionNotice {
public:
  // While the results file at `path` (the partial file) is created, or opened to resume: the
  // notice says what a new run needs (-output_overwrite, or -resume). watch() once it is open.
  InterruptionNotice(MPI_Comm comm, const std::string& path, bool resuming);
  // `what`: "tasks" or "points"; `resumeOption`: -resume.
  InterruptionNotice(MPI_Comm comm, const io::ResultsFile& file, const std::string& path, const char* what,
                     const std::string& resumeOption);
  // From now on the notice counts the file's finished tasks (through the statistics written at the
  // end, until the notice is destroyed).
  void watch(const io::ResultsFile& file, const std::string& path, const char* what, const std::string& resumeOption);
  ~InterruptionNotice();  // the earlier handlers back
  InterruptionNotice(const InterruptionNotice&) = delete;
  InterruptionNotice& operator=(const InterruptionNotice&) = delete;
};

}  // namespace gradfric::campaign
