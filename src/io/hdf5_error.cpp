// HDF5 failures: the throwing check behind GF_H5, and the scope in which a failure ends the job
// instead (include/gradfric/io/collective_file.hpp).
#include "gradfric/core/collective_error.hpp"
#include "gradfric/io/collective_file.hpp"
#include "gradfric/io/hdf5_handle.hpp"

#include <hdf5.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace gradfric::io {

namespace {

struct ActiveScope {
  MPI_Comm comm = MPI_COMM_NULL;
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
static std::string writeFailure(int error) {
  switch (error) {
    case ENOSPC: case EFBIG: case EDQUOT: case EROFS: case EIO: return std::strerror(error);
    default: return "";
  }
}

void throwHdf5Error(const char* expression, const char* file, int line) {
  const std::string system = writeFailure(errno);
  const std::string reason = innermostHdf5Reason();
  ActiveScope& scope = activeScope();
  if (scope.depth > 0) {
    int rank = 0;
    MPI_Comm_rank(scope.comm, &rank);
    abortJob(scope.comm, "writing " + scope.path + " failed on rank " + std::to_string(rank) +
                             (reason.empty() ? std::string() : ": " + reason) +
                             (system.empty() ? " (is the disk full or the file system read-only?)" : ": " + system));
  }
  throw Hdf5Error(std::string("HDF5 call failed: ") + expression + (reason.empty() ? "" : ": " + reason) + " (" +
                      file + ":" + std::to_string(line) + ")",
                  reason);
}

CollectiveFileScope::CollectiveFileScope(MPI_Comm comm, const std::string& path) {
  ActiveScope& scope = activeScope();
  if (scope.depth++ == 0) {
    scope.comm = comm;
    scope.path = path;
    H5Eget_auto2(H5E_DEFAULT, &scope.printer, &scope.printerData);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
}

CollectiveFileScope::~CollectiveFileScope() {
  ActiveScope& scope = activeScope();
  if (--scope.depth == 0) {
    H5Eset_auto2(H5E_DEFAULT, scope.printer, scope.printerData);
    scope.comm = MPI_COMM_NULL;
  }
}

}  // namespace gradfric::io
