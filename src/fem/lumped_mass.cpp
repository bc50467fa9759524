#include "gradfric/fem/lumped_mass.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/reproducible_sum.hpp"

namespace gradfric::fem {

LumpedMass::LumpedMass(const PlateMesh& mesh, double density) : comm_(mesh.comm()) {
  std::vector<double> share(mesh.localCells());  // each cell's mass on each of its corners
  for (PetscInt c = 0; c < mesh.localCells(); ++c) share[c] = density * mesh.cellVolume(c) / 8.0;
  mass_ = mesh.sumOverCells(share);
  inverse_.resize(mass_.size());
  for (std::size_t b = 0; b < mass_.size(); ++b) inverse_[b] = 1.0 / mass_[b];
}

double LumpedMass::total() const {
  ExactSum m;
  for (double mb : mass_) m.add(mb);
  return sumOverRanks(comm_, m);
}

double LumpedMass::kineticEnergy(Vec X) const {
  const PetscScalar* x = nullptr;
  GF_CALL(VecGetArrayRead(X, &x));
  ExactSum e;
  for (std::size_t b = 0; b < mass_.size(); ++b)
    for (int d = 3; d < 6; ++d) e.add(0.5 * mass_[b] * x[6 * b + d] * x[6 * b + d]);
  GF_CALL(VecRestoreArrayRead(X, &x));
  return sumOverRanks(comm_, e);
}

}  // namespace gradfric::fem
