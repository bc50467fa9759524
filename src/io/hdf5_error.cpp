// HDF5 failures: the throwing check behind GF_H5, and the scope in which a failure names the file
// being written (include/gradfric/io/collective_file.hpp).
#include "gradfric/io/collective_file.hpp"
#include "gradfric/io/hdf5_handle.hpp"

#include <hdf5.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace gradfric::io {

namespace {

struct ActiveScope {
  std::string path;
  int depth = 0;
  H5E_auto2_t printer = nullptr;
  void* printerData = nullptr;
};

ActiveScope& activeScope() {
  static ActiveScope scope;
  return scope;
}

herr_t keepInnermost(unsigned n, const H5E_error2_t* entry, void* out) {
  // Walked from the innermost entry outwards: the first one is the most specific.
  auto* text = static_cast<std::string*>(out);
  if (n == 0 && entry && entry->desc) *text = entry->desc;
  return 0;
}

}  // namespace

std::string innermostHdf5Reason() {
  std::string text;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keepInnermost, &text);
  return text;
}

// The system's reason when it is one a write can fail with (errno may be stale otherwise).
static std::string systemWriteReason(int error) {
  switch (error) {
    case ENOSPC: case EFBIG: case EDQUOT: case EROFS: case EIO: return std::strerror(error);
    default: return "";
  }
}

void throwHdf5Error(const char* expression, const char* file, int line) {
  const std::string system = systemWriteReason(errno);
  std::string reason = innermostHdf5Reason();
  // "file write failed: time = ..., filename = ..., errno = 28, ...": the head says it, the
  // system's reason follows.
  if (const auto cut = reason.find(": time = "); cut != std::string::npos) reason.resize(cut);
  const ActiveScope& scope = activeScope();
  if (scope.depth > 0)
    throw Hdf5Error(writeFailure(scope.path, (reason.empty() ? std::string("an HDF5 call failed") : reason) +
                                                 (system.empty() ? " (is the disk full or the file system read-only?)"
                                                                 : ": " + system)),
                    reason);
  throw Hdf5Error(std::string("HDF5 call failed: ") + expression + (reason.empty() ? "" : ": " + reason) + " (" +
                      file + ":" + std::to_string(line) + ")",
                  reason);
}

std::string writeFailure(const std::string& path, const std::string& detail) {
  int initialised = 0, rank = 0;
  MPI_Initialized(&initialised);
  if (initialised) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return "writing " + path + " failed on rank " + std::to_string(rank) + ": " + detail;
}

FileWriteScope::FileWriteScope(const std::string& path) {
  ActiveScope& scope = activeScope();
  outer_ = scope.path;
  scope.path = path;
  if (scope.depth++ == 0) {
    H5Eget_auto2(H5E_DEFAULT, &scope.printer, &scope.printerData);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
}

FileWriteScope::~FileWriteScope() {
  ActiveScope& scope = activeScope();
  scope.path = outer_;
  if (--scope.depth == 0) H5Eset_auto2(H5E_DEFAULT, scope.printer, scope.printerData);
}

}  // namespace gradfric::io
