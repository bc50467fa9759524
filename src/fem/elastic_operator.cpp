#include "gradfric/fem/elastic_operator.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/log_events.hpp"
#include "gradfric/physics/property_sampler.hpp"

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>

namespace gradfric::fem {

const FemLogEvents& femLogEvents() {
  static FemLogEvents events;
  static bool registered = false;
  if (!registered) {
    PetscClassId classId = 0;
    GF_CALL(PetscClassIdRegister("gradfric FEM", &classId));
    GF_CALL(PetscLogEventRegister("GfFemRHS", classId, &events.rhs));
    GF_CALL(PetscLogEventRegister("GfFemElastic", classId, &events.elastic));
    GF_CALL(PetscLogEventRegister("GfFemContact", classId, &events.contact));
    GF_CALL(PetscLogEventRegister("GfFemGeneric", classId, &events.generic));
    GF_CALL(PetscLogEventRegister("GfFemPostStep", classId, &events.postStep));
    GF_CALL(PetscLogEventRegister("GfFemMonitor", classId, &events.monitor));
    registered = true;
  }
  return events;
}

ElasticOperator::ElasticOperator(const PlateMesh& mesh, double youngsModulus, double poissonRatio,
                                 double stiffnessDamping, const Grading& grading, ElementType element,
                                 bool blockedKernel)
    : mesh_(mesh),
      element_(makeBoxElement(mesh.hx(), mesh.hy(), mesh.hz(), poissonRatio, element)),
      beta_(stiffnessDamping) {
  evKernel_ = femLogEvents().elastic;
  evGeneric_ = femLogEvents().generic;
  const double length = mesh.size().length;
  cellModulus_.resize(mesh.localCells());
  const PropertySampler sampler(grading, mesh.size().nx, mesh.size().ny);  // field or bands at the cell centroid
  for (PetscInt c = 0; c < mesh.localCells(); ++c)
    cellModulus_[c] = youngsModulus * sampler.modulus(mesh.cellCentres()[c][0] / length, mesh.cellCentres()[c][1] / length);
  blocked_ = blockedKernel && reflectionBlocks(element_.stiffness.data(), &blocks_);
  setupReference();
  GF_CALL(DMCreateGlobalVector(dmU_, uGlobal_.out()));
  GF_CALL(VecDuplicate(uGlobal_, fGlobal_.out()));
  GF_CALL(DMCreateLocalVector(dmU_, uLocal_.out()));
  GF_CALL(VecDuplicate(uLocal_, fLocalU_.out()));
  GF_CALL(DMCreateLocalVector(mesh.dm(), xLocal_.out()));
  GF_CALL(VecDuplicate(xLocal_, fLocal_.out()));
  PetscInt n = 0;
  GF_CALL(VecGetLocalSize(uGlobal_, &n));
  if (n != 3 * mesh.ownedBlocks()) throw std::runtime_error("plate mesh: displacement and state layouts differ");
}

void ElasticOperator::shuffleCellOrder(unsigned seed) {
  if (seed == 0) return;
  const PetscInt cells = mesh_.localCells();
  std::vector<PetscInt> order(cells);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  std::vector<PetscInt> offsets(cellDispOff_.size());
  std::vector<double> modulus(cells);
  for (PetscInt c = 0; c < cells; ++c) {
    std::copy_n(cellDispOff_.begin() + 8 * order[c], 8, offsets.begin() + 8 * c);
    modulus[c] = cellModulus_[order[c]];
  }
  cellDispOff_ = std::move(offsets);
  shuffledModulus_ = std::move(modulus);
}

void ElasticOperator::setForce(Vec X, Vec F) {
  const PetscInt blocks = mesh_.ownedBlocks();
  {
    const PetscScalar* x = nullptr;
    PetscScalar* u = nullptr;
    GF_CALL(VecGetArrayRead(X, &x));
    GF_CALL(VecGetArray(uGlobal_, &u));
    if (beta_ != 0.0) {
      for (PetscInt b = 0; b < blocks; ++b)
        for (int d = 0; d < 3; ++d) u[3 * b + d] = x[6 * b + d] + beta_ * x[6 * b + 3 + d];
    } else {
      for (PetscInt b = 0; b < blocks; ++b)
        for (int d = 0; d < 3; ++d) u[3 * b + d] = x[6 * b + d];
    }
    GF_CALL(VecRestoreArray(uGlobal_, &u));
    GF_CALL(VecRestoreArrayRead(X, &x));
  }
  GF_CALL(DMGlobalToLocal(dmU_, uGlobal_, INSERT_VALUES, uLocal_));
  kernelForce(uLocal_, fLocalU_);
  GF_CALL(VecZeroEntries(fGlobal_));
  GF_CALL(DMLocalToGlobal(dmU_, fLocalU_, ADD_VALUES, fGlobal_));
  haveForce_ = true;
  PetscScalar* f = nullptr;
  const PetscScalar* fe = nullptr;
  GF_CALL(VecGetArray(F, &f));
  GF_CALL(VecGetArrayRead(fGlobal_, &fe));
  for (PetscInt b = 0; b < blocks; ++b)
    for (int d = 0; d < 3; ++d) f[6 * b + 3 + d] = fe[3 * b + d];
  GF_CALL(VecRestoreArrayRead(fGlobal_, &fe));
  GF_CALL(VecRestoreArray(F, &f));
}

// The energy of the displacements the last setForce saw (the blow-up monitor asks after a step,
// whose right-hand side was evaluated at the step's final positions): (1/2) u . K u from the force
// already computed, no kernel pass or ghost exchange. Otherwise (stiffness damping, another state)
// the kernel runs on X. The choice is made on all ranks together (the fallback is collective).
bool ElasticOperator::lastForceIsFor(Vec X) {
  int mine = haveForce_ && beta_ == 0.0;
  if (mine) {
    const PetscScalar* x = nullptr;
    const PetscScalar* u = nullptr;
    GF_CALL(VecGetArrayRead(X, &x));
    GF_CALL(VecGetArrayRead(uGlobal_, &u));
    for (PetscInt b = 0; b < mesh_.ownedBlocks() && mine; ++b)
      for (int d = 0; d < 3; ++d) mine = mine && u[3 * b + d] == x[6 * b + d];
    GF_CALL(VecRestoreArrayRead(uGlobal_, &u));
    GF_CALL(VecRestoreArrayRead(X, &x));
  }
  int all = 0;
  GF_CALL_MPI(MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_LAND, mesh_.comm()));
  return all != 0;
}

double ElasticOperator::energy(Vec X) {
  double e = 0;
  if (lastForceIsFor(X)) {
    const PetscScalar *u = nullptr, *f = nullptr;
    GF_CALL(VecGetArrayRead(uGlobal_, &u));
    GF_CALL(VecGetArrayRead(fGlobal_, &f));
    for (PetscInt b = 0; b < mesh_.ownedBlocks(); ++b)
      for (int d = 0; d < 3; ++d) e -= 0.5 * u[3 * b + d] * f[3 * b + d];
    GF_CALL(VecRestoreArrayRead(uGlobal_, &u));
    GF_CALL(VecRestoreArrayRead(fGlobal_, &f));
  } else {
    DM dm = mesh_.dm();
    GF_CALL(DMGlobalToLocal(dm, X, INSERT_VALUES, xLocal_));
    GF_CALL(VecZeroEntries(fLocal_));
    const PetscScalar* xl = nullptr;
    PetscScalar* fl = nullptr;
    GF_CALL(VecGetArrayRead(xLocal_, &xl));
    GF_CALL(VecGetArray(fLocal_, &fl));
    applyKernel(mesh_.cellStateOffsets(), xl, fl);
    GF_CALL(VecRestoreArrayRead(xLocal_, &xl));
    GF_CALL(VecRestoreArray(fLocal_, &fl));
    if (!stateForce_) GF_CALL(VecDuplicate(X, stateForce_.out()));
    GF_CALL(VecZeroEntries(stateForce_));
    GF_CALL(DMLocalToGlobal(dm, fLocal_, ADD_VALUES, stateForce_));
    const PetscScalar *x = nullptr, *f = nullptr;
    GF_CALL(VecGetArrayRead(X, &x));
    GF_CALL(VecGetArrayRead(stateForce_, &f));
    for (PetscInt b = 0; b < mesh_.ownedBlocks(); ++b)
      for (int d = 0; d < 3; ++d) e -= 0.5 * x[6 * b + d] * f[6 * b + d];
    GF_CALL(VecRestoreArrayRead(X, &x));
    GF_CALL(VecRestoreArrayRead(stateForce_, &f));
  }
  double sum = 0;
  GF_CALL_MPI(MPI_Allreduce(&e, &sum, 1, MPI_DOUBLE, MPI_SUM, mesh_.comm()));
  return sum;
}

void ElasticOperator::cellStresses(Vec X, std::vector<std::array<double, 6>>* stress) {
  GF_CALL(DMGlobalToLocal(mesh_.dm(), X, INSERT_VALUES, xLocal_));
  const PetscScalar* xl = nullptr;
  GF_CALL(VecGetArrayRead(xLocal_, &xl));
  const std::vector<PetscInt>& off = mesh_.cellStateOffsets();
  stress->resize(mesh_.localCells());
  for (PetscInt c = 0; c < mesh_.localCells(); ++c) {
    double ue[24];
    for (int a = 0; a < 8; ++a)
      for (int d = 0; d < 3; ++d) ue[3 * a + d] = xl[off[8 * c + a] + d];
    (*stress)[c] = cellAverageStress(element_, cellModulus_[c], ue);
  }
  GF_CALL(VecRestoreArrayRead(xLocal_, &xl));
}

// fLocal = -K uLocal on this rank's cells (local vectors of the displacement DM).
void ElasticOperator::kernelForce(Vec uLocal, Vec fLocal) {
  GF_CALL(VecZeroEntries(fLocal));
  const PetscScalar* ul = nullptr;
  PetscScalar* fl = nullptr;
  GF_CALL(VecGetArrayRead(uLocal, &ul));
  GF_CALL(VecGetArray(fLocal, &fl));
  GF_CALL(PetscLogEventBegin(evKernel_, 0, 0, 0, 0));
  applyKernel(cellDispOff_, ul, fl);
  GF_CALL(PetscLogEventEnd(evKernel_, 0, 0, 0, 0));
  GF_CALL(PetscLogFlops((blocked_ ? 312.0 : 1152.0) * mesh_.localCells()));  // blocks + transforms, or 24x24
  GF_CALL(VecRestoreArrayRead(uLocal, &ul));
  GF_CALL(VecRestoreArray(fLocal, &fl));
}

void ElasticOperator::applyKernel(const std::vector<PetscInt>& cellOffsets, const double* u, double* f) const {
  const PetscInt cells = mesh_.localCells();
  // The displacement DM's offsets follow shuffleCellOrder; the state's (energy fallback) do not.
  const double* modulus =
      !shuffledModulus_.empty() && &cellOffsets == &cellDispOff_ ? shuffledModulus_.data() : cellModulus_.data();
  if (blocked_)
    elasticKernelBlocked(cells, cellOffsets.data(), modulus, blocks_.data(), u, f);
  else
    elasticKernel(cells, cellOffsets.data(), modulus, element_.stiffness.data(), u, nullptr, 0.0, f);
}

void ElasticOperator::forceSpecialised(Vec u, Vec f) {
  OwnedVec uLoc, fLoc;
  GF_CALL(DMGetLocalVector(dmU_, uLoc.out()));
  GF_CALL(DMGetLocalVector(dmU_, fLoc.out()));
  GF_CALL(DMGlobalToLocal(dmU_, u, INSERT_VALUES, uLoc));
  kernelForce(uLoc, fLoc);
  GF_CALL(VecZeroEntries(f));
  GF_CALL(DMLocalToGlobal(dmU_, fLoc, ADD_VALUES, f));
  Vec a = uLoc.release(), b = fLoc.release();
  GF_CALL(DMRestoreLocalVector(dmU_, &a));
  GF_CALL(DMRestoreLocalVector(dmU_, &b));
}

void ElasticOperator::addStiffnessDiagonal(Vec diag) {
  OwnedVec local;
  GF_CALL(DMGetLocalVector(dmU_, local.out()));
  GF_CALL(VecZeroEntries(local));
  PetscScalar* d = nullptr;
  GF_CALL(VecGetArray(local, &d));
  const std::vector<double>& modulus = shuffledModulus_.empty() ? cellModulus_ : shuffledModulus_;
  for (PetscInt c = 0; c < mesh_.localCells(); ++c)
    for (int a = 0; a < 8; ++a)
      for (int k = 0; k < 3; ++k)
        d[cellDispOff_[8 * c + a] + k] += modulus[c] * element_.stiffness[25 * (3 * a + k)];
  GF_CALL(VecRestoreArray(local, &d));
  GF_CALL(DMLocalToGlobal(dmU_, local, ADD_VALUES, diag));
  Vec v = local.release();
  GF_CALL(DMRestoreLocalVector(dmU_, &v));
}

}  // namespace gradfric::fem
