#pragma once
// Checkpoints of a single FEM run (docs/running.md, "Checkpoints and -resume"). Every
// -checkpoint_interval seconds of wall time, and once more when SIGINT or SIGTERM arrives, the
// run's whole state between two steps is written: each rank's bytes (core/state_archive.hpp: the
// state vector, the integrator's reused right-hand side, the terms' and the law's per-node state,
// the observers, the history so far, the TS time and step) as its slab of one dataset of a
// parallel HDF5 file. The file is written as <path>.partial, in room reserved first
// (io/file_room.hpp), and renamed into place once complete: an interrupted or failed write leaves
// the previous checkpoint whole. -resume reads it back on the same number of ranks and the run
// continues bit for bit: the history of a resumed run is that of the uninterrupted one.
#include "gradfric/core/options.hpp"

#include <mpi.h>

#include <optional>
#include <string>
#include <vector>

namespace gradfric::fem {

struct CheckpointSettings {
  std::string path;          // "": no checkpoints
  double interval = 300.0;   // wall seconds between checkpoints [s]; 0: only when interrupted
  bool resume = false;       // -resume: continue from path if it exists
  bool overwrite = false;    // -output_overwrite: a run started again replaces an earlier checkpoint
  std::string scene;         // the options that define the run: a checkpoint of another scene is refused
  std::string off;           // why there are none ("" when path is set)
  // Testing only (-checkpoint_test_signal TERM@5000): after this step every rank sends itself the
  // signal, as mpiexec or Slurm would (0: none).
  int testSignal = 0;
  long testStep = -1;
};

// Reads -checkpoint_interval and -checkpoint_file (default <output stem>.checkpoint.h5) for a
// single run writing `output`; resume: -resume. Checkpoints need an output file, the gfverlet
// integrator and no field snapshots (their file is not resumable): otherwise they are off, and the
// settings say why; -resume is then refused (InputError). Every rank alike.
CheckpointSettings readCheckpointSettings(MPI_Comm comm, RunParameters* record, const std::string& output,
                                          bool resume, bool overwrite, const std::string& off);
// The options that define the run, as text (the checkpoint's and -resume's test of sameness): every
// option read but those that only steer it (checkpoints, -resume, -output_overwrite, the monitor
// and progress lines).
std::string sceneText(const RunParameters& record);

struct CheckpointHeader {
  long step = 0;          // TS steps taken
  double time = 0.0;      // TS time [s]
  double tSliding = -1;   // time since the start of sliding [s]; < 0: still pressing
  int ranks = 0;
  std::string scene;
};

// Collective: the checkpoint at path, if there is one (rank 0 reads, every rank gets the same).
// A file that is not a readable checkpoint throws InputError naming -resume.
std::optional<CheckpointHeader> peekCheckpoint(MPI_Comm comm, const std::string& path);
// Collective, before any work: with -resume, the checkpoint to continue from (nullopt: none yet,
// the run starts from the beginning and says so); refused (InputError naming -resume) when it is of
// another scene or number of ranks. Without -resume, an existing checkpoint is refused unless
// -output_overwrite (a run started again would replace it at its first checkpoint).
std::optional<CheckpointHeader> checkpointToResume(MPI_Comm comm, const CheckpointSettings& settings);

// Collective: writes every rank's bytes and the header to settings.path (through .partial). Throws
// CollectiveError on every rank when the file cannot be written; the previous checkpoint stays.
void writeCheckpoint(MPI_Comm comm, const CheckpointSettings& settings, const CheckpointHeader& header,
                     const std::vector<char>& bytes);
// Collective: this rank's bytes of the checkpoint at path.
std::vector<char> readCheckpointBytes(MPI_Comm comm, const std::string& path);
// Collective: removes the checkpoint once the run's results are complete.
void removeCheckpoint(MPI_Comm comm, const CheckpointSettings& settings);

}  // namespace gradfric::fem
