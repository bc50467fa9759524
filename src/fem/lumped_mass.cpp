#include "gradfric/fem/lumped_mass.hpp"

#include "gradfric/core/petsc_call.hpp"

namespace gradfric::fem {

LumpedMass::LumpedMass(const PlateMesh& mesh, double density) : comm_(mesh.comm()) {
  const double volume = mesh.hx() * mesh.hy() * mesh.hz();
  const double share = density * volume / 8.0;
  mass_ = mesh.sumOverCells(std::vector<double>(mesh.localCells(), share));
  inverse_.resize(mass_.size());
  for (std::size_t b = 0; b < mass_.size(); ++b) inverse_[b] = 1.0 / mass_[b];
}

double LumpedMass::total() const {
  double m = 0, sum = 0;
  for (double mb : mass_) m += mb;
  GF_CALL_MPI(MPI_Allreduce(&m, &sum, 1, MPI_DOUBLE, MPI_SUM, comm_));
  return sum;
}

double LumpedMass::kineticEnergy(Vec X) const {
  const PetscScalar* x = nullptr;
  GF_CALL(VecGetArrayRead(X, &x));
  double e = 0;
  for (std::size_t b = 0; b < mass_.size(); ++b)
    for (int d = 3; d < 6; ++d) e += 0.5 * mass_[b] * x[6 * b + d] * x[6 * b + d];
  GF_CALL(VecRestoreArrayRead(X, &x));
  double sum = 0;
  GF_CALL_MPI(MPI_Allreduce(&e, &sum, 1, MPI_DOUBLE, MPI_SUM, comm_));
  return sum;
}

}  // namespace gradfric::fem
