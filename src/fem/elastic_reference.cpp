// The elastic operator's displacement-only DM and PETSc's generic PetscFE residual of the same
// operator: the reference the specialised kernel is tested against (tests/fem/test_fem_model.cpp,
// bench/fem/fem_residual.cpp).
#include "gradfric/fem/elastic_operator.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/log_events.hpp"

#include <petscds.h>
#include <petscfe.h>

namespace gradfric::fem {

namespace {

// The RHS residual G = -int grad(phi) : sigma, E from the auxiliary field.
void g1Elastic(PetscInt dim, PetscInt, PetscInt, const PetscInt[], const PetscInt[], const PetscScalar[],
               const PetscScalar[], const PetscScalar u_x[], const PetscInt aOff[], const PetscInt[],
               const PetscScalar a[], const PetscScalar[], const PetscScalar[], PetscReal, const PetscReal[],
               PetscInt, const PetscScalar constants[], PetscScalar f1[]) {
  const double E = a[aOff[0]], nu = constants[0];
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  double trace = 0;
  for (PetscInt d = 0; d < dim; ++d) trace += u_x[d * dim + d];
  for (PetscInt c = 0; c < dim; ++c) {
    for (PetscInt d = 0; d < dim; ++d) f1[c * dim + d] = -mu * (u_x[c * dim + d] + u_x[d * dim + c]);
    f1[c * dim + c] -= lambda * trace;
  }
}

struct FE {
  PetscFE fe = nullptr;
  ~FE() { PetscFEDestroy(&fe); }
};

}  // namespace

void ElasticOperator::setupReference() {
  MPI_Comm comm = mesh_.comm();
  DM dm = mesh_.dm();
  GF_CALL(DMClone(dm, dmU_.out()));
  FE feU, feE;
  GF_CALL(PetscFECreateLagrange(comm, 3, 3, PETSC_FALSE, 1, 1, &feU.fe));
  GF_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(feU.fe), "displacement"));
  GF_CALL(DMSetField(dmU_, 0, nullptr, reinterpret_cast<PetscObject>(feU.fe)));
  GF_CALL(DMCreateDS(dmU_));
  PetscDS ds = nullptr;
  GF_CALL(DMGetDS(dmU_, &ds));
  GF_CALL(PetscDSSetRHSResidual(ds, 0, nullptr, g1Elastic));
  GF_CALL(PetscDSSetImplicit(ds, 0, PETSC_FALSE));  // else the RHS residual is silently zero (3.18)
  const PetscScalar constants[1] = {elements_.front().poissonRatio};
  GF_CALL(PetscDSSetConstants(ds, 1, const_cast<PetscScalar*>(constants)));
  // E per cell as a piecewise-constant auxiliary field.
  GF_CALL(DMClone(dm, dmAux_.out()));
  GF_CALL(PetscFECreateLagrange(comm, 3, 1, PETSC_FALSE, 0, 1, &feE.fe));
  GF_CALL(PetscFECopyQuadrature(feU.fe, feE.fe));
  GF_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(feE.fe), "E"));
  GF_CALL(DMSetField(dmAux_, 0, nullptr, reinterpret_cast<PetscObject>(feE.fe)));
  GF_CALL(DMCreateDS(dmAux_));
  GF_CALL(DMCreateLocalVector(dmAux_, auxLocal_.out()));
  PetscSection auxSection = nullptr, uSection = nullptr;
  GF_CALL(DMGetLocalSection(dmAux_, &auxSection));
  GF_CALL(DMGetLocalSection(dmU_, &uSection));
  PetscInt cStart = 0, cEnd = 0;
  GF_CALL(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscScalar* a = nullptr;
  GF_CALL(VecGetArray(auxLocal_, &a));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    PetscInt off = 0;
    GF_CALL(PetscSectionGetOffset(auxSection, c, &off));
    a[off] = cellModulus_[c - cStart];
  }
  GF_CALL(VecRestoreArray(auxLocal_, &a));
  GF_CALL(DMSetAuxiliaryVec(dmU_, nullptr, 0, 0, auxLocal_));
  GF_CALL(DMSetAuxiliaryVec(dmU_, nullptr, 0, 100, auxLocal_));
  const std::vector<PetscInt>& cellVertices = mesh_.cellVertices();
  cellDispOff_.assign(8 * mesh_.localCells(), 0);
  for (PetscInt c = 0; c < mesh_.localCells(); ++c)
    for (int k = 0; k < 8; ++k) {
      PetscInt off = 0;
      GF_CALL(PetscSectionGetOffset(uSection, cellVertices[8 * c + k] + mesh_.firstVertex(), &off));
      cellDispOff_[8 * c + k] = off;
    }
}

void ElasticOperator::forceGeneric(Vec u, Vec f) {
  Vec uLoc = nullptr, fLoc = nullptr;
  GF_CALL(DMGetLocalVector(dmU_, &uLoc));
  GF_CALL(DMGetLocalVector(dmU_, &fLoc));
  GF_CALL(DMGlobalToLocal(dmU_, u, INSERT_VALUES, uLoc));
  GF_CALL(VecZeroEntries(fLoc));
  {
    const LogEventScope timed(evGeneric_);
    GF_CALL(DMPlexTSComputeRHSFunctionFEM(dmU_, 0.0, uLoc, fLoc, nullptr));
  }
  GF_CALL(VecZeroEntries(f));
  GF_CALL(DMLocalToGlobal(dmU_, fLoc, ADD_VALUES, f));
  GF_CALL(DMRestoreLocalVector(dmU_, &uLoc));
  GF_CALL(DMRestoreLocalVector(dmU_, &fLoc));
}

}  // namespace gradfric::fem
