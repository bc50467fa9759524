#include "gradfric/fem/elastic_operator.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/reproducible_sum.hpp"
#include "gradfric/fem/log_events.hpp"
#include "gradfric/fem/state_view.hpp"

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>

namespace gradfric::fem {

const FemLogEvents& femLogEvents() {
  static FemLogEvents events;
  static bool registered = false;
  if (!registered) {
    events.rhs = registerLogEvent("gradfric FEM", "GfFemRHS");
    events.elastic = registerLogEvent("gradfric FEM", "GfFemElastic");
    events.contact = registerLogEvent("gradfric FEM", "GfFemContact");
    events.generic = registerLogEvent("gradfric FEM", "GfFemGeneric");
    events.postStep = registerLogEvent("gradfric FEM", "GfFemPostStep");
    events.monitor = registerLogEvent("gradfric FEM", "GfFemMonitor");
    events.output = registerLogEvent("gradfric FEM", "GfFemOutput");
    registered = true;
  }
  return events;
}

ElasticOperator::ElasticOperator(const PlateMesh& mesh, const PlateProperties& properties,
                                 const ElasticSettings& settings)
    : mesh_(mesh),
      settings_(settings),
      beta_(settings.stiffnessDamping),
      cellModulus_(properties.cellModulus()) {
  evKernel_ = femLogEvents().elastic;
  evGeneric_ = femLogEvents().generic;
  const double poissonRatio = settings.poissonRatio;
  const ElementType element = settings.element;
  blocked_ = settings.blockedKernel;
  for (const std::array<double, 3>& h : mesh.shapes()) {
    elements_.push_back(makeBoxElement(h[0], h[1], h[2], poissonRatio, element));
    const std::array<double, 576>& k = elements_.back().stiffness;
    stiffnesses_.insert(stiffnesses_.end(), k.begin(), k.end());
    std::array<double, 72> blocks{};
    blocked_ = blocked_ && reflectionBlocks(k.data(), &blocks);
    blocks_.insert(blocks_.end(), blocks.begin(), blocks.end());
  }
  if (mesh.shapes().size() > 1) cellShape_ = mesh.cellShape();
  setupReference();
  GF_CALL(DMCreateGlobalVector(dmU_, uGlobal_.out()));
  GF_CALL(VecDuplicate(uGlobal_, fGlobal_.out()));
  GF_CALL(DMCreateLocalVector(dmU_, uLocal_.out()));
  GF_CALL(VecDuplicate(uLocal_, fLocalU_.out()));
  GF_CALL(DMCreateLocalVector(mesh.dm(), xLocal_.out()));
  PetscInt n = 0;
  GF_CALL(VecGetLocalSize(uGlobal_, &n));
  if (n != 3 * mesh.ownedBlocks()) throw std::runtime_error("plate mesh: displacement and state layouts differ");
  const OrderedAssembly& ordered = mesh.orderedAssembly();
  shared_ = ordered.sharesVertices();
  if (shared_) {
    for (PetscInt c : ordered.boundaryCells()) {
      boundaryDispOff_.insert(boundaryDispOff_.end(), cellDispOff_.begin() + 8 * c, cellDispOff_.begin() + 8 * c + 8);
      boundaryModulus_.push_back(cellModulus_[c]);
      if (!cellShape_.empty()) boundaryShape_.push_back(cellShape_[c]);
    }
    boundarySlots_ = ordered.cornerSlots(3);
    slots_.assign(ordered.slotCount(3), 0.0);
  }
}

void ElasticOperator::reorderSharedSums(const double* uLocal, double* global) {
  if (!shared_) return;
  std::fill(slots_.begin(), slots_.end(), 0.0);
  const PetscInt cells = static_cast<PetscInt>(boundaryModulus_.size());
  const int* shape = boundaryShape_.empty() ? nullptr : boundaryShape_.data();
  if (blocked_)
    elasticKernelBlocked(cells, boundaryDispOff_.data(), boundaryModulus_.data(), blocks_.data(), uLocal, slots_.data(),
                         boundarySlots_.data(), shape);
  else
    elasticKernel(cells, boundaryDispOff_.data(), boundaryModulus_.data(), stiffnesses_.data(), uLocal, nullptr, 0.0,
                  slots_.data(), boundarySlots_.data(), shape);
  mesh_.orderedAssembly().finish(3, slots_, global, 3, 0);
}

void ElasticOperator::fixSharedSums(Vec uLocal, Vec fGlobal) {
  if (!shared_) return;
  const PetscScalar* u = nullptr;
  PetscScalar* f = nullptr;
  GF_CALL(VecGetArrayRead(uLocal, &u));
  GF_CALL(VecGetArray(fGlobal, &f));
  reorderSharedSums(u, f);
  GF_CALL(VecRestoreArray(fGlobal, &f));
  GF_CALL(VecRestoreArrayRead(uLocal, &u));
}

void ElasticOperator::shuffleCellOrder(unsigned seed) {
  if (seed == 0) return;
  const PetscInt cells = mesh_.localCells();
  std::vector<PetscInt> order(cells);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  std::vector<PetscInt> offsets(cellDispOff_.size());
  std::vector<double> modulus(cells);
  std::vector<int> shape(cellShape_.empty() ? 0 : cells);
  for (PetscInt c = 0; c < cells; ++c) {
    std::copy_n(cellDispOff_.begin() + 8 * order[c], 8, offsets.begin() + 8 * c);
    modulus[c] = cellModulus_[order[c]];
    if (!shape.empty()) shape[c] = cellShape_[order[c]];
  }
  cellDispOff_ = std::move(offsets);
  shuffledModulus_ = std::move(modulus);
  shuffledShape_ = std::move(shape);
}

void ElasticOperator::addForce(const LayerContext& ctx, Vec X, Vec F, ContactSums&) {
  const PetscInt blocks = mesh_.ownedBlocks();
  {
    const ReadState x(X);
    PetscScalar* u = nullptr;
    GF_CALL(VecGetArray(uGlobal_, &u));
    if (beta_ != 0.0) {
      for (PetscInt b = 0; b < blocks; ++b)
        for (int d = 0; d < 3; ++d) u[3 * b + d] = x.displacement(b)[d] + beta_ * x.velocity(b)[d];
    } else {
      for (PetscInt b = 0; b < blocks; ++b)
        for (int d = 0; d < 3; ++d) u[3 * b + d] = x.displacement(b)[d];
    }
    GF_CALL(VecRestoreArray(uGlobal_, &u));
  }
  GF_CALL(DMGlobalToLocal(dmU_, uGlobal_, INSERT_VALUES, uLocal_));
  kernelForce(uLocal_, fLocalU_);
  GF_CALL(VecZeroEntries(fGlobal_));
  GF_CALL(DMLocalToGlobal(dmU_, fLocalU_, ADD_VALUES, fGlobal_));
  fixSharedSums(uLocal_, fGlobal_);
  haveForce_ = true;
  {
    const WriteState f(F);
    const PetscScalar* fe = nullptr;
    GF_CALL(VecGetArrayRead(fGlobal_, &fe));
    if (ctx.setForce) {  // first in the list: no zeroing pass
      for (PetscInt b = 0; b < blocks; ++b)
        for (int d = 0; d < 3; ++d) f.force(b)[d] = fe[3 * b + d];
    } else {
      for (PetscInt b = 0; b < blocks; ++b)
        for (int d = 0; d < 3; ++d) f.force(b)[d] += fe[3 * b + d];
    }
    GF_CALL(VecRestoreArrayRead(fGlobal_, &fe));
  }
  if (settings_.energyAudit && beta_ > 0) stiffnessPower_ = stiffnessDampingPower(X);
}

// beta v . K v = 2 beta x (the elastic energy of the velocity field taken as a displacement).
double ElasticOperator::stiffnessDampingPower(Vec X) {
  if (!velocityAsDisplacement_) GF_CALL(VecDuplicate(X, velocityAsDisplacement_.out()));
  {
    const ReadState x(X);
    const WriteState w(velocityAsDisplacement_);
    for (PetscInt b = 0; b < mesh_.ownedBlocks(); ++b)
      for (int d = 0; d < 3; ++d) {
        w.displacement(b)[d] = x.velocity(b)[d];
        w.velocity(b)[d] = 0;
      }
  }
  return 2.0 * beta_ * energy(velocityAsDisplacement_);
}

void ElasticOperator::archive(StateArchive& a) {
  a.field("elastic.stiffnessPower", stiffnessPower_);
  a.field("elastic.stiffnessWork", stiffnessWork_);
  a.field("elastic.beta", beta_);  // the peak's stiffness damping switches it
  if (a.restoring()) haveForce_ = false;  // the cached force is of another state
}

LayerWork ElasticOperator::work() const {
  LayerWork w;  // always reported (0 without the audit): the balance's sums as they were
  w.overRanks = stiffnessWork_;
  w.hasOverRanks = true;
  return w;
}

std::string ElasticOperator::describe() const {
  std::string text = std::string(settings_.element == ElementType::Trilinear ? "q1" : "q1i") + " hexahedra, " +
                     (blocked_ ? "blocked" : "dense") + " kernel";
  if (beta_ > 0) text += ", stiffness-proportional damping " + std::to_string(beta_) + " s";
  return text;
}

void ElasticOperator::writeProperties(PropertySink& sink) const {
  sink.cellField("E", "Pa", "Young's modulus of the cell (the graded E at its centre)", cellModulus_);
}

// The energy of the displacements the last setForce saw (the blow-up monitor asks after a step,
// whose right-hand side was evaluated at the step's final positions): (1/2) u . K u from the force
// already computed, no kernel pass or ghost exchange. Otherwise (stiffness damping, another state)
// the kernel runs on X. The choice is made on all ranks together (the fallback is collective).
bool ElasticOperator::lastForceIsFor(Vec X) {
  int mine = haveForce_ && beta_ == 0.0;
  if (mine) {
    const ReadState x(X);
    const PetscScalar* u = nullptr;
    GF_CALL(VecGetArrayRead(uGlobal_, &u));
    for (PetscInt b = 0; b < mesh_.ownedBlocks() && mine; ++b)
      for (int d = 0; d < 3; ++d) mine = mine && u[3 * b + d] == x.displacement(b)[d];
    GF_CALL(VecRestoreArrayRead(uGlobal_, &u));
  }
  int all = 0;
  GF_CALL_MPI(MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_LAND, mesh_.comm()));
  return all != 0;
}

double ElasticOperator::energy(Vec X) {
  const bool last = lastForceIsFor(X);  // collective
  if (!last) {  // the displacements of X through the displacement DM
    if (!energyU_) {
      GF_CALL(VecDuplicate(uGlobal_, energyU_.out()));
      GF_CALL(VecDuplicate(uGlobal_, energyF_.out()));
    }
    const ReadState x(X);
    PetscScalar* u = nullptr;
    GF_CALL(VecGetArray(energyU_, &u));
    for (PetscInt b = 0; b < mesh_.ownedBlocks(); ++b)
      for (int d = 0; d < 3; ++d) u[3 * b + d] = x.displacement(b)[d];
    GF_CALL(VecRestoreArray(energyU_, &u));
    forceSpecialised(energyU_, energyF_);
  }
  Vec uVec = last ? uGlobal_.get() : energyU_.get();
  Vec fVec = last ? fGlobal_.get() : energyF_.get();
  ExactSum e;
  const PetscScalar *u = nullptr, *f = nullptr;
  GF_CALL(VecGetArrayRead(uVec, &u));
  GF_CALL(VecGetArrayRead(fVec, &f));
  for (PetscInt i = 0; i < 3 * mesh_.ownedBlocks(); ++i) e.add(-0.5 * u[i] * f[i]);
  GF_CALL(VecRestoreArrayRead(uVec, &u));
  GF_CALL(VecRestoreArrayRead(fVec, &f));
  return sumOverRanks(mesh_.comm(), e);
}

void ElasticOperator::cellStresses(Vec X, std::vector<std::array<double, 6>>* stress) {
  GF_CALL(DMGlobalToLocal(mesh_.dm(), X, INSERT_VALUES, xLocal_));
  const ReadState xl(xLocal_);
  const std::vector<PetscInt>& off = mesh_.cellStateOffsets();
  stress->resize(mesh_.localCells());
  for (PetscInt c = 0; c < mesh_.localCells(); ++c) {
    double ue[24];
    for (int a = 0; a < 8; ++a)
      for (int d = 0; d < 3; ++d) ue[3 * a + d] = xl.displacementAt(off[8 * c + a])[d];
    (*stress)[c] = cellAverageStress(elements_[mesh_.cellShape()[c]], cellModulus_[c], ue);
  }
}

// fLocal = -K uLocal on this rank's cells (local vectors of the displacement DM).
void ElasticOperator::kernelForce(Vec uLocal, Vec fLocal) {
  GF_CALL(VecZeroEntries(fLocal));
  const PetscScalar* ul = nullptr;
  PetscScalar* fl = nullptr;
  GF_CALL(VecGetArrayRead(uLocal, &ul));
  GF_CALL(VecGetArray(fLocal, &fl));
  {
    const LogEventScope timed(evKernel_);
    applyKernel(ul, fl);
  }
  GF_CALL(PetscLogFlops((blocked_ ? 312.0 : 1152.0) * mesh_.localCells()));  // blocks + transforms, or 24x24
  GF_CALL(VecRestoreArrayRead(uLocal, &ul));
  GF_CALL(VecRestoreArray(fLocal, &fl));
}

void ElasticOperator::applyKernel(const double* u, double* f) const {
  const PetscInt cells = mesh_.localCells();
  const double* modulus = shuffledModulus_.empty() ? cellModulus_.data() : shuffledModulus_.data();
  const std::vector<int>& shapes = shuffledModulus_.empty() ? cellShape_ : shuffledShape_;
  const int* shape = shapes.empty() ? nullptr : shapes.data();
  if (blocked_)
    elasticKernelBlocked(cells, cellDispOff_.data(), modulus, blocks_.data(), u, f, nullptr, shape);
  else
    elasticKernel(cells, cellDispOff_.data(), modulus, stiffnesses_.data(), u, nullptr, 0.0, f, nullptr, shape);
}

void ElasticOperator::forceSpecialised(Vec u, Vec f) {
  OwnedVec uLoc, fLoc;
  GF_CALL(DMGetLocalVector(dmU_, uLoc.out()));
  GF_CALL(DMGetLocalVector(dmU_, fLoc.out()));
  GF_CALL(DMGlobalToLocal(dmU_, u, INSERT_VALUES, uLoc));
  kernelForce(uLoc, fLoc);
  GF_CALL(VecZeroEntries(f));
  GF_CALL(DMLocalToGlobal(dmU_, fLoc, ADD_VALUES, f));
  fixSharedSums(uLoc, f);
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
  const std::vector<int>& shapes = shuffledModulus_.empty() ? cellShape_ : shuffledShape_;
  for (PetscInt c = 0; c < mesh_.localCells(); ++c) {
    const double* stiffness = stiffnesses_.data() + (shapes.empty() ? 0 : 576 * shapes[c]);
    for (int a = 0; a < 8; ++a)
      for (int k = 0; k < 3; ++k) d[cellDispOff_[8 * c + a] + k] += modulus[c] * stiffness[25 * (3 * a + k)];
  }
  GF_CALL(VecRestoreArray(local, &d));
  OwnedVec assembled;  // diag + the diagonal, its shared sums in the global cell order
  GF_CALL(VecDuplicate(diag, assembled.out()));
  GF_CALL(VecZeroEntries(assembled));
  GF_CALL(DMLocalToGlobal(dmU_, local, ADD_VALUES, assembled));
  PetscScalar* g = nullptr;
  GF_CALL(VecGetArray(assembled, &g));
  mesh_.orderedAssembly().redo(
      3, [&](PetscInt c, double* values) {
        for (int a = 0; a < 8; ++a)
          for (int k = 0; k < 3; ++k)  // c is a mesh cell: E in mesh order
            values[3 * a + k] = cellModulus_[c] * elements_[mesh_.cellShape()[c]].stiffness[25 * (3 * a + k)];
      },
      g, 3, 0);
  GF_CALL(VecRestoreArray(assembled, &g));
  GF_CALL(VecAXPY(diag, 1.0, assembled));
  Vec v = local.release();
  GF_CALL(DMRestoreLocalVector(dmU_, &v));
}

}  // namespace gradfric::fem
