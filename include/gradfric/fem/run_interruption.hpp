#pragma once
// SIGINT (Ctrl-C) or SIGTERM (a scheduler's time limit) while a single FEM run steps. Rank 0 says
// at once, from the handler, what is kept:
//   gradfric-fem: interrupted (SIGTERM): the checkpoint of step 41200 (t = 3.1e-3 s) is kept in
//   run.checkpoint.h5; writing one of this step, then stopping; continue with the same command and -resume
// and every rank raises a flag. At its next step the run agrees on the flag over the ranks, writes
// the checkpoint of that step and ends (exit 128 + the signal's number). mpiexec kills its ranks a
// second after it forwarded the signal (Open MPI's odls_base_sigkill_timeout): if that comes before
// the new checkpoint is complete, the one named first is still whole. A second signal ends the run at
// once. Without checkpoints the line says that nothing is kept, and the run ends by the signal.
#include "gradfric/fem/checkpoint.hpp"

#include <mpi.h>

namespace gradfric::fem {

class RunInterruption {
public:
  RunInterruption(MPI_Comm comm, const CheckpointSettings& settings);  // installs the handlers
  ~RunInterruption();                                                  // the earlier handlers back
  RunInterruption(const RunInterruption&) = delete;
  RunInterruption& operator=(const RunInterruption&) = delete;

  // After each checkpoint: what the handler's line names as kept (tSliding < 0: still pressing).
  void kept(long step, double time, double tSliding);
  // The signal this rank has had (SIGINT, SIGTERM) or 0.
  static int pending();
};

}  // namespace gradfric::fem
