#pragma once
// The results file of an ensemble run: one parallel HDF5 file (MPI-IO driver) per run.
//
// Every dataset is created, allocated and filled once, by rank 0, when the file is created;
// after that a finished task is written by the rank that ran it alone (independent MPI-IO
// writes into storage that already exists, so no HDF5 metadata changes and nothing is gathered
// on one rank). Attributes are changed by rank 0 alone in the closed file, in room reserved
// first: a full disk ends every rank with the same CollectiveError naming the file, and a file
// being resumed is left as it was (src/io/results_file.cpp). A task writes its data first and its `done` flag last: a run killed at any
// moment leaves a readable file in which every task flagged done is complete. The statistics
// are written, and the `complete` attribute set, collectively at the end.
// The layout is documented field by field in docs/ensemble.md.
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/io/hdf5_handle.hpp"
#include "gradfric/io/provenance.hpp"
#include "gradfric/io/results_schema.hpp"
#include "gradfric/physics/friction_history.hpp"

#include <mpi.h>

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace gradfric::io {

// The root attribute format_version, per format (formatVersion below).
// 2: units, dimension scales, forces, properties, provenance; 3: every interval a 95 % Student t
// interval (mu_*_relative_ci95 for mu_*_relative_error), an `interval` attribute on each, discretisation bars.
inline constexpr int kFormatVersion = 3;  // gradfric-sbm-ensemble
// 4, the FEM's files only: the axes of /properties are the bottom cells (cell_x [nx], cell_y [ny],
// their centres in m) instead of block_column, block_row and map_side; no /sweep/sigma,
// /sweep/sigma_kinetic or /realisations/redrawn_blocks; a single run stores its samples alone
// (history capacity = its length) and no /sweep/reference_point or relative statistics.
// 5: /realisations/nodes_slid_above_one and area_slid_above_one (the flutter flag of each run).
inline constexpr int kFemFormatVersion = 5;  // gradfric-fem-sweep, gradfric-fem-run
inline constexpr const char* kFormatName = "gradfric-sbm-ensemble";
// The same layout filled by a sweep of finite-element runs (gradfric-fem, one run per point).
inline constexpr const char* kFemSweepFormatName = "gradfric-fem-sweep";
// The same layout filled by one finite-element run (gradfric-fem without a sweep): one point, one
// realisation, with the run's FEM extras under /fem (docs/fem.md). Its own name: a single run is
// not resumed or extended as a sweep.
inline constexpr const char* kFemRunFormatName = "gradfric-fem-run";

// The format version this build writes (and resumes) for a format name.
inline int formatVersion(const std::string& format) {
  return format == kFemSweepFormatName || format == kFemRunFormatName ? kFemFormatVersion : kFormatVersion;
}

// A per-point column of /statistics: real (float64, NaN until written) or integer (int32), with
// its units, description and further text attributes (`interval`, `basis`).
struct StatisticColumn {
  std::string name;
  std::string units = "1";
  std::string description;
  bool integer = false;
  std::vector<std::pair<std::string, std::string>> attributes;
};

struct EnsembleLayout {
  std::string format = kFormatName;  // the root attribute `format`: kFormatName, kFemSweepFormatName or kFemRunFormatName
  int points = 0;        // P sweep points
  int realisations = 0;  // R realisations per point
  int historyCapacity = 0;  // C: mu(t) samples kept per task (0: no histories; a single FEM run: its samples)
  int mapSide = 0;          // N_b: side of the first-slip and stress maps (the spring-block lattice's)
  // A FEM file's axes of /properties instead of the lattice's: the centres [m] of the bottom cell
  // columns along x (cell_x, nx of them) and, with property-field maps only, of the bottom cell
  // rows along y (cell_y, ny; empty: no map over y).
  std::vector<double> cellX, cellY;
  bool firstSlipMap = false;
  bool frictionFields = false;  // /maps/mu_s_local, mu_k_local: each realisation's local coefficients
  std::vector<double> snapshotTimes;  // requested sigma_x/p snapshot times [s] (S of them)
  // The per-point columns of /statistics (ensemble/statistics_columns.hpp makes them); read
  // back from a file, a column has its name, type, units and description.
  std::vector<StatisticColumn> statistics;

  bool springBlock() const { return format == kFormatName; }  // else a FEM sweep or run
  bool singleRun() const { return format == kFemRunFormatName; }  // no sweep: no reference point
};

// One row per sweep point.
struct SweepTable {
  std::vector<std::string> axes;  // the swept quantities, in loop order (outermost first)
  std::vector<double> delta;
  std::vector<double> theta;  // sliding angle [degree]
  std::vector<double> sigma;  // relative dispersion of mu_s,i (and mu_k,i unless set apart); empty in the FEM
  std::vector<double> sigmaKinetic;  // (a FEM file stores neither: its one surface is /scene's -surface_sigma_*)
  std::vector<std::string> property;  // E, friction, both
  std::vector<std::string> profile;   // none, linear, triangular
  std::vector<int> referencePoint;    // the non-graded point of the same (theta, sigma, ...) or -1 (not stored by a single FEM run)
  // The property fields each point used before random dispersion, P x N_b row-major (point,
  // block column; every row of a column is the same): E [Pa], mean mu_s and mu_k. A FEM file:
  // P x nx (point, bottom cell column, on the middle row).
  std::vector<double> modulus, muStatic, muKinetic;
  // With property fields only (else empty): P x N_b x N_b (point, block row, block column): E [Pa],
  // mean mu_s and mu_k, normal pressure p [Pa] of every block. A FEM file: P x ny x nx (point,
  // bottom cell row, bottom cell column), at the bottom cells' centres.
  std::vector<double> blockModulus, blockMuStatic, blockMuKinetic, blockPressure;
  std::vector<double> fieldValue;  // per point: the swept field parameter (-ensemble_field), else empty
};

struct TaskOutput {
  int point = 0;
  int realisation = 0;
  // The shared observer's measurement (mu_s, peak time and confirmation, mu_k) and its sampled
  // history (time, mu, force_x, force_y: at most historyCapacity samples; empty if not stored).
  FrictionSummary friction;
  double endTime = 0.0;
  std::int64_t steps = 0;
  int redrawnBlocks = 0;
  // The FEM's bottom nodes that slid at mu(theta) > 1 before the peak, and their share of the
  // contact area (docs/flutter.md); -1 and NaN: not measured (a law without state).
  std::int64_t nodesSlidAboveOne = -1;
  double areaSlidAboveOne = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> firstSlipTime;  // N_b x N_b or empty
  std::vector<double> localStatic, localKinetic;  // mu_s,i and mu_k,i, N_b x N_b (frictionFields)
  std::vector<double> snapshotTime;   // actual time of each snapshot taken (<= S)
  std::vector<std::vector<double>> snapshots;  // sigma_x/p maps, N_b x N_b each
  double wallSeconds = 0.0;
  int rank = 0;
};

class ResultsFile {
public:
  // Collective: creates (truncates) path and every dataset of the layout; on failure (CollectiveError
  // on every rank) path is removed.
  static ResultsFile create(MPI_Comm comm, const std::string& path, const EnsembleLayout& layout,
                            const SweepTable& sweep, const std::vector<Attribute>& scene);
  // Collective: opens an existing results file for reading and writing (resume).
  static ResultsFile open(MPI_Comm comm, const std::string& path);
  // Collective: opens read-only (inspection, tests).
  static ResultsFile openReadOnly(MPI_Comm comm, const std::string& path);

  ResultsFile(ResultsFile&&) = default;
  ResultsFile& operator=(ResultsFile&&) = default;
  ~ResultsFile();

  const EnsembleLayout& layout() const { return layout_; }
  const SweepTable& sweep() const { return sweep_; }
  std::vector<Attribute> sceneAttributes() const;
  bool complete() const;

  // Independent: only the rank that ran the task calls it. Data first, then the done flag. A
  // failure is this rank's (Hdf5Error naming the file): the caller agrees on it.
  void writeTask(const TaskOutput& task);
  // Collective: pushes everything written so far to the file (MPI_File_sync). Every collective
  // member below throws the same CollectiveError on every rank when it fails.
  void flush();
  // Collective: copies every task of the results file at `path` (P' x R' with P' <= P, R' <= R:
  // a finished file being extended) into the same (point, realisation) slots of this file, raw
  // bytes, done flags last. Rank 0 reads and writes; nothing is run again.
  void copyTasksFrom(const std::string& path);

  // Every rank reads the whole P x R table (small scalars only).
  std::vector<std::uint8_t> finishedTasks() const;
  long finishedCount() const;  // how many of them are done
  std::vector<double> readRealisationReal(const std::string& name) const;  // mu_s, mu_k, peak_time, ...
  std::vector<std::int8_t> readPeakConfirmed() const;
  std::vector<double> readStatistic(const std::string& name) const;

  // Collective; the values must be the same on every rank (rank 0 writes them).
  void writeStatistics(const std::vector<std::pair<std::string, std::vector<double>>>& real,
                       const std::vector<std::pair<std::string, std::vector<int>>>& integer);
  // Collective: attributes of /run (ranks, sessions, the run-control options): not part of the
  // results, they differ between runs of the same scene.
  void setRunAttributes(const std::vector<Attribute>& attributes);
  // Collective: software version and commit, command line, options files, date, ranks in /run.
  void setProvenance(const Provenance& provenance);
  // Collective: both of the above with one close and reopen of the file.
  void setRun(const std::vector<Attribute>& attributes, const Provenance& provenance);
  // Collective: rank 0 adds a model's own groups to the closed file (write gets the file), in
  // `bytes` of room reserved first; a failure is the same CollectiveError on every rank.
  void addGroups(std::uint64_t bytes, const std::function<void(hid_t file)>& write);
  // Collective: sets the root attribute complete = 1.
  void markComplete();
  // Collective: the same, leaving the file closed (the end of a run: no reopening to close again).
  void markCompleteAndClose();
  // Collective.
  void close();
  // Where the done flags are: their byte offset in the file and their count (P x R, one byte
  // each, row-major), or {0, 0}. Read with plain file reads by the interruption notice.
  std::pair<std::uint64_t, std::uint64_t> doneFlags() const;

private:
  ResultsFile() = default;
  void openFile(unsigned flags);
  void openDatasets();
  // Collective: every rank closes the file, rank 0 applies change to it alone (changeHdf5File,
  // `bytes` of room), the ranks agree on the outcome and open it again.
  void changeOnRank0(std::uint64_t bytes, const std::function<void(hid_t file)>& change);

  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0;
  std::string path_;
  H5File file_;
  EnsembleLayout layout_;
  SweepTable sweep_;
  // The task datasets (results_schema.hpp) and their open handles, in the same order.
  std::vector<TaskDataset> schema_;
  std::vector<H5Dataset> taskData_;
  hid_t taskDataset(const std::string& path) const;
  H5PropertyList independent_;
};

// True if the file at path can be opened as HDF5 (any rank count; serial open on the caller).
bool isHdf5File(const std::string& path);

}  // namespace gradfric::io
