// The parallel results file (include/gradfric/io/results_file.hpp). The ranks write raw data
// only, into storage allocated when rank 0 created the file; every change of its metadata
// (attributes, the layout itself) is made by rank 0 alone in the closed file, in room reserved
// first (file_room.hpp): a full disk is then a clean error every rank agrees on, never a failure
// inside a collective HDF5 call, where the ranks would part ways and wait for ever.
#include "gradfric/io/results_file.hpp"

#include "results_layout.hpp"

#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/quiet_wait.hpp"
#include "gradfric/io/collective_file.hpp"
#include "gradfric/io/file_room.hpp"
#include "gradfric/io/hdf5_datasets.hpp"

#include <H5FDmpio.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gradfric::io {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

H5PropertyList accessList(MPI_Comm comm) {
  H5PropertyList fapl(GF_H5(H5Pcreate(H5P_FILE_ACCESS)));
  GF_H5(H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL));
  return fapl;
}

// Collective: runs work on rank 0 (raw writes into allocated storage, file checks); its failure
// is thrown on every rank as the same CollectiveError.
void onRank0(MPI_Comm comm, const std::string& path, const std::function<void()>& work) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string error;
  if (rank == 0) {
    try {
      FileWriteScope scope(path);
      work();
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  waitForRanks(comm);  // the others sleep while rank 0 works
  agreeOnError(comm, error);
}

}  // namespace

bool isHdf5File(const std::string& path) {
  htri_t result = -1;
  H5E_BEGIN_TRY { result = H5Fis_hdf5(path.c_str()); }
  H5E_END_TRY;
  return result > 0;
}

ResultsFile::~ResultsFile() {
  // A file not closed explicitly (an exception unwinding) is closed here; every rank unwinds
  // through the same path when the error is collective, which is the case for input errors.
}

ResultsFile ResultsFile::create(MPI_Comm comm, const std::string& path, const EnsembleLayout& layout,
                                const SweepTable& sweep, const std::vector<Attribute>& scene) {
  onRank0(comm, path, [&] {
    try {
      createHdf5File(path, detail::layoutBytes(layout, sweep, scene),
                     [&](hid_t file) { detail::writeLayout(file, layout, sweep, scene); });
    } catch (...) {
      unlink(path.c_str());  // a file being created holds nothing yet
      throw;
    }
  });
  ResultsFile f;
  f.comm_ = comm;
  MPI_Comm_rank(comm, &f.rank_);
  f.path_ = path;
  f.layout_ = layout;
  f.sweep_ = sweep;
  f.openFile(H5F_ACC_RDWR);
  f.openDatasets();
  return f;
}

ResultsFile ResultsFile::open(MPI_Comm comm, const std::string& path) {
  ResultsFile f;
  f.comm_ = comm;
  MPI_Comm_rank(comm, &f.rank_);
  f.path_ = path;
  f.openFile(H5F_ACC_RDWR);
  detail::readLayout(f.file_, &f.layout_, &f.sweep_);
  f.openDatasets();
  return f;
}

ResultsFile ResultsFile::openReadOnly(MPI_Comm comm, const std::string& path) {
  ResultsFile f;
  f.comm_ = comm;
  MPI_Comm_rank(comm, &f.rank_);
  f.path_ = path;
  f.openFile(H5F_ACC_RDONLY);
  detail::readLayout(f.file_, &f.layout_, &f.sweep_);
  f.openDatasets();
  return f;
}

void ResultsFile::openFile(unsigned flags) {
  H5PropertyList fapl = accessList(comm_);
  file_ = H5File(GF_H5(H5Fopen(path_.c_str(), flags, fapl)));
  independent_ = H5PropertyList(GF_H5(H5Pcreate(H5P_DATASET_XFER)));
  GF_H5(H5Pset_dxpl_mpio(independent_, H5FD_MPIO_INDEPENDENT));
}

void ResultsFile::changeOnRank0(std::uint64_t bytes, const std::function<void(hid_t)>& change) {
  close();
  onRank0(comm_, path_, [&] { changeHdf5File(path_, bytes, change); });
  openFile(H5F_ACC_RDWR);
  openDatasets();
}

void ResultsFile::openDatasets() {
  schema_ = taskDatasets(layout_);
  taskData_.clear();
  for (const TaskDataset& d : schema_) taskData_.emplace_back(GF_H5(H5Dopen2(file_, d.path.c_str(), H5P_DEFAULT)));
}

hid_t ResultsFile::taskDataset(const std::string& path) const {
  for (size_t i = 0; i < schema_.size(); ++i)
    if (schema_[i].path == path) return i < taskData_.size() ? taskData_[i].get() : H5I_INVALID_HID;  // closed
  throw Hdf5Error("no dataset " + path + " in " + path_);
}

std::vector<Attribute> ResultsFile::sceneAttributes() const { return readOptionRecord(file_, "scene"); }

bool ResultsFile::complete() const { return readScalarAttribute<int>(file_, "complete", H5T_NATIVE_INT, 0) != 0; }

void ResultsFile::writeTask(const TaskOutput& t) {
  FileWriteScope scope(path_);  // a failure names the file; the caller agrees on it
  if (t.point < 0 || t.point >= layout_.points || t.realisation < 0 || t.realisation >= layout_.realisations)
    throw Hdf5Error("task (" + std::to_string(t.point) + ", " + std::to_string(t.realisation) + ") outside the file");
  const size_t samples = std::min(t.friction.time.size(), t.friction.mu.size());
  if (layout_.historyCapacity > 0 && samples > static_cast<size_t>(layout_.historyCapacity))
    throw Hdf5Error("mu(t) history of task (" + std::to_string(t.point) + ", " + std::to_string(t.realisation) +
                    ") has " + std::to_string(samples) + " samples, more than the file's capacity " +
                    std::to_string(layout_.historyCapacity));
  // Whole rows, padding included, so that a task redone after an interruption overwrites whatever
  // a torn earlier write left; the done flag last: it says the rows above are complete.
  auto write = [&](size_t i) {
    const TaskDataset& d = schema_[i];
    std::vector<hsize_t> offset{static_cast<hsize_t>(t.point), static_cast<hsize_t>(t.realisation)}, count{1, 1};
    hsize_t extent = 1;
    for (const auto& axis : d.axes) {
      offset.push_back(0);
      count.push_back(axisSize(layout_, axis));
      extent *= count.back();
    }
    const hid_t memory = memoryType(d.type);
    if (d.type == TaskDataset::Type::Real) {
      std::vector<double> row(extent, kNaN);
      d.real(t, row);
      writeSlab(taskData_[i], memory, offset, count, row.data(), independent_);
      return;
    }
    const std::int64_t value = d.integer(t);
    const std::int8_t small = static_cast<std::int8_t>(value);
    const int medium = static_cast<int>(value);
    const void* data = d.type == TaskDataset::Type::Int8 ? static_cast<const void*>(&small)
                       : d.type == TaskDataset::Type::Int32 ? static_cast<const void*>(&medium)
                                                            : static_cast<const void*>(&value);
    writeSlab(taskData_[i], memory, offset, count, data, independent_);
  };
  for (size_t i = 0; i < schema_.size(); ++i)
    if (!schema_[i].doneFlag) write(i);
  for (size_t i = 0; i < schema_.size(); ++i)
    if (schema_[i].doneFlag) write(i);
}

void ResultsFile::flush() {
  // No metadata is ever dirty here: this is MPI_File_sync, which every rank reaches.
  std::string error;
  try {
    FileWriteScope scope(path_);
    GF_H5(H5Fflush(file_, H5F_SCOPE_GLOBAL));
  } catch (const std::exception& e) {
    error = e.what();
  }
  agreeOnError(comm_, error);
}

void ResultsFile::copyTasksFrom(const std::string& path) {
  onRank0(comm_, path_, [&] {
    H5File old(GF_H5(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)));
    const hsize_t P = static_cast<hsize_t>(readScalarAttribute<int>(old, "points", H5T_NATIVE_INT, 0));
    const hsize_t R = static_cast<hsize_t>(readScalarAttribute<int>(old, "realisations", H5T_NATIVE_INT, 0));
    if (P > static_cast<hsize_t>(layout_.points) || R > static_cast<hsize_t>(layout_.realisations))
      throw Hdf5Error("cannot extend " + path + ": it has more points or realisations than the new file");
    // One point row of one dataset at a time: [p, 0..R, rest...].
    auto copy = [&](const std::string& name) {
      H5Dataset from(GF_H5(H5Dopen2(old, name.c_str(), H5P_DEFAULT)));
      H5Space space(GF_H5(H5Dget_space(from)));
      const int rankOf = H5Sget_simple_extent_ndims(space);
      std::vector<hsize_t> dims(static_cast<size_t>(std::max(rankOf, 0)));
      GF_H5(H5Sget_simple_extent_dims(space, dims.data(), nullptr));
      if (rankOf < 2 || dims[0] != P || dims[1] != R) return;  // not a per-task table
      H5Dataset to(GF_H5(H5Dopen2(file_, name.c_str(), H5P_DEFAULT)));
      H5Type type(GF_H5(H5Dget_type(from)));
      const size_t size = H5Tget_size(type);
      std::vector<hsize_t> count(dims), offset(dims.size(), 0);
      count[0] = 1;
      hsize_t items = 1;
      for (auto c : count) items *= c;
      std::vector<unsigned char> row(items * size);
      H5Space memory(GF_H5(H5Screate_simple(1, &items, nullptr)));
      for (hsize_t p = 0; p < P; ++p) {
        offset[0] = p;
        H5Space source(GF_H5(H5Dget_space(from)));
        GF_H5(H5Sselect_hyperslab(source, H5S_SELECT_SET, offset.data(), nullptr, count.data(), nullptr));
        GF_H5(H5Dread(from, type, memory, source, H5P_DEFAULT, row.data()));
        H5Space target(GF_H5(H5Dget_space(to)));
        GF_H5(H5Sselect_hyperslab(target, H5S_SELECT_SET, offset.data(), nullptr, count.data(), nullptr));
        GF_H5(H5Dwrite(to, type, memory, target, independent_, row.data()));
      }
    };
    for (const char* group : {"realisations", "run", "history", "maps"}) {
      if (H5Lexists(old, group, H5P_DEFAULT) <= 0) continue;
      H5Group g(GF_H5(H5Gopen2(old, group, H5P_DEFAULT)));
      for (const std::string& name : linkNames(g)) {
        H5O_info_t info;
        GF_H5(H5Oget_info_by_name2(g, name.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT));
        if (info.type != H5O_TYPE_DATASET) continue;  // the option record's groups of /run
        if (std::string(group) + "/" + name != "realisations/done") copy(std::string(group) + "/" + name);
      }
    }
    copy("realisations/done");  // last: a task is done once all its data is there
  });
  flush();
  flush();  // sync, barrier, sync: every rank reads what rank 0 copied
}

std::vector<std::uint8_t> ResultsFile::finishedTasks() const {
  auto flags = readAll<std::int8_t>(taskDataset("realisations/done"), H5T_NATIVE_INT8);
  return std::vector<std::uint8_t>(flags.begin(), flags.end());
}

long ResultsFile::finishedCount() const {
  long finished = 0;
  for (auto flag : finishedTasks()) finished += flag ? 1 : 0;
  return finished;
}

std::vector<double> ResultsFile::readRealisationReal(const std::string& name) const {
  H5Dataset d(GF_H5(H5Dopen2(file_, ("realisations/" + name).c_str(), H5P_DEFAULT)));
  return readAll<double>(d, H5T_NATIVE_DOUBLE);
}

std::vector<std::int8_t> ResultsFile::readPeakConfirmed() const {
  return readAll<std::int8_t>(taskDataset("realisations/peak_confirmed"), H5T_NATIVE_INT8);
}

std::vector<double> ResultsFile::readStatistic(const std::string& name) const {
  H5Dataset d(GF_H5(H5Dopen2(file_, ("statistics/" + name).c_str(), H5P_DEFAULT)));
  return readAll<double>(d, H5T_NATIVE_DOUBLE);
}

void ResultsFile::writeStatistics(const std::vector<std::pair<std::string, std::vector<double>>>& real,
                                  const std::vector<std::pair<std::string, std::vector<int>>>& integer) {
  const hsize_t P = static_cast<hsize_t>(layout_.points);
  onRank0(comm_, path_, [&] {  // raw writes into the columns allocated at creation
    for (const auto& [name, values] : real) {
      if (values.size() != P) throw Hdf5Error("statistics column " + name + " has the wrong length");
      H5Dataset d(GF_H5(H5Dopen2(file_, ("statistics/" + name).c_str(), H5P_DEFAULT)));
      writeSlab(d, H5T_NATIVE_DOUBLE, {0}, {P}, values.data(), independent_);
    }
    for (const auto& [name, values] : integer) {
      if (values.size() != P) throw Hdf5Error("statistics column " + name + " has the wrong length");
      H5Dataset d(GF_H5(H5Dopen2(file_, ("statistics/" + name).c_str(), H5P_DEFAULT)));
      writeSlab(d, H5T_NATIVE_INT, {0}, {P}, values.data(), independent_);
    }
  });
  flush();
}

void ResultsFile::setRunAttributes(const std::vector<Attribute>& attributes) {
  std::uint64_t bytes = 0;
  for (const auto& a : attributes) bytes += 2 * (a.name.size() + a.value.size()) + 256;  // old and new, records
  changeOnRank0(withMetadataRoom(bytes), [&](hid_t file) {
    H5Group run(GF_H5(H5Gopen2(file, "run", H5P_DEFAULT)));
    for (const auto& a : attributes) writeStringAttribute(run, a.name, a.value);
  });
}

void ResultsFile::setProvenance(const Provenance& provenance) { setRun({}, provenance); }

void ResultsFile::setRun(const std::vector<Attribute>& attributes, const Provenance& provenance) {
  std::uint64_t bytes = 2 * (provenance.commandLine.size() + provenance.version.size() + provenance.commit.size()) + 2048;
  for (const auto& [name, text] : provenance.optionsFiles) bytes += 2 * (name.size() + text.size()) + 256;
  for (const auto& a : attributes) bytes += 2 * (a.name.size() + a.value.size()) + 256;
  changeOnRank0(withMetadataRoom(bytes), [&](hid_t file) {  // one close and reopen for both
    H5Group run(GF_H5(H5Gopen2(file, "run", H5P_DEFAULT)));
    for (const auto& a : attributes) writeStringAttribute(run, a.name, a.value);
    writeProvenance(run, provenance);
  });
}

void ResultsFile::addGroups(std::uint64_t bytes, const std::function<void(hid_t)>& write) {
  changeOnRank0(withMetadataRoom(bytes), write);
}

void ResultsFile::markComplete() {
  changeOnRank0(0, [](hid_t file) { writeIntAttribute(file, "complete", 1); });  // in place: no room needed
}

void ResultsFile::markCompleteAndClose() {
  close();
  onRank0(comm_, path_, [&] { changeHdf5File(path_, 0, [](hid_t file) { writeIntAttribute(file, "complete", 1); }); });
}

std::pair<std::uint64_t, std::uint64_t> ResultsFile::doneFlags() const {
  const haddr_t offset = H5Dget_offset(taskDataset("realisations/done"));
  if (offset == HADDR_UNDEF) return {0, 0};
  return {offset, static_cast<std::uint64_t>(layout_.points) * static_cast<std::uint64_t>(layout_.realisations)};
}

void ResultsFile::close() {
  taskData_.clear();
  independent_.reset();
  file_.reset();
}

}  // namespace gradfric::io
