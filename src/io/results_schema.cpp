// The per-task datasets of a results file (include/gradfric/io/results_schema.hpp).
#include "gradfric/io/results_schema.hpp"

#include "gradfric/io/hdf5_datasets.hpp"
#include "gradfric/io/results_file.hpp"
#include "gradfric/physics/observables.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace gradfric::io {

namespace {

using Type = TaskDataset::Type;

// values copied into the front of row, the rest left NaN; only a full map (or none) is copied.
void copyInto(const std::vector<double>& values, std::vector<double>& row, std::size_t count) {
  std::copy(values.begin(), values.begin() + std::min({count, values.size(), row.size()}), row.begin());
}

TaskDataset integer(const char* path, Type type, std::int64_t fill, const char* units, const char* description,
                    std::function<std::int64_t(const TaskOutput&)> value) {
  TaskDataset d;
  d.path = path;
  d.type = type;
  d.units = units;
  d.description = description;
  d.integerFill = fill;
  d.integer = std::move(value);
  return d;
}

TaskDataset real(const char* path, std::vector<std::string> axes, const char* units, const char* description,
                 std::function<void(const TaskOutput&, std::vector<double>&)> fill) {
  TaskDataset d;
  d.path = path;
  d.axes = std::move(axes);
  d.units = units;
  d.description = description;
  d.real = std::move(fill);
  return d;
}

// A map [block_row, block_column] per task: copied whole when it has N x N values, else NaN.
TaskDataset map(const char* path, const char* units, const char* description, std::vector<double> TaskOutput::*field,
                std::size_t cells) {
  return real(path, {"block_row", "block_column"}, units, description,
              [field, cells](const TaskOutput& t, std::vector<double>& row) {
                if ((t.*field).size() == cells) row = t.*field;
              });
}

}  // namespace

namespace {

hid_t fileType(Type type) {
  switch (type) {
    case Type::Int8: return H5T_STD_I8LE;
    case Type::Int32: return H5T_STD_I32LE;
    case Type::Int64: return H5T_STD_I64LE;
    default: return H5T_IEEE_F64LE;
  }
}

}  // namespace

hid_t memoryType(Type type) {
  switch (type) {
    case Type::Int8: return H5T_NATIVE_INT8;
    case Type::Int32: return H5T_NATIVE_INT;
    case Type::Int64: return H5T_NATIVE_INT64;
    default: return H5T_NATIVE_DOUBLE;
  }
}

H5Dataset createTaskDataset(hid_t group, const std::string& name, const TaskDataset& spec,
                            const std::vector<hsize_t>& dims, const std::vector<hid_t>& scales) {
  const hid_t file = fileType(spec.type), memory = memoryType(spec.type);
  const char* n = name.c_str();
  switch (spec.type) {
    case Type::Int8:
      return createDescribedDataset(group, n, file, memory, dims, static_cast<std::int8_t>(spec.integerFill), spec.units,
                                    spec.description, scales);
    case Type::Int32:
      return createDescribedDataset(group, n, file, memory, dims, static_cast<int>(spec.integerFill), spec.units,
                                    spec.description, scales);
    case Type::Int64:
      return createDescribedDataset(group, n, file, memory, dims, spec.integerFill, spec.units, spec.description, scales);
    default:
      return createDescribedDataset(group, n, file, memory, dims, std::numeric_limits<double>::quiet_NaN(), spec.units,
                                    spec.description, scales);
  }
}

hsize_t axisSize(const EnsembleLayout& layout, const std::string& axis) {
  if (axis == "sample") return static_cast<hsize_t>(layout.historyCapacity);
  if (axis == "snapshot") return layout.snapshotTimes.size();
  if (axis == "block_row" || axis == "block_column") return static_cast<hsize_t>(layout.mapSide);
  if (axis == "cell_x") return layout.cellX.size();
  if (axis == "cell_y") return layout.cellY.size();
  throw std::invalid_argument("no axis " + axis + " in a results file");
}

std::vector<TaskDataset> taskDatasets(const EnsembleLayout& layout) {
  std::vector<TaskDataset> out;
  // The observables (their values come from the friction summary), then what the run reports.
  for (const Observable& o : observables()) {
    auto take = o.take;
    out.push_back(real(("realisations/" + o.name).c_str(), {}, o.unit.c_str(), o.description.c_str(),
                       [take](const TaskOutput& t, std::vector<double>& row) { row[0] = take(t.friction); }));
  }
  out.push_back(real("realisations/end_time", {}, "s", "simulated time reached",
                     [](const TaskOutput& t, std::vector<double>& row) { row[0] = t.endTime; }));
  // Each model's words: the spring-block model's run length and slider springs, the FEM's sliding
  // time and contact forces (a FEM file names no spring-block option or concept).
  const bool sbm = layout.springBlock();
  out.push_back(integer("realisations/peak_confirmed", Type::Int8, 0, "1",
                        sbm ? "1 if the peak was confirmed, 0 if the run ended first (-sbm_t_max, -fem_slide_time)"
                            : "1 if the peak was confirmed, 0 if the run ended first (-fem_slide_time)",
                        [](const TaskOutput& t) { return t.friction.peakConfirmed ? 1 : 0; }));
  out.push_back(integer("realisations/steps", Type::Int64, 0, "1", "time steps taken",
                        [](const TaskOutput& t) { return t.steps; }));
  if (sbm)  // the FEM draws no local coefficients
    out.push_back(integer("realisations/redrawn_blocks", Type::Int32, 0, "1",
                          "local coefficients redrawn to keep 0 < mu_k,i <= mu_s,i",
                          [](const TaskOutput& t) { return t.redrawnBlocks; }));
  if (!sbm) {  // the FEM's flutter flag of each run (docs/flutter.md)
    out.push_back(integer("realisations/nodes_slid_above_one", Type::Int64, -1, "1",
                          "bottom nodes that slid at mu(theta) > 1 before the peak: there the onset depends on the mesh "
                          "unless the normal-stress memory resolves it (docs/flutter.md); -1: not measured (a law "
                          "without state)",
                          [](const TaskOutput& t) { return t.nodesSlidAboveOne; }));
    out.push_back(real("realisations/area_slid_above_one", {}, "1", "their share of the contact area (NaN: not measured)",
                       [](const TaskOutput& t, std::vector<double>& row) { row[0] = t.areaSlidAboveOne; }));
  }
  out.push_back(integer("realisations/done", Type::Int8, 0, "1",
                        "1: the task finished and its results are stored; 0: not run (yet)",
                        [](const TaskOutput&) { return 1; }));
  out.back().doneFlag = true;
  out.push_back(real("run/wall_seconds", {}, "s", "wall time of each task [point, realisation]",
                     [](const TaskOutput& t, std::vector<double>& row) { row[0] = t.wallSeconds; }));
  out.push_back(integer("run/rank", Type::Int32, -1, "1", "the MPI rank that ran each task [point, realisation]",
                        [](const TaskOutput& t) { return t.rank; }));
  out[out.size() - 2].scales = out.back().scales = false;

  if (layout.historyCapacity > 0) {
    // A task's samples: as many as it has times and mu values (ResultsFile checks the capacity).
    auto samples = [](const TaskOutput& t) { return std::min(t.friction.time.size(), t.friction.mu.size()); };
    auto history = [&](const char* path, const char* units, const char* description,
                       std::vector<double> FrictionSummary::*field) {
      out.push_back(real(path, {"sample"}, units, description,
                         [field, samples](const TaskOutput& t, std::vector<double>& row) {
                           copyInto(t.friction.*field, row, samples(t));
                         }));
    };
    if (sbm) {
      history("history/time", "s", "time of each mu(t) sample; NaN after the last sample", &FrictionSummary::time);
      history("history/mu", "1", "mu(t) = |sum of the slider forces| / (p L^2); NaN after the last sample",
              &FrictionSummary::mu);
      history("history/force_x", "N", "x component (grading axis) of the sum of the slider-spring forces on the plate",
              &FrictionSummary::forceX);
      history("history/force_y", "N", "y component of the sum of the slider-spring forces on the plate",
              &FrictionSummary::forceY);
    } else {  // a single run's capacity is its length; a sweep's is the most a run can take, each run padded
      const char* past = layout.singleRun() ? "" : "; NaN from sample /history/length on";
      history("history/time", "s", (std::string("time of each mu(t) sample since the start of sliding") + past).c_str(),
              &FrictionSummary::time);
      history("history/mu", "1",
              (std::string("mu(t) = |total tangential contact force| / (p L^2)") + past).c_str(), &FrictionSummary::mu);
      history("history/force_x", "N",
              (std::string("x component (grading axis) of the total tangential contact force on the plate") + past).c_str(),
              &FrictionSummary::forceX);
      history("history/force_y", "N",
              (std::string("y component of the total tangential contact force on the plate") + past).c_str(),
              &FrictionSummary::forceY);
    }
    out.push_back(integer("history/length", Type::Int32, 0, "1", "number of samples of each task",
                          [samples](const TaskOutput& t) { return static_cast<std::int64_t>(samples(t)); }));
  }
  const std::size_t cells = static_cast<std::size_t>(layout.mapSide) * layout.mapSide;
  if (layout.frictionFields) {
    out.push_back(map("maps/mu_s_local", "1", "local static coefficient mu_s,i of each block, as drawn for the realisation",
                      &TaskOutput::localStatic, cells));
    out.push_back(map("maps/mu_k_local", "1", "local kinetic coefficient mu_k,i of each block, as drawn for the realisation",
                      &TaskOutput::localKinetic, cells));
  }
  if (layout.firstSlipMap)
    out.push_back(map("maps/first_slip_time", "s", "time of each block's first slip; NaN: never slipped",
                      &TaskOutput::firstSlipTime, cells));
  if (!layout.snapshotTimes.empty()) {
    // Snapshot s is stored if the task took it (its map, of N x N values, and its time).
    const std::size_t S = layout.snapshotTimes.size();
    out.push_back(real("maps/snapshot_time", {"snapshot"}, "s",
                       "the time each snapshot was taken; NaN if the run ended before",
                       [S](const TaskOutput& t, std::vector<double>& row) {
                         for (std::size_t s = 0; s < S && s < t.snapshots.size(); ++s)
                           if (s < t.snapshotTime.size()) row[s] = t.snapshotTime[s];
                       }));
    out.push_back(real("maps/sigma_x_over_p", {"snapshot", "block_row", "block_column"}, "1",
                       "longitudinal stress sigma_x / p of each block at each snapshot",
                       [S, cells](const TaskOutput& t, std::vector<double>& row) {
                         for (std::size_t s = 0; s < S && s < t.snapshots.size(); ++s)
                           if (t.snapshots[s].size() == cells)
                             std::copy(t.snapshots[s].begin(), t.snapshots[s].end(), row.begin() + s * cells);
                       }));
  }
  return out;
}

}  // namespace gradfric::io
