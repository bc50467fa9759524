#pragma once
// While a file is open on several ranks (parallel HDF5), an HDF5 failure on one rank (a full disk
// inside a collective write) leaves the other ranks waiting inside the collective call, and
// unwinding would reach collective closes that wait too: the job would hang. Inside a
// CollectiveFileScope such a failure ends the job at once instead: one line naming the file and
// what failed, then MPI_Abort. HDF5's own error stack is not printed inside the scope.
#include <mpi.h>

#include <string>

namespace gradfric::io {

class CollectiveFileScope {
public:
  CollectiveFileScope(MPI_Comm comm, const std::string& path);
  ~CollectiveFileScope();
  CollectiveFileScope(const CollectiveFileScope&) = delete;
  CollectiveFileScope& operator=(const CollectiveFileScope&) = delete;
};

// The innermost entry of HDF5's error stack ("No space left on device", "truncated file: ..."),
// or "" if the stack is empty: the most specific reason HDF5 gives.
std::string innermostHdf5Reason();

// Runs f with HDF5's automatic error printing switched off (checks that expect failures).
template <class F>
auto withoutHdf5Printing(F&& f) -> decltype(f());

}  // namespace gradfric::io

#include <hdf5.h>

namespace gradfric::io {

template <class F>
auto withoutHdf5Printing(F&& f) -> decltype(f()) {
  H5E_auto2_t function = nullptr;
  void* data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &function, &data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  struct Restore {
    H5E_auto2_t function;
    void* data;
    ~Restore() { H5Eset_auto2(H5E_DEFAULT, function, data); }
  } restore{function, data};
  return f();
}

}  // namespace gradfric::io
