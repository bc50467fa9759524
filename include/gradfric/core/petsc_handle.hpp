#pragma once
// RAII ownership of PETSc objects (core/unique_handle.hpp): the destructor calls the matching XxxDestroy.
#include <petscdm.h>
#include <petscsection.h>
#include <petscsf.h>
#include <petscis.h>
#include <petscmat.h>
#include <petscts.h>
#include <petscvec.h>
#include <petscviewer.h>

#include "gradfric/core/unique_handle.hpp"

namespace gradfric {

template <typename Handle, PetscErrorCode (*Destroy)(Handle*)>
struct PetscDestroy {
  static Handle empty() { return nullptr; }
  static bool valid(Handle handle) { return handle != nullptr; }
  static void close(Handle& handle) { Destroy(&handle); }
};

template <typename Handle, PetscErrorCode (*Destroy)(Handle*)>
using PetscHandle = UniqueHandle<Handle, PetscDestroy<Handle, Destroy>>;

using OwnedVec = PetscHandle<Vec, VecDestroy>;
using OwnedMat = PetscHandle<Mat, MatDestroy>;
using OwnedDM = PetscHandle<DM, DMDestroy>;
using OwnedTS = PetscHandle<TS, TSDestroy>;
using OwnedIS = PetscHandle<IS, ISDestroy>;
using OwnedViewer = PetscHandle<PetscViewer, PetscViewerDestroy>;
using OwnedSF = PetscHandle<PetscSF, PetscSFDestroy>;
using OwnedSection = PetscHandle<PetscSection, PetscSectionDestroy>;

}  // namespace gradfric
