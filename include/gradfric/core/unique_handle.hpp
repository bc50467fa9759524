#pragma once
// Sole ownership of a C library's handle (a PETSc object, an HDF5 identifier): the destructor
// closes it through the library's own function. Policy says what an empty handle is and how to
// close one: core/petsc_handle.hpp (XxxDestroy) and io/hdf5_handle.hpp (H5Xclose). PETSc-free.
#include <utility>

namespace gradfric {

template <typename Handle, typename Policy>
class UniqueHandle {
public:
  UniqueHandle() = default;
  explicit UniqueHandle(Handle handle) : handle_(handle) {}
  ~UniqueHandle() { reset(); }
  UniqueHandle(const UniqueHandle&) = delete;
  UniqueHandle& operator=(const UniqueHandle&) = delete;
  UniqueHandle(UniqueHandle&& other) noexcept : handle_(std::exchange(other.handle_, Policy::empty())) {}
  UniqueHandle& operator=(UniqueHandle&& other) noexcept {
    if (this != &other) {
      reset();
      handle_ = std::exchange(other.handle_, Policy::empty());
    }
    return *this;
  }

  Handle get() const { return handle_; }
  operator Handle() const { return handle_; }  // pass straight to the library's calls
  bool valid() const { return Policy::valid(handle_); }
  // For the library's create functions: XxxCreate(comm, handle.out()).
  Handle* out() {
    reset();
    return &handle_;
  }
  // Gives up ownership without closing (the caller closes and checks the result).
  Handle release() { return std::exchange(handle_, Policy::empty()); }
  void reset() {
    if (Policy::valid(handle_)) Policy::close(handle_);  // destructors must not throw: the library reports
    handle_ = Policy::empty();
  }

private:
  Handle handle_ = Policy::empty();
};

}  // namespace gradfric
