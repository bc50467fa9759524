// Checkpoints of a single FEM run (include/gradfric/fem/checkpoint.hpp).
#include "gradfric/fem/checkpoint.hpp"

#include "gradfric/core/broadcast.hpp"
#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/format.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/quiet_wait.hpp"
#include "gradfric/io/collective_file.hpp"
#include "gradfric/io/file_room.hpp"
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/io/hdf5_datasets.hpp"
#include "gradfric/io/hdf5_handle.hpp"

#include <H5FDmpio.h>
#include <petscsys.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <functional>

namespace gradfric::fem {

namespace {

constexpr const char* kFormat = "gradfric-fem-checkpoint 1";

// Options that steer a run without changing its numbers: they may differ between the interrupted
// run and the resumed one.
bool steersOnly(const std::string& name) {
  return name.rfind("-checkpoint_", 0) == 0 || name == "-resume" || name == "-output_overwrite" ||
         name == "-fem_verbose" || name == "-fem_dry_run";
}

std::string outputStem(const std::string& output) {
  const std::string suffix = ".h5";
  if (output.size() > suffix.size() && output.compare(output.size() - suffix.size(), suffix.size(), suffix) == 0)
    return output.substr(0, output.size() - suffix.size());
  return output;
}

int rankOf(MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  return rank;
}

// Runs work on rank 0; its failure is thrown on every rank as the same CollectiveError.
void onRank0(MPI_Comm comm, const std::string& path, const std::function<void()>& work) {
  std::string error;
  if (rankOf(comm) == 0) {
    try {
      io::FileWriteScope scope(path);
      work();
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  waitForRanks(comm);
  agreeOnError(comm, error);
}

io::H5PropertyList parallelAccess(MPI_Comm comm) {
  io::H5PropertyList fapl(GF_H5(H5Pcreate(H5P_FILE_ACCESS)));
  GF_H5(H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL));
  return fapl;
}

// This rank's slab [offset, offset + count) of the "state" dataset, for one collective transfer
// (a rank without bytes selects nothing but takes part).
struct RankSlab {
  io::H5Dataset state;
  io::H5Space space, memory;
  io::H5PropertyList transfer;
  RankSlab(hid_t file, unsigned long long offset, unsigned long long size)
      : state(GF_H5(H5Dopen2(file, "state", H5P_DEFAULT))), space(GF_H5(H5Dget_space(state))) {
    const hsize_t start = offset, count = size;
    memory = io::H5Space(GF_H5(H5Screate_simple(1, &count, nullptr)));
    if (count > 0) {
      GF_H5(H5Sselect_hyperslab(space, H5S_SELECT_SET, &start, nullptr, &count, nullptr));
    } else {
      GF_H5(H5Sselect_none(space));
      GF_H5(H5Sselect_none(memory));
    }
    transfer = io::H5PropertyList(GF_H5(H5Pcreate(H5P_DATASET_XFER)));
    GF_H5(H5Pset_dxpl_mpio(transfer, H5FD_MPIO_COLLECTIVE));
  }
};

// Rank 0, serially: the header of the checkpoint at path.
CheckpointHeader readHeader(const std::string& path) {
  return io::withoutHdf5Printing([&] {
    io::H5File file(GF_H5(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)));
    const auto attributes = io::readStringAttributes(file);
    auto value = [&](const char* name) {
      for (const auto& [key, text] : attributes)
        if (key == name) return text;
      throw std::runtime_error(std::string("no attribute ") + name);
    };
    if (value("format") != kFormat) throw std::runtime_error("format '" + value("format") + "', not " + kFormat);
    CheckpointHeader h;
    h.step = std::stol(value("step"));
    h.time = std::stod(value("time"));
    h.tSliding = std::stod(value("t_sliding"));
    h.ranks = std::stoi(value("ranks"));
    io::H5Dataset scene(GF_H5(H5Dopen2(file, "scene", H5P_DEFAULT)));
    const auto lines = io::readStrings(scene);
    h.scene = lines.empty() ? "" : lines.front();
    return h;
  });
}

// The first line that differs between two scene texts, for the refusal.
std::string firstDifference(const std::string& stored, const std::string& now) {
  auto lineAt = [](const std::string& text, std::size_t& at) {
    const std::size_t end = text.find('\n', at);
    std::string line = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
    at = end == std::string::npos ? text.size() : end + 1;
    return line;
  };
  std::size_t a = 0, b = 0;
  while (a < stored.size() || b < now.size()) {
    const std::string x = lineAt(stored, a), y = lineAt(now, b);
    if (x != y) return "the checkpoint has '" + x + "', this run '" + y + "'";
  }
  return "";
}

}  // namespace

std::string sceneText(const RunParameters& record) {
  std::string text;
  for (const ResolvedOption& o : record.all())
    if (o.origin != OptionOrigin::Derived && !steersOnly(o.name)) text += o.name + " " + o.value + "\n";
  return text;
}

CheckpointSettings readCheckpointSettings(MPI_Comm comm, RunParameters* record, const std::string& output, bool resume,
                                          bool overwrite, const std::string& off) {
  OptionReader options(comm, "checkpoint_", "Checkpoints of a single FEM run (docs/running.md)", record);
  CheckpointSettings s;
  s.interval = options.real("interval", 300.0, "s",
                            "wall time between checkpoints of a single run with -output (0: only on SIGINT/SIGTERM); "
                            "-resume continues from the last one");
  s.path = options.text("file", "", "checkpoint file (default: <-output without .h5>.checkpoint.h5)");
  const std::string test = options.text(
      "test_signal", "", "testing only: SIGNAL@STEP (INT, TERM or KILL): after that step every rank sends itself the signal");
  if (helpRequested()) return s;
  if (!test.empty()) {
    const std::size_t at = test.find('@');
    const std::string name = test.substr(0, at);
    s.testSignal = name == "INT" ? SIGINT : name == "TERM" ? SIGTERM : name == "KILL" ? SIGKILL : 0;
    char* end = nullptr;
    if (at != std::string::npos) s.testStep = std::strtol(test.c_str() + at + 1, &end, 10);
    if (s.testSignal == 0 || at == std::string::npos || !end || *end != '\0' || s.testStep < 1)
      throw InputError("-checkpoint_test_signal", test, "SIGNAL@STEP with SIGNAL INT, TERM or KILL and STEP >= 1");
  }
  if (!(s.interval >= 0.0))
    throw InputError("-checkpoint_interval", formatReal(s.interval), "0 (only when interrupted) or more seconds");
  s.resume = resume;
  s.overwrite = overwrite;
  if (output.empty())
    s.off = "no -output: a run without a results file keeps nothing";
  else
    s.off = off;
  if (!s.off.empty()) {
    if (resume) throw InputError("-resume", "true", "a single run with checkpoints (they are off: " + s.off + ")");
    if (options.wasSet("file") || options.wasSet("interval"))
      throw InputError(options.wasSet("file") ? "-checkpoint_file" : "-checkpoint_interval",
                       options.wasSet("file") ? s.path : formatReal(s.interval),
                       "a run with checkpoints (they are off: " + s.off + ")");
    s.path.clear();
    return s;
  }
  if (s.path.empty()) s.path = outputStem(output) + ".checkpoint.h5";
  if (s.path == output) throw InputError("-checkpoint_file", s.path, "a file other than -output");
  s.scene = sceneText(*record);
  return s;
}

std::optional<CheckpointHeader> peekCheckpoint(MPI_Comm comm, const std::string& path) {
  int state = 0;  // 0 none, 1 found, 2 unreadable
  CheckpointHeader h;
  std::string why;
  if (rankOf(comm) == 0 && access(path.c_str(), F_OK) == 0) {
    try {
      h = readHeader(path);
      state = 1;
    } catch (const std::exception& e) {
      state = 2;
      why = e.what();
    }
  }
  MPI_Bcast(&state, 1, MPI_INT, 0, comm);
  if (state == 0) return std::nullopt;
  if (state == 2) {
    broadcast(comm, why);
    throw InputError("-resume", path, "a checkpoint of gradfric-fem (" + path + " is not one: " + why + ")");
  }
  long long numbers[2] = {h.step, h.ranks};
  double times[2] = {h.time, h.tSliding};
  MPI_Bcast(numbers, 2, MPI_LONG_LONG, 0, comm);
  MPI_Bcast(times, 2, MPI_DOUBLE, 0, comm);
  h.step = static_cast<long>(numbers[0]);
  h.ranks = static_cast<int>(numbers[1]);
  h.time = times[0];
  h.tSliding = times[1];
  broadcast(comm, h.scene);
  return h;
}

// Rank 0: why the checkpoint cannot be written at path ("" if it can): a directory, or a folder
// that is missing or not writable (the first checkpoint may come hours into the run).
static std::string unwritable(const std::string& path) {
  struct stat info {};
  if (stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) return path + " is a directory";
  const std::size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  if (stat(folder.c_str(), &info) != 0 || !S_ISDIR(info.st_mode)) return "the folder " + folder + " does not exist";
  if (access(folder.c_str(), W_OK | X_OK) != 0) return "the folder " + folder + " is not writable";
  return "";
}

std::optional<CheckpointHeader> checkpointToResume(MPI_Comm comm, const CheckpointSettings& settings) {
  if (settings.path.empty()) return std::nullopt;
  std::string why;
  if (rankOf(comm) == 0) why = unwritable(settings.path);
  broadcast(comm, why);
  if (!why.empty()) throw InputError("-checkpoint_file", settings.path, "a file in an existing, writable folder (" + why + ")");
  if (!settings.resume) {
    int exists = 0;
    if (rankOf(comm) == 0) exists = access(settings.path.c_str(), F_OK) == 0;
    MPI_Bcast(&exists, 1, MPI_INT, 0, comm);
    if (exists && !settings.overwrite)
      throw InputError("-resume", "false",
                       "-resume to continue from the checkpoint " + settings.path +
                           " of an interrupted run, or -output_overwrite to start again and replace it");
    return std::nullopt;
  }
  std::optional<CheckpointHeader> h = peekCheckpoint(comm, settings.path);
  if (!h) return std::nullopt;
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  if (h->ranks != ranks)
    throw InputError("-resume", settings.path,
                     "a checkpoint written on this number of ranks (" + std::to_string(ranks) + "); it was written on " +
                         std::to_string(h->ranks) + ": resume with mpiexec -n " + std::to_string(h->ranks));
  if (h->scene != settings.scene)
    throw InputError("-resume", settings.path,
                     "a checkpoint of this run's scene: " + firstDifference(h->scene, settings.scene) +
                         " (resume with the interrupted run's options, or start again without -resume)");
  return h;
}

void writeCheckpoint(MPI_Comm comm, const CheckpointSettings& settings, const CheckpointHeader& header,
                     const std::vector<char>& bytes) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  const int rank = rankOf(comm);
  std::vector<unsigned long long> sizes(ranks);
  const unsigned long long mine = bytes.size();
  MPI_Allgather(&mine, 1, MPI_UNSIGNED_LONG_LONG, sizes.data(), 1, MPI_UNSIGNED_LONG_LONG, comm);
  unsigned long long total = 0, offset = 0;
  for (int r = 0; r < ranks; ++r) {
    if (r == rank) offset = total;
    total += sizes[r];
  }
  const std::string partial = settings.path + ".partial";
  // Rank 0 lays the file out, every byte of the state's storage allocated, in room reserved first.
  onRank0(comm, partial, [&] {
    unlink(partial.c_str());
    try {
      io::createHdf5File(partial, io::withMetadataRoom(total + 8 * sizes.size() + settings.scene.size()), [&](hid_t file) {
        io::writeStringAttribute(file, "format", kFormat);
        io::writeStringAttribute(file, "step", std::to_string(header.step));
        io::writeStringAttribute(file, "time", formatReal(header.time));
        io::writeStringAttribute(file, "t_sliding", formatReal(header.tSliding));
        io::writeStringAttribute(file, "ranks", std::to_string(ranks));
        io::H5Dataset scene = io::createStringDataset(file, "scene", 1, settings.scene.size());
        io::writeStrings(scene, {settings.scene}, H5P_DEFAULT);
        const hsize_t length = std::max<hsize_t>(total, 1), count = sizes.size();
        io::H5Space space(GF_H5(H5Screate_simple(1, &length, nullptr)));
        io::H5PropertyList dcpl(GF_H5(H5Pcreate(H5P_DATASET_CREATE)));
        GF_H5(H5Pset_alloc_time(dcpl, H5D_ALLOC_TIME_EARLY));
        io::H5Dataset state(GF_H5(H5Dcreate2(file, "state", H5T_NATIVE_UCHAR, space, H5P_DEFAULT, dcpl, H5P_DEFAULT)));
        io::H5Space sizeSpace(GF_H5(H5Screate_simple(1, &count, nullptr)));
        io::H5Dataset sizeSet(
            GF_H5(H5Dcreate2(file, "sizes", H5T_STD_U64LE, sizeSpace, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)));
        GF_H5(H5Dwrite(sizeSet, H5T_NATIVE_ULLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, sizes.data()));
      });
    } catch (...) {
      unlink(partial.c_str());
      throw;
    }
  });
  // Every rank writes its slab of raw data into the allocated storage, in parallel.
  std::string error;
  try {
    io::FileWriteScope scope(partial);
    io::H5PropertyList fapl = parallelAccess(comm);
    io::H5File file(GF_H5(H5Fopen(partial.c_str(), H5F_ACC_RDWR, fapl)));
    const RankSlab slab(file, offset, mine);
    GF_H5(H5Dwrite(slab.state, H5T_NATIVE_UCHAR, slab.memory, slab.space, slab.transfer, bytes.data()));
  } catch (const std::exception& e) {
    error = e.what();
  }
  agreeOnError(comm, error);
  // Complete: it replaces the previous checkpoint in one step.
  onRank0(comm, settings.path, [&] {
    io::releaseRoom(partial);
    if (std::rename(partial.c_str(), settings.path.c_str()) != 0)
      throw std::runtime_error("renaming " + partial + " to " + settings.path + " failed");
  });
}

std::vector<char> readCheckpointBytes(MPI_Comm comm, const std::string& path) {
  const int rank = rankOf(comm);
  std::vector<char> bytes;
  std::string error;
  try {
    io::H5PropertyList fapl = parallelAccess(comm);
    io::H5File file(GF_H5(H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl)));
    io::H5Dataset sizeSet(GF_H5(H5Dopen2(file, "sizes", H5P_DEFAULT)));
    io::H5Space sizeSpace(GF_H5(H5Dget_space(sizeSet)));
    std::vector<unsigned long long> sizes(static_cast<std::size_t>(H5Sget_simple_extent_npoints(sizeSpace)));
    GF_H5(H5Dread(sizeSet, H5T_NATIVE_ULLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, sizes.data()));
    if (static_cast<std::size_t>(rank) >= sizes.size()) throw std::runtime_error("no slab for this rank");
    unsigned long long offset = 0;
    for (int r = 0; r < rank; ++r) offset += sizes[r];
    bytes.resize(sizes[rank]);
    const RankSlab slab(file, offset, bytes.size());
    GF_H5(H5Dread(slab.state, H5T_NATIVE_UCHAR, slab.memory, slab.space, slab.transfer, bytes.data()));
  } catch (const std::exception& e) {
    error = "reading the checkpoint " + path + " failed on rank " + std::to_string(rank) + ": " + e.what();
  }
  agreeOnError(comm, error);
  return bytes;
}

void removeCheckpoint(MPI_Comm comm, const CheckpointSettings& settings) {
  if (settings.path.empty()) return;
  if (rankOf(comm) == 0) {
    unlink(settings.path.c_str());
    unlink((settings.path + ".partial").c_str());
  }
  MPI_Barrier(comm);
}

}  // namespace gradfric::fem
