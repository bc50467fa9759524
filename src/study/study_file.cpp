#include "gradfric/study/study_file.hpp"

#include "gradfric/io/file_room.hpp"
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/io/hdf5_datasets.hpp"
#include "gradfric/io/hdf5_handle.hpp"
#include "gradfric/io/provenance.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

namespace gradfric::study {

namespace {

// A column's unit and meaning (the layout in docs/accuracy.md); settingUnit: the ladder's knob unit.
std::pair<std::string, std::string> columnMeaning(const std::string& column, const std::string& settingUnit) {
  if (column == "setting") return {settingUnit, "the knob's value at this rung (the ladder's attribute knob)"};
  if (column == "mu_s_error") return {"1", "relative error of the global mu_s (the ladder's attribute error_meaning)"};
  if (column == "mu_k_error") return {"1", "relative error of the global mu_k (the ladder's attribute error_meaning)"};
  if (column == "mu_s_stderr") return {"1", "relative standard error of the ensemble mean of mu_s at this rung"};
  if (column == "mu_k_stderr") return {"1", "relative standard error of the ensemble mean of mu_k at this rung"};
  if (column == "wall_seconds") return {"s", "wall time per realisation (per run in the FEM study)"};
  if (column == "cpu_seconds") return {"s", "CPU time of the run"};
  if (column == "mu_s") return {"1", "global static friction coefficient at this rung (ensemble mean in the SBM study)"};
  if (column == "mu_k") return {"1", "global kinetic friction coefficient at this rung (ensemble mean in the SBM study)"};
  if (column == "dt") return {"s", "time step of the run"};
  if (column == "steps") return {"1", "time steps taken"};
  throw std::logic_error("study file: no meaning for column " + column);
}

std::string textOf(const LadderTable& ladder, const std::string& name) {
  for (const auto& [n, value] : ladder.texts)
    if (n == name) return value;
  return "";
}

}  // namespace

io::OutputPlan planStudyFile(MPI_Comm comm, const std::string& output, bool overwrite) {
  io::OutputRequest request;
  request.option = "-output";
  request.path = output;
  request.temporarySuffix = ".partial";
  request.overwrite = overwrite;
  request.overwriteOption = "-output_overwrite";
  return io::OutputPlan::decide(comm, request);
}

std::vector<std::pair<std::string, std::string>> studyAttributes(
    const RunParameters& record, const std::vector<std::pair<std::string, std::string>>& first) {
  std::vector<std::pair<std::string, std::string>> attributes = {{"format", "gradfric-accuracy-study"}};
  attributes.insert(attributes.end(), first.begin(), first.end());
  for (const auto& option : io::optionAttributes(record)) attributes.emplace_back(option.name, option.value);
  return attributes;
}

void saveStudyFile(MPI_Comm comm, const io::OutputPlan& plan, const StudyFile& content) {
  std::uint64_t bytes = 0;  // the room reserved for it (io/file_room.hpp: a full disk is a clean error)
  for (const auto& [name, value] : content.attributes) bytes += name.size() + value.size() + 64;
  for (const auto& ladder : content.ladders) {
    for (const auto& [name, value] : ladder.texts) bytes += name.size() + value.size() + 64;
    for (const auto& [name, values] : ladder.columns) bytes += 8 * values.size() + 1024;
  }
  const io::Provenance provenance = io::collectProvenance(comm);  // collective: every rank, before rank 0 writes
  for (const auto& [name, text] : provenance.optionsFiles) bytes += name.size() + text.size() + 128;
  bytes += provenance.commandLine.size() + 1024;
  // The conventions of the other results files (io/hdf5_attributes.hpp): UTF-8 string attributes,
  // described datasets on a named axis (each ladder's rung), the provenance record in /provenance.
  plan.writeOnRank0(comm, [&](const std::string& path) {
    io::createHdf5File(path, io::withMetadataRoom(bytes), [&](hid_t file) {
      for (const auto& [name, value] : content.attributes) io::writeStringAttribute(file, name, value);
      for (const auto& ladder : content.ladders) {
        io::H5Group group = io::createGroup(file, ladder.name.c_str());
        for (const auto& [name, value] : ladder.texts) io::writeStringAttribute(group, name, value);
        const hsize_t rungs = ladder.columns.empty() ? 0 : ladder.columns.front().second.size();
        const io::H5Dataset rung = io::createIndexScale(group, "rung", rungs, "rung of the ladder, in the order run");
        for (const auto& [name, values] : ladder.columns) {
          const auto [units, description] = columnMeaning(name, textOf(ladder, "unit"));
          io::writeDescribedColumn(group, name, values, units, description, rung);
        }
      }
      io::H5Group group = io::createGroup(file, "provenance");
      io::writeProvenance(group, provenance);
    });
  });
  plan.commit(comm);
}

}  // namespace gradfric::study
