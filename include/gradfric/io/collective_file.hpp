#pragma once
// HDF5 failures while a file is written. Inside a FileWriteScope a failed HDF5 call throws an
// Hdf5Error whose message names the file, the rank and the reason ("writing out.h5.partial failed
// on rank 1: file write failed: No space left on device"), and HDF5's own error stack is not
// printed. The error is this rank's alone: the caller agrees on it with the other ranks
// (agreeOnError) before any collective call, so that every rank ends with the same message and
// exit code, without MPI_Abort. Collective HDF5 writes are kept from failing at all: every change
// to a file's metadata is made by rank 0 alone, serially, in room reserved first (file_room.hpp);
// the ranks write raw data only, into storage allocated when the file was created.
#include <mpi.h>

#include <string>

namespace gradfric::io {

class FileWriteScope {
public:
  explicit FileWriteScope(const std::string& path);
  ~FileWriteScope();
  FileWriteScope(const FileWriteScope&) = delete;
  FileWriteScope& operator=(const FileWriteScope&) = delete;

private:
  std::string outer_;  // the path of an enclosing scope: the innermost one names the file
};

// "writing <path> failed on rank <r>: <detail>", r the rank in MPI_COMM_WORLD.
std::string writeFailure(const std::string& path, const std::string& detail);

// The innermost entry of HDF5's error stack ("No space left on device", "truncated file: ..."),
// or "" if the stack is empty: the most specific reason HDF5 gives.
std::string innermostHdf5Reason();

// HDF5's automatic error printing switched off for the scope's lifetime (checks that expect
// failures, readers that give their own message), restored at its end.
class Hdf5PrintingOff;
// Runs f with HDF5's automatic error printing switched off.
template <class F>
auto withoutHdf5Printing(F&& f) -> decltype(f());

}  // namespace gradfric::io

#include <hdf5.h>

namespace gradfric::io {

class Hdf5PrintingOff {
public:
  Hdf5PrintingOff() {
    H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~Hdf5PrintingOff() { H5Eset_auto2(H5E_DEFAULT, function_, data_); }
  Hdf5PrintingOff(const Hdf5PrintingOff&) = delete;
  Hdf5PrintingOff& operator=(const Hdf5PrintingOff&) = delete;

private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
};

template <class F>
auto withoutHdf5Printing(F&& f) -> decltype(f()) {
  const Hdf5PrintingOff quiet;
  return f();
}

}  // namespace gradfric::io
