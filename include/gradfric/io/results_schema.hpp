#pragma once
// The per-task part of the results file as one list of dataset specs: what a finished task
// writes, with its type, axes, units, description and how its values come from the task.
// ResultsFile creates, opens, writes and closes the datasets by looping over this list; its
// /realisations scalars are the observable table's rows (physics/observables.hpp).
#include "gradfric/io/hdf5_handle.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace gradfric::io {

struct EnsembleLayout;
struct TaskOutput;

// One dataset [point, realisation, axes...] a task fills one row of.
struct TaskDataset {
  enum class Type { Real, Int8, Int32, Int64 };
  std::string path;               // "realisations/mu_s"
  Type type = Type::Real;
  std::vector<std::string> axes;  // after (point, realisation): sample, snapshot, block_row, block_column
  std::string units, description;
  bool scales = true;  // false under /run: a scale there would let h5diff --exclude-path /run see it
  std::int64_t integerFill = 0;  // reals are filled with NaN
  bool doneFlag = false;         // the task's done flag: written last
  // A real row (the axes' extent, NaN-filled on entry) or an integer scalar.
  std::function<void(const TaskOutput&, std::vector<double>& row)> real;
  std::function<std::int64_t(const TaskOutput&)> integer;
};

// The task datasets of this layout, in the order they are created (the order the dimension
// scales list them in); the done flag is among them and written last.
std::vector<TaskDataset> taskDatasets(const EnsembleLayout& layout);
// The extent of an axis in this layout.
hsize_t axisSize(const EnsembleLayout& layout, const std::string& axis);
// The memory type a spec's values are written from.
hid_t memoryType(TaskDataset::Type type);
// Creates the dataset of a spec (allocated, filled, described) with scales attached along dims.
H5Dataset createTaskDataset(hid_t group, const std::string& name, const TaskDataset& spec,
                            const std::vector<hsize_t>& dims, const std::vector<hid_t>& scales);

}  // namespace gradfric::io
