#include "gradfric/fem/lumped_mass.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/reproducible_sum.hpp"
#include "gradfric/fem/state_view.hpp"

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
  ExactSum e;
  {
    const ReadState x(X);
    for (std::size_t b = 0; b < mass_.size(); ++b) {
      const PetscScalar* v = x.velocity(b);
      for (int d = 0; d < 3; ++d) e.add(0.5 * mass_[b] * v[d] * v[d]);
    }
  }
  return sumOverRanks(comm_, e);
}

}  // namespace gradfric::fem
