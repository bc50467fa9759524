#include "gradfric/fem/bulk_viscosity.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/hex_element.hpp"
#include "gradfric/fem/state_view.hpp"

#include <cstdio>

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

BulkViscosity::BulkViscosity(const PlateMesh& mesh, const PlateProperties& properties, double linear,
                             double quadratic)
    : mesh_(mesh),
      linear_(linear),
      quadratic_(quadratic),
      density_(properties.plate().density) {
  for (const std::array<double, 3>& h : mesh.shapes())
    shapes_.push_back({std::min({h[0], h[1], h[2]}), h[0] * h[1] * h[2], boxMeanShapeGradients(h[0], h[1], h[2])});
  cellSpeed_.resize(mesh.localCells());
  for (PetscInt c = 0; c < mesh.localCells(); ++c) {
    const Lame lame = lameFromYoung(properties.cellModulus()[c], properties.plate().poissonRatio);
    cellSpeed_[c] = std::sqrt((lame.lambda + 2 * lame.mu) / density_);
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
  const StateView<const PetscScalar> state(x);
  double rate = 0;
  for (int a = 0; a < 8; ++a)
    for (int d = 0; d < 3; ++d) rate += state.velocityAt(o[a])[d] * shape.gradient[a][d];
  const double stress = bulkViscousStress(linear_, quadratic_, density_, cellSpeed_[c], shape.length, rate);
  for (int a = 0; a < 8; ++a)
    for (int d = 0; d < 3; ++d) (*w)[3 * a + d] = shape.volume * stress * shape.gradient[a][d];
  return shape.volume * stress * rate;
}

void BulkViscosity::addForce(const LayerContext& ctx, Vec X, Vec F, ContactSums&) {
  step_ = ExactSum();
  GF_CALL(DMGlobalToLocal(mesh_.dm(), X, INSERT_VALUES, xLocal_));
  GF_CALL(VecZeroEntries(fLocal_));
  const ReadState x(xLocal_);
  {
    const WriteState fl(fLocal_);
    const std::vector<PetscInt>& off = mesh_.cellStateOffsets();
    std::array<double, 24> w;
    for (PetscInt c = 0; c < mesh_.localCells(); ++c) {
      step_.add(cellForce(c, x.data(), &w) * ctx.dt);
      for (int a = 0; a < 8; ++a)
        for (int d = 0; d < 3; ++d) fl.forceAt(off[8 * c + a])[d] -= w[3 * a + d];
    }
  }
  GF_CALL(VecZeroEntries(fGlobal_));
  GF_CALL(DMLocalToGlobal(mesh_.dm(), fLocal_, ADD_VALUES, fGlobal_));
  {
    const WriteState g(fGlobal_);  // the sums at the shared vertices in the global cell order
    std::array<double, 24> w;
    mesh_.orderedAssembly().redo(
        3, [&](PetscInt c, double* values) {
          cellForce(c, x.data(), &w);
          for (int i = 0; i < 24; ++i) values[i] = -w[i];  // f - w is f + (-w), bit for bit
        },
        g.data(), StateLayout::kBlock, StateLayout::kVelocity);
  }
  GF_CALL(VecAXPY(F, 1.0, fGlobal_));  // only the force slots of fGlobal are non-zero
}

void BulkViscosity::archive(StateArchive& a) {
  a.field("bulk_viscosity.step", step_);
  a.field("bulk_viscosity.work", work_);
}

LayerWork BulkViscosity::work() const {
  LayerWork w;
  w.rankShare = work_;
  return w;
}

std::string BulkViscosity::describe() const {
  char text[160];
  std::snprintf(text, sizeof text, "b1 %.3g, b2 %.3g (Abaqus/Explicit's form, on the volumetric strain rate)", linear_,
                quadratic_);
  return text;
}

void BulkViscosity::writeProperties(PropertySink& sink) const {
  sink.cellField("c_d", "m/s", "dilatational wave speed of the cell (bulk viscosity)", cellSpeed_);
}

}  // namespace gradfric::fem
