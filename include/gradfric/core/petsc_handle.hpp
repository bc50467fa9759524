#pragma once
// RAII ownership of PETSc objects: the destructor calls the matching XxxDestroy.
#include <petscdm.h>
#include <petscsection.h>
#include <petscsf.h>
#include <petscis.h>
#include <petscmat.h>
#include <petscts.h>
#include <petscvec.h>
#include <petscviewer.h>

#include <utility>

namespace gradfric {

template <typename Handle, PetscErrorCode (*Destroy)(Handle*)>
class PetscHandle {
public:
  PetscHandle() = default;
  explicit PetscHandle(Handle h) : handle_(h) {}
  ~PetscHandle() { reset(); }
  PetscHandle(const PetscHandle&) = delete;
  PetscHandle& operator=(const PetscHandle&) = delete;
  PetscHandle(PetscHandle&& other) noexcept : handle_(std::exchange(other.handle_, nullptr)) {}
  PetscHandle& operator=(PetscHandle&& other) noexcept {
    if (this != &other) {
      reset();
      handle_ = std::exchange(other.handle_, nullptr);
    }
    return *this;
  }

  Handle get() const { return handle_; }
  operator Handle() const { return handle_; }  // pass straight to PETSc calls
  // For PETSc's create functions: XxxCreate(comm, handle.out()).
  Handle* out() {
    reset();
    return &handle_;
  }
  Handle release() { return std::exchange(handle_, nullptr); }
  void reset() {
    if (handle_) Destroy(&handle_);  // destructors must not throw; PETSc reports its own errors
    handle_ = nullptr;
  }

private:
  Handle handle_ = nullptr;
};

using OwnedVec = PetscHandle<Vec, VecDestroy>;
using OwnedMat = PetscHandle<Mat, MatDestroy>;
using OwnedDM = PetscHandle<DM, DMDestroy>;
using OwnedTS = PetscHandle<TS, TSDestroy>;
using OwnedIS = PetscHandle<IS, ISDestroy>;
using OwnedViewer = PetscHandle<PetscViewer, PetscViewerDestroy>;
using OwnedSF = PetscHandle<PetscSF, PetscSFDestroy>;
using OwnedSection = PetscHandle<PetscSection, PetscSectionDestroy>;

}  // namespace gradfric
