#pragma once
// The explicit scheme's state per vertex, [u_x u_y u_z v_x v_y v_z] (fields "displacement" and
// "velocity" of the plate's DM), seen through named accessors instead of `6 * b + 3` arithmetic.
// The offsets are compile-time constants so that the hot loops keep a constant stride; PlateMesh
// checks them against the section's field offsets when it builds the mesh (checkStateLayout).
// A right-hand side F = dX/dt has the same layout: its displacement slots hold v, its velocity
// slots the force on the vertex, then (after M^-1) its acceleration.
#include "gradfric/core/petsc_call.hpp"

#include <petscvec.h>

namespace gradfric::fem {

struct StateLayout {
  static constexpr PetscInt kBlock = 6;         // values per vertex
  static constexpr PetscInt kDisplacement = 0;  // offset of field 0 in a vertex's block
  static constexpr PetscInt kVelocity = 3;      // offset of field 1
};

// A view of a state-layout array: owned blocks of a global vector (block b), or vertex offsets
// of a local vector (PlateMesh::cellStateOffsets, `At` accessors).
template <class Scalar>
class StateView {
public:
  explicit StateView(Scalar* data) : data_(data) {}
  Scalar* displacement(PetscInt block) const { return at(block, StateLayout::kDisplacement); }
  Scalar* velocity(PetscInt block) const { return at(block, StateLayout::kVelocity); }
  // In a right-hand side: the force (then the acceleration) of the block.
  Scalar* force(PetscInt block) const { return velocity(block); }
  Scalar* displacementAt(PetscInt offset) const { return data_ + offset + StateLayout::kDisplacement; }
  Scalar* velocityAt(PetscInt offset) const { return data_ + offset + StateLayout::kVelocity; }
  Scalar* forceAt(PetscInt offset) const { return velocityAt(offset); }
  Scalar* data() const { return data_; }

private:
  Scalar* at(PetscInt block, PetscInt field) const { return data_ + StateLayout::kBlock * block + field; }
  Scalar* data_;
};

// The array of a Vec held for the scope (VecGetArray[Read] ... VecRestoreArray[Read]) and viewed
// as a state.
class ReadState : public StateView<const PetscScalar> {
public:
  explicit ReadState(Vec v) : StateView(get(v)), vec_(v) {}
  ~ReadState() {
    const PetscScalar* a = data();
    VecRestoreArrayRead(vec_, &a);  // a destructor must not throw
  }
  ReadState(const ReadState&) = delete;
  ReadState& operator=(const ReadState&) = delete;

private:
  static const PetscScalar* get(Vec v) {
    const PetscScalar* a = nullptr;
    GF_CALL(VecGetArrayRead(v, &a));
    return a;
  }
  Vec vec_;
};

class WriteState : public StateView<PetscScalar> {
public:
  explicit WriteState(Vec v) : StateView(get(v)), vec_(v) {}
  ~WriteState() {
    PetscScalar* a = data();
    VecRestoreArray(vec_, &a);
  }
  WriteState(const WriteState&) = delete;
  WriteState& operator=(const WriteState&) = delete;

private:
  static PetscScalar* get(Vec v) {
    PetscScalar* a = nullptr;
    GF_CALL(VecGetArray(v, &a));
    return a;
  }
  Vec vec_;
};

}  // namespace gradfric::fem
