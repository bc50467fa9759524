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
      density_(density),
      length_(std::min({mesh.hx(), mesh.hy(), mesh.hz()})),
      volume_(mesh.hx() * mesh.hy() * mesh.hz()),
      gradient_(boxMeanShapeGradients(mesh.hx(), mesh.hy(), mesh.hz())) {
  if (!active()) return;
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

double BulkViscosity::addForce(Vec X, Vec F) {
  if (!active()) return 0.0;
  GF_CALL(DMGlobalToLocal(mesh_.dm(), X, INSERT_VALUES, xLocal_));
  GF_CALL(VecZeroEntries(fLocal_));
  const PetscScalar* x = nullptr;
  PetscScalar* fl = nullptr;
  GF_CALL(VecGetArrayRead(xLocal_, &x));
  GF_CALL(VecGetArray(fLocal_, &fl));
  const std::vector<PetscInt>& off = mesh_.cellStateOffsets();
  double power = 0;
  for (PetscInt c = 0; c < mesh_.localCells(); ++c) {
    const PetscInt* o = off.data() + 8 * c;
    double rate = 0;
    for (int a = 0; a < 8; ++a)
      for (int d = 0; d < 3; ++d) rate += x[o[a] + 3 + d] * gradient_[a][d];
    const double stress = bulkViscousStress(linear_, quadratic_, density_, cellSpeed_[c], length_, rate);
    if (stress == 0.0) continue;
    power += volume_ * stress * rate;
    for (int a = 0; a < 8; ++a)
      for (int d = 0; d < 3; ++d) fl[o[a] + 3 + d] -= volume_ * stress * gradient_[a][d];
  }
  GF_CALL(VecRestoreArray(fLocal_, &fl));
  GF_CALL(VecRestoreArrayRead(xLocal_, &x));
  GF_CALL(VecZeroEntries(fGlobal_));
  GF_CALL(DMLocalToGlobal(mesh_.dm(), fLocal_, ADD_VALUES, fGlobal_));
  GF_CALL(VecAXPY(F, 1.0, fGlobal_));  // only the force slots of fGlobal are non-zero
  return power;
}

}  // namespace gradfric::fem
