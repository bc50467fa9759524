#include "gradfric/io/provenance.hpp"

#include "gradfric/core/broadcast.hpp"
#include "gradfric/core/command_line.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/version.hpp"

#include <petscsys.h>

#include <ctime>
#include <fstream>
#include <sstream>

namespace gradfric::io {

namespace {

std::string shellQuoted(const std::string& word) {
  if (!word.empty() && word.find_first_of(" \t\n'\"\\$`*?;&|<>()[]{}!#~") == std::string::npos) return word;
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// Length-prefixed fields, so that texts with any bytes survive the broadcast.
void put(std::string& out, const std::string& field) { out += std::to_string(field.size()) + ':' + field; }

std::string take(const std::string& in, size_t& at) {
  const size_t colon = in.find(':', at);
  const size_t length = std::stoul(in.substr(at, colon - at));
  std::string field = in.substr(colon + 1, length);
  at = colon + 1 + length;
  return field;
}

}  // namespace

Provenance collectProvenance(MPI_Comm comm) {
  int rank = 0;
  Provenance p;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &p.ranks);
  std::string packed;
  if (rank == 0) {
    // The command line as given: PETSc's own has the options files expanded in place.
    const std::vector<std::string>& argv = originalArguments();
    const int argc = static_cast<int>(argv.size());
    std::string line;
    for (int i = 0; i < argc; ++i) line += (i ? " " : "") + shellQuoted(argv[i]);
    put(packed, line);
    put(packed, utcNow());
    std::string files;
    int count = 0;
    for (int i = 1; i + 1 < argc; ++i) {
      if (argv[i] != "-options_file") continue;
      std::ifstream in(argv[i + 1]);
      std::ostringstream text;
      text << in.rdbuf();
      put(files, argv[i + 1]);
      put(files, in ? text.str() : std::string("(could not be read when the run started)"));
      ++count;
    }
    put(packed, std::to_string(count));
    packed += files;
  }
  broadcast(comm, packed);
  size_t at = 0;
  p.version = kVersion;
  p.commit = kCommit;
  p.commandLine = take(packed, at);
  p.date = take(packed, at);
  const int count = std::stoi(take(packed, at));
  for (int i = 0; i < count; ++i) {
    std::string path = take(packed, at);
    p.optionsFiles.emplace_back(std::move(path), take(packed, at));
  }
  return p;
}

void writeProvenance(hid_t group, const Provenance& p) {
  writeStringAttribute(group, "software_version", p.version);
  writeStringAttribute(group, "software_commit", p.commit);
  writeStringAttribute(group, "command_line", p.commandLine);
  writeStringAttribute(group, "date", p.date);
  writeIntAttribute(group, "ranks", p.ranks);
  if (GF_H5(H5Lexists(group, "options_files", H5P_DEFAULT)) > 0)
    GF_H5(H5Ldelete(group, "options_files", H5P_DEFAULT));
  H5Group files = createGroup(group, "options_files");
  for (const auto& [path, text] : p.optionsFiles) writeStringAttribute(files, path, text);
}

}  // namespace gradfric::io
