#include "gradfric/fem/bulk_viscosity.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/hex_element.hpp"

#include <algorithm>
#include <cmath>

namespace gradfric::fem {

std::array<std::array<double, 3>, 8> boxMeanShapeGradients(double hx, double hy, double hz) {
  std::array<std::array<double, 3>, 8> g{};
  for (int a = 0; a < 8; ++a) {
    const int i = a & 1, j = (a >> 1) & 1, k = (a >> 2) & 1;
    g[a] = {(2 * i - 1) / (4 * hx), (2 * j - 1) / (4 * hy), (2 * k - 1) / (4 * hz)};
  }
  return g;
}

double bulkViscousStress(double linear, double quadratic, double density, double dilatationalSpeed, double length,
                         double volumetricRate) {
  double stress = linear * density * dilatationalSpeed * length * volumetricRate;
  if (volumetricRate < 0) {  // compression only
    const double q = quadratic * length;
    stress += density * q * q * volumetricRate * std::fabs(volumetricRate);
  }
  return stress;
}

BulkViscosity::BulkViscosity(const PlateMesh& mesh, double youngsModulus, double poissonRatio, double density,
                             double linear, double quadratic, const Grading& grading)
    : mesh_(mesh),
      linear_(linear),
      quadratic_(quadratic),
      density_(density) {
  if (!active()) return;
  for (const std::array<double, 3>& h : mesh.shapes())
    shapes_.push_back({std::min({h[0], h[1], h[2]}), h[0] * h[1] * h[2], boxMeanShapeGradients(h[0], h[1], h[2])});
  const double plateLength = mesh.size().length;
  cellSpeed_.resize(mesh.localCells());
  for (PetscInt c = 0; c < mesh.localCells(); ++c) {
    const Lame lame =
        lameFromYoung(youngsModulus * grading.modulusFactor(mesh.cellCentres()[c][0] / plateLength), poissonRatio);
    cellSpeed_[c] = std::sqrt((lame.lambda + 2 * lame.mu) / density);
  }
  GF_CALL(DMCreateLocalVector(mesh.dm(), xLocal_.out()));
  GF_CALL(VecDuplicate(xLocal_, fLocal_.out()));
  GF_CALL(DMCreateGlobalVector(mesh.dm(), fGlobal_.out()));
}

// The cell's viscous force on its corners' velocity slots, f[corner a] -= w_a (three values a
// corner, 8 corners); returns the power of the cell.
double BulkViscosity::cellForce(PetscInt c, const PetscScalar* x, std::array<double, 24>* w) const {
  const PetscInt* o = mesh_.cellStateOffsets().data() + 8 * c;
  const Shape& shape = shapes_[mesh_.cellShape()[c]];
  double rate = 0;
  for (int a = 0; a < 8; ++a)
    for (int d = 0; d < 3; ++d) rate += x[o[a] + 3 + d] * shape.gradient[a][d];
  const double stress = bulkViscousStress(linear_, quadratic_, density_, cellSpeed_[c], shape.length, rate);
  for (int a = 0; a < 8; ++a)
    for (int d = 0; d < 3; ++d) (*w)[3 * a + d] = shape.volume * stress * shape.gradient[a][d];
  return shape.volume * stress * rate;
}

void BulkViscosity::addForce(Vec X, Vec F, ExactSum* energy, double dt) {
  if (!active()) return;
  GF_CALL(DMGlobalToLocal(mesh_.dm(), X, INSERT_VALUES, xLocal_));
  GF_CALL(VecZeroEntries(fLocal_));
  const PetscScalar* x = nullptr;
  PetscScalar* fl = nullptr;
  GF_CALL(VecGetArrayRead(xLocal_, &x));
  GF_CALL(VecGetArray(fLocal_, &fl));
  const std::vector<PetscInt>& off = mesh_.cellStateOffsets();
  std::array<double, 24> w;
  for (PetscInt c = 0; c < mesh_.localCells(); ++c) {
    energy->add(cellForce(c, x, &w) * dt);
    for (int a = 0; a < 8; ++a)
      for (int d = 0; d < 3; ++d) fl[off[8 * c + a] + 3 + d] -= w[3 * a + d];
  }
  GF_CALL(VecRestoreArray(fLocal_, &fl));
  GF_CALL(VecZeroEntries(fGlobal_));
  GF_CALL(DMLocalToGlobal(mesh_.dm(), fLocal_, ADD_VALUES, fGlobal_));
  PetscScalar* g = nullptr;  // the sums at the shared vertices in the global cell order
  GF_CALL(VecGetArray(fGlobal_, &g));
  mesh_.orderedAssembly().redo(
      3, [&](PetscInt c, double* values) {
        cellForce(c, x, &w);
        for (int i = 0; i < 24; ++i) values[i] = -w[i];  // f - w is f + (-w), bit for bit
      },
      g, 6, 3);
  GF_CALL(VecRestoreArray(fGlobal_, &g));
  GF_CALL(VecRestoreArrayRead(xLocal_, &x));
  GF_CALL(VecAXPY(F, 1.0, fGlobal_));  // only the force slots of fGlobal are non-zero
}

}  // namespace gradfric::fem
