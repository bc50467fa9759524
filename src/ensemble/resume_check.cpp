// Is the file given to -ensemble_resume a results file of this scene? Checked on rank 0 with
// HDF5's error printing off, before any rank opens it in parallel: a foreign, truncated or damaged
// file, or one of another scene, gets one line saying what is wrong with it (exit 2).
#include "gradfric/core/input_error.hpp"
#include "gradfric/ensemble/scene_file.hpp"
#include "gradfric/io/collective_file.hpp"

#include <string>

namespace gradfric::ensemble {

namespace {

// "" if the scene and layout match; else the differences, "; "-separated.
std::string sceneDifferences(const Scene& scene, const io::ResultsFile& file) {
  std::string differences;
  auto add = [&](const std::string& text) { differences += (differences.empty() ? "" : "; ") + text; };
  const std::vector<io::Attribute> stored = file.sceneAttributes();
  auto findStored = [&](const std::string& name) -> const io::Attribute* {
    for (const auto& a : stored)
      if (a.name == name) return &a;
    return nullptr;
  };
  for (const auto& a : scene.sceneAttributes) {
    const io::Attribute* s = findStored(a.name);
    if (!s) add("-" + a.name + " = " + a.value + " (not in the file)");
    else if (s->value != a.value) add("-" + a.name + ": file " + s->value + ", now " + a.value);
  }
  for (const auto& s : stored) {
    bool found = false;
    for (const auto& a : scene.sceneAttributes) found = found || a.name == s.name;
    if (!found) add("-" + s.name + " = " + s.value + " (in the file only)");
  }
  const auto& l = file.layout();
  const auto& want = scene.layout;
  if (l.points != want.points || l.realisations != want.realisations || l.historyCapacity != want.historyCapacity ||
      l.mapSide != want.mapSide || l.firstSlipMap != want.firstSlipMap ||
      l.snapshotTimes.size() != want.snapshotTimes.size())
    add("layout (points, realisations, history capacity or maps)");
  return differences;
}

// Rank 0: what is wrong with the file, or "".
std::string problemWith(const Scene& scene, const std::string& path) {
  const char* again = " (start again with -output_overwrite)";
  if (!io::isHdf5File(path)) return "it is not an HDF5 file" + std::string(again);
  {
    io::H5File raw(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    if (!raw.valid()) {
      const std::string reason = io::innermostHdf5Reason();
      return "it is truncated or damaged, HDF5 cannot open it" + (reason.empty() ? "" : " (" + reason + ")") + again;
    }
    if (H5Aexists(raw, "format") <= 0)
      return "it is an HDF5 file of another program (no attribute format = " + std::string(io::kFormatName) + ")" +
             again;
  }
  try {
    io::ResultsFile file = io::ResultsFile::openReadOnly(MPI_COMM_SELF, path);
    // Everything a resumed run reads: a damaged part shows here, not in the middle of the run.
    file.finishedTasks();
    file.readRealisationReal("mu_s");
    file.readRealisationReal("mu_k");
    file.readPeakConfirmed();
    const std::string differences = sceneDifferences(scene, file);
    file.close();
    if (!differences.empty())
      return "it was started with another scene (run that scene, or start again with -output_overwrite): " +
             differences;
  } catch (const io::Hdf5Error& e) {
    // Format and version problems come as sentences; a failed HDF5 call means a damaged file.
    if (e.reason().empty() && std::string(e.what()).rfind("HDF5 call failed", 0) != 0)
      return e.what() + std::string(again);
    return "it is damaged: a part of it cannot be read" + (e.reason().empty() ? "" : " (" + e.reason() + ")") + again;
  }
  return "";
}

}  // namespace

void checkResumable(MPI_Comm comm, const Scene& scene, const std::string& path) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string problem;
  if (rank == 0) problem = io::withoutHdf5Printing([&] { return problemWith(scene, path); });
  int length = static_cast<int>(problem.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, comm);
  problem.resize(length);
  if (length > 0) MPI_Bcast(problem.data(), length, MPI_CHAR, 0, comm);
  if (!problem.empty()) throw InputError("invalid option -ensemble_resume (continue " + path + "): " + problem);
}

}  // namespace gradfric::ensemble
