#include "gradfric/fem/ordered_assembly.hpp"

#include "gradfric/core/petsc_call.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace gradfric::fem {

OrderedAssembly::OrderedAssembly(DM dm, int nx, int ny, PetscInt vStart, PetscInt vEnd,
                                 const std::vector<PetscInt>& cellVertices, const std::vector<long>& cellGlobal,
                                 const std::vector<PetscInt>& blockOfVertex)
    : comm_(PetscObjectComm(reinterpret_cast<PetscObject>(dm))) {
  // The global cell index, x fastest: the order of the serial mesh, kept by the distribution.
  const std::size_t cells = cellGlobal.size();
  long previous = -1;
  for (const long key : cellGlobal) {
    if (key <= previous)
      throw std::logic_error("plate mesh: this rank's cells are not in the global cell order, so the assembled "
                             "forces would depend on the partition");
    previous = key;
  }
  // The cell at corner a of a vertex sits at offset -(i + j nx + k nx ny): the larger the offset,
  // the earlier the cell.
  const auto offset = [&](int a) { return (a & 1) + ((a >> 1) & 1) * nx + ((a >> 2) & 1) * static_cast<long>(nx) * ny; };
  std::iota(cornerOrder_.begin(), cornerOrder_.end(), 0);
  std::sort(cornerOrder_.begin(), cornerOrder_.end(), [&](int a, int b) { return offset(a) > offset(b); });

  PetscSF points = nullptr;
  GF_CALL(DMGetPointSF(dm, &points));
  PetscInt roots = 0, leaves = 0;
  const PetscInt* local = nullptr;
  const PetscSFNode* remote = nullptr;
  GF_CALL(PetscSFGetGraph(points, &roots, &leaves, &local, &remote));
  // Whether any rank shares a vertex, agreed by every rank whatever it found.
  const auto agree = [&] {
    int mine = shared_ > 0, any = 0;
    GF_CALL_MPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, comm_));
    sharesAny_ = any != 0;
  };
  if (roots < 0) {  // no graph: a serial mesh
    agree();
    return;
  }
  const PetscInt* degree = nullptr;
  GF_CALL(PetscSFComputeDegreeBegin(points, &degree));
  GF_CALL(PetscSFComputeDegreeEnd(points, &degree));
  std::vector<int> leafOwner(roots, -1);
  for (PetscInt l = 0; l < leaves; ++l) leafOwner[local ? local[l] : l] = static_cast<int>(remote[l].rank);

  std::vector<PetscInt> sharedIndex(vEnd - vStart, -1);
  std::vector<PetscInt> rootSlot(roots, -1), leafSlot(roots, -1);
  for (PetscInt v = vStart; v < vEnd; ++v)
    if (leafOwner[v] < 0 && degree[v] > 0) {
      sharedIndex[v - vStart] = static_cast<PetscInt>(ownedShared_);
      rootSlot[v] = static_cast<PetscInt>(ownedShared_++);
      ownedSharedBlock_.push_back(blockOfVertex[v - vStart]);
    }
  GF_CALL(PetscSFBcastBegin(points, MPIU_INT, rootSlot.data(), leafSlot.data(), MPI_REPLACE));
  GF_CALL(PetscSFBcastEnd(points, MPIU_INT, rootSlot.data(), leafSlot.data(), MPI_REPLACE));
  shared_ = ownedShared_;
  for (PetscInt v = vStart; v < vEnd; ++v)
    if (leafOwner[v] >= 0) {
      sharedIndex[v - vStart] = static_cast<PetscInt>(shared_++);
      ghostOwner_.push_back(leafOwner[v]);
      ghostRemoteSlot_.push_back(leafSlot[v]);
    }
  for (std::size_t c = 0; c < cells; ++c) {
    bool touches = false;
    for (int a = 0; a < 8; ++a) touches = touches || sharedIndex[cellVertices[8 * c + a]] >= 0;
    if (!touches) continue;
    boundaryCells_.push_back(static_cast<PetscInt>(c));
    for (int a = 0; a < 8; ++a) boundaryCorner_.push_back(sharedIndex[cellVertices[8 * c + a]]);
  }
  agree();
}

OrderedAssembly::~OrderedAssembly() {
  for (auto& [width, forest] : forests_) PetscSFDestroy(&forest);
}

std::vector<PetscInt> OrderedAssembly::cornerSlots(int width) const {
  std::vector<PetscInt> slots(boundaryCorner_.size());
  const PetscInt scratch = static_cast<PetscInt>(8 * shared_ * width);
  for (std::size_t i = 0; i < slots.size(); ++i) {
    const PetscInt vertex = boundaryCorner_[i];
    slots[i] = vertex < 0 ? scratch : (8 * vertex + static_cast<PetscInt>(i % 8)) * width;
  }
  return slots;
}

// The owners' slots are the roots, the ghosts' slots the leaves; `width` values a corner.
PetscSF OrderedAssembly::slotForest(int width) const {
  auto found = forests_.find(width);
  if (found != forests_.end()) return found->second;
  const PetscInt perVertex = 8 * width;
  std::vector<PetscInt> leafIndex;
  std::vector<PetscSFNode> rootOf;
  for (std::size_t g = 0; g < ghostOwner_.size(); ++g)
    for (PetscInt k = 0; k < perVertex; ++k) {
      leafIndex.push_back(static_cast<PetscInt>(ownedShared_ + g) * perVertex + k);
      rootOf.push_back(PetscSFNode{ghostOwner_[g], ghostRemoteSlot_[g] * perVertex + k});
    }
  PetscSF forest = nullptr;
  GF_CALL(PetscSFCreate(comm_, &forest));
  GF_CALL(PetscSFSetGraph(forest, static_cast<PetscInt>(ownedShared_) * perVertex,
                          static_cast<PetscInt>(leafIndex.size()), leafIndex.data(), PETSC_COPY_VALUES, rootOf.data(),
                          PETSC_COPY_VALUES));
  GF_CALL(PetscSFSetUp(forest));
  forests_[width] = forest;
  return forest;
}

void OrderedAssembly::finish(int width, std::vector<double>& slots, double* global, int stride, int offset) const {
  PetscSF forest = slotForest(width);
  // Each slot has one writer over all ranks: the sum adds zeros to it, which is exact.
  GF_CALL(PetscSFReduceBegin(forest, MPIU_SCALAR, slots.data(), slots.data(), MPI_SUM));
  GF_CALL(PetscSFReduceEnd(forest, MPIU_SCALAR, slots.data(), slots.data(), MPI_SUM));
  for (std::size_t s = 0; s < ownedShared_; ++s)
    for (int d = 0; d < width; ++d) {
      double sum = 0.0;  // the first addend lands on +0 as in the cell loop, and missing cells add +0
      for (int a : cornerOrder_) sum += slots[(8 * s + a) * width + d];
      global[stride * ownedSharedBlock_[s] + offset + d] = sum;
    }
}

void OrderedAssembly::redo(int width, const std::function<void(PetscInt, double*)>& cornerValues, double* global,
                           int stride, int offset) const {
  if (!sharesAny_) return;
  std::vector<double> slots(slotCount(width), 0.0), values(8 * width);
  const std::vector<PetscInt> corner = cornerSlots(width);
  for (std::size_t i = 0; i < boundaryCells_.size(); ++i) {
    cornerValues(boundaryCells_[i], values.data());
    for (int a = 0; a < 8; ++a)
      for (int d = 0; d < width; ++d) slots[corner[8 * i + a] + d] += values[width * a + d];
  }
  finish(width, slots, global, stride, offset);
}

}  // namespace gradfric::fem
