#pragma once
// Nodal sums of cell contributions in one order fixed by the mesh, whatever the partition.
//
// An assembled force is, at every vertex, a sum over the cells around it. A rank sums its cells'
// contributions in its cell order, which is the global cell order (checked here); but at a vertex
// whose cells lie on several ranks, PETSc's local-to-global ADD adds the ranks' partial sums, whose
// grouping changes with the partition, and so do the last bits of the force. The sliding phase
// amplifies such a difference to percents (docs/fem.md, "Rank independence").
//
// So at the shared vertices the owner redoes the sum: each cell touching a shared vertex writes
// its contribution for corner a into that vertex's slot a (no sum: one writer per slot), the slots
// travel to the owner (adding zeros, exactly), and the owner adds them in the cells' global order,
// as one rank holding every cell would. Off the shared vertices nothing changes, so a serial run
// pays nothing.
#include <petscdmplex.h>
#include <petscsf.h>

#include <array>
#include <functional>
#include <map>
#include <vector>

namespace gradfric::fem {

class OrderedAssembly {
public:
  // cellVertices: 8 per local cell in element order (a = i + 2 j + 4 k), vertex point minus
  // vStart; cellGlobal: each local cell's index in the serial mesh (x fastest, from its mapped
  // centre); blockOfVertex: the owned block of a vertex (minus vStart) or -1. Throws if this
  // rank's cells are not in global order (the sums off the shared vertices rely on it).
  OrderedAssembly(DM dm, int nx, int ny, PetscInt vStart, PetscInt vEnd, const std::vector<PetscInt>& cellVertices,
                  const std::vector<long>& cellGlobal, const std::vector<PetscInt>& blockOfVertex);
  ~OrderedAssembly();
  OrderedAssembly(const OrderedAssembly&) = delete;
  OrderedAssembly& operator=(const OrderedAssembly&) = delete;

  bool sharesVertices() const { return sharesAny_; }  // on some rank a vertex has cells on two ranks
  // The local cells with a corner on a shared vertex, and for each of their 8 corners where its
  // `width` values go in a slot buffer of slotCount(width) zeros (unshared corners: a scratch slot).
  const std::vector<PetscInt>& boundaryCells() const { return boundaryCells_; }
  std::vector<PetscInt> cornerSlots(int width) const;
  std::size_t slotCount(int width) const { return (8 * shared_ + 1) * static_cast<std::size_t>(width); }

  // Collective. Sends the slots to the owners and sets, for every owned shared vertex and d <
  // width, global[stride * block + offset + d] to the sum of its slots in the cells' global order.
  void finish(int width, std::vector<double>& slots, double* global, int stride, int offset) const;
  // Collective; nothing when no vertex is shared. The same from each boundary cell's own values:
  // cornerValues(cell, values) sets values[width * a + d] for its corners a = 0..7.
  void redo(int width, const std::function<void(PetscInt, double*)>& cornerValues, double* global, int stride,
            int offset) const;

private:
  PetscSF slotForest(int width) const;

  MPI_Comm comm_;
  bool sharesAny_ = false;
  std::size_t shared_ = 0, ownedShared_ = 0;  // shared vertices: the owned ones first, then the ghosts
  std::vector<PetscInt> ownedSharedBlock_;
  std::vector<int> ghostOwner_;
  std::vector<PetscInt> ghostRemoteSlot_;  // the ghost's index among its owner's shared vertices
  std::vector<PetscInt> boundaryCells_;
  std::vector<PetscInt> boundaryCorner_;  // 8 per boundary cell: shared vertex index or -1
  std::array<int, 8> cornerOrder_{};      // corners in the global order of the cells they stand for
  mutable std::map<int, PetscSF> forests_;
};

}  // namespace gradfric::fem
