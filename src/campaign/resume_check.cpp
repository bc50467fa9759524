// Is the file given to -resume a results file of this scene? Checked on rank 0 with
// HDF5's error printing off, before any rank opens it in parallel: a foreign, truncated or damaged
// file, or one of another scene, gets one line saying what is wrong with it (exit 2).
#include "gradfric/campaign/resume_check.hpp"

#include "gradfric/campaign/campaign_file.hpp"
#include "gradfric/campaign/statistics_columns.hpp"
#include "gradfric/core/broadcast.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/io/collective_file.hpp"
#include "gradfric/io/hdf5_datasets.hpp"
#include "gradfric/physics/observables.hpp"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>

#include <unistd.h>

namespace gradfric::campaign {

namespace {

// Options renamed or added since a file was written: the file's attribute `before` reads as
// `now`, with its value or, for an option added since, the value `valueBefore` its scene had. A
// spring-block file from before the random surface is the scene -surface_kind blocks.
struct RenamedOption {
  const char* before;
  const char* now;
  const char* valueBefore;  // for an added option: the file's scene had this
};
const RenamedOption kRenamedOptions[] = {{"sbm_sigma_s", "surface_sigma_s", nullptr},
                                         {"sbm_sigma_k", "surface_sigma_k", nullptr},
                                         {"sbm_sigma_s", "surface_kind", "blocks"}};

// "" if the scene and layout match; else the differences, "; "-separated. An extension may
// change the options it names and grow the sweep and the count.
std::string sceneDifferences(const ResumeTarget& scene, const io::ResultsFile& file, const Extension* extension) {
  std::string differences;
  auto add = [&](const std::string& text) { differences += (differences.empty() ? "" : "; ") + text; };
  auto has = [](const std::vector<io::Attribute>& list, const std::string& name) {
    return std::any_of(list.begin(), list.end(), [&](const io::Attribute& a) { return a.name == name; });
  };
  // An older file's spelling, read as today's.
  const std::vector<io::Attribute> written = file.sceneAttributes();
  std::vector<io::Attribute> stored;
  for (const io::Attribute& a : written) {
    bool renamed = false;
    for (const RenamedOption& r : kRenamedOptions)
      if (a.name == r.before && !has(written, r.now) && !has(scene.sceneAttributes, r.before)) {
        renamed = true;
        stored.push_back({r.now, r.valueBefore ? r.valueBefore : a.value, a.unit, a.origin});
      }
    if (!renamed) stored.push_back(a);
  }
  auto findStored = [&](const std::string& name) -> const io::Attribute* {
    for (const auto& a : stored)
      if (a.name == name) return &a;
    return nullptr;
  };
  for (const auto& a : scene.sceneAttributes) {
    if (extension && extension->mayChange(a.name)) continue;
    const io::Attribute* s = findStored(a.name);
    if (!s) add("-" + a.name + " = " + a.value + " (not in the file)");
    else if (s->value != a.value) add("-" + a.name + ": file " + s->value + ", now " + a.value);
  }
  for (const auto& s : stored) {
    bool found = false;
    for (const auto& a : scene.sceneAttributes) found = found || a.name == s.name;
    if (!found && !(extension && extension->mayChange(s.name))) add("-" + s.name + " = " + s.value + " (in the file only)");
  }
  const auto& l = file.layout();
  const auto& want = scene.layout;
  if (l.format != want.format) add("format: file " + l.format + ", now " + want.format);
  const bool sameCount = extension || (l.points == want.points && l.realisations == want.realisations);
  if (!sameCount || l.historyCapacity != want.historyCapacity ||
      l.mapSide != want.mapSide || l.cellX != want.cellX || l.cellY != want.cellY ||
      l.firstSlipMap != want.firstSlipMap || l.frictionFields != want.frictionFields ||
      l.snapshotTimes.size() != want.snapshotTimes.size())
    add("layout (points, realisations, history capacity or maps)");
  return differences;
}

// The first dataset of an observable (physics/observables.hpp: /realisations/<name> and its
// /statistics columns) this build writes and the file lacks, "" if none: a file of an earlier
// build, before that observable was added, cannot take this build's tasks. An extension writes a
// new file and copies the tasks alone (statistics: false). Both lists are the same for any scene.
std::string missingObservable(hid_t file, bool statistics) {
  std::vector<std::string> paths;
  for (const Observable& o : observables()) paths.push_back("realisations/" + o.name);
  if (statistics)
    for (const io::StatisticColumn& c : statisticsColumns()) paths.push_back("statistics/" + c.name);
  for (const std::string& path : paths) {
    const std::string group = path.substr(0, path.find('/'));  // HDF5 1.10 fails on a path through a missing group
    if (H5Lexists(file, group.c_str(), H5P_DEFAULT) <= 0 || H5Lexists(file, path.c_str(), H5P_DEFAULT) <= 0)
      return "/" + path;
  }
  return "";
}

// Rank 0: what is wrong with the file, or "". `extension`: null to resume.
std::string problemWith(const ResumeTarget& target, const Extension* extension, const std::string& path) {
  const std::string again = " (start again with " + target.overwriteOption + ")";
  if (!io::isHdf5File(path)) return "it is not an HDF5 file" + again;
  {
    io::H5File raw(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    if (!raw.valid()) {
      const std::string reason = io::innermostHdf5Reason();
      return "it is truncated or damaged, HDF5 cannot open it" + (reason.empty() ? "" : " (" + reason + ")") + again;
    }
    const htri_t hasFormat = H5Aexists(raw, "format");
    if (hasFormat < 0) {
      const std::string reason = io::innermostHdf5Reason();
      return "it is damaged: its root group cannot be read" + (reason.empty() ? "" : " (" + reason + ")") + again;
    }
    if (hasFormat == 0)
      return "it is not a gradfric ensemble results file (no attribute format = " + target.layout.format +
             ": a file of another program, or a damaged one)" + again;
  }
  try {
    {  // A file of another format version gets its own sentence from ResultsFile (it reads the version).
      io::H5File raw(GF_H5(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)));
      const bool sameVersion =
          io::readScalarAttribute<int>(raw, "format_version", H5T_NATIVE_INT, 0) == io::formatVersion(target.layout.format);
      const std::string missing = sameVersion ? missingObservable(raw, extension == nullptr) : "";
      if (!missing.empty())
        return "it has no " + missing + ": it was written by an earlier gradfric, before that observable existed" +
               again;
    }
    io::ResultsFile file = io::ResultsFile::openReadOnly(MPI_COMM_SELF, path);
    // Everything a resumed run reads: a damaged part shows here, not in the middle of the run.
    file.finishedTasks();
    observableTables(file);
    file.readPeakConfirmed();
    const std::string differences = sceneDifferences(target, file, extension);
    const std::string mismatch = extension && differences.empty() ? extension->mismatch(file) : "";
    const bool complete = file.complete();
    file.close();
    if (extension && !differences.empty())
      return "it was made with another scene, beyond what an extension may change (the count, the target, "
             "appended sweep values): " + differences;
    if (!mismatch.empty()) return mismatch;
    if (extension && !complete)
      return "it is not finished (attribute complete = 0): finish it with -resume first";
    if (!differences.empty())
      return "it was started with another scene (run that scene, or start again with " + target.overwriteOption + "): " +
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

namespace {

// HDF5 1.10 can loop for ever on some damaged files (a corrupt global heap behind a string
// attribute): past a time limit, rank 0 says so and exits, which ends the job (no hang).
char timeoutMessage[1024];

void onTimeout(int) {
  const ssize_t ignored = write(STDERR_FILENO, timeoutMessage, std::strlen(timeoutMessage));
  (void)ignored;
  _exit(2);
}

std::string problemWithin(const ResumeTarget& target, const Extension* extension, const std::string& path,
                          unsigned seconds) {
  std::snprintf(timeoutMessage, sizeof timeoutMessage,
                "gradfric: error: invalid option %s (continue %s): it is damaged: HDF5 did not finish "
                "reading it within %u s (start again with %s)\n",
                extension ? extension->option.c_str() : target.resumeOption.c_str(), path.c_str(), seconds,
                target.overwriteOption.c_str());
  struct sigaction action {}, previous{};
  action.sa_handler = onTimeout;
  sigaction(SIGALRM, &action, &previous);
  alarm(seconds);
  const std::string problem = io::withoutHdf5Printing([&] { return problemWith(target, extension, path); });
  alarm(0);
  sigaction(SIGALRM, &previous, nullptr);
  return problem;
}

}  // namespace

namespace {

// Rank 0 checks, every rank throws the same InputError.
void checkFile(MPI_Comm comm, const ResumeTarget& target, const Extension* extension, const std::string& path) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string problem;
  if (rank == 0) problem = problemWithin(target, extension, path, 60);
  broadcast(comm, problem);
  if (!problem.empty())
    throw InputError("invalid option " + (extension ? extension->option + " (extend " : target.resumeOption + " (continue ") +
                     path + "): " + problem);
}

}  // namespace

void checkResumable(MPI_Comm comm, const ResumeTarget& target, const std::string& path) {
  checkFile(comm, target, nullptr, path);
}

void checkExtendable(MPI_Comm comm, const ResumeTarget& target, const Extension& extension, const std::string& path) {
  checkFile(comm, target, &extension, path);
}

}  // namespace gradfric::campaign
