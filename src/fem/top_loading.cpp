#include "gradfric/fem/top_loading.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/reproducible_sum.hpp"

#include <algorithm>
#include <cmath>

namespace gradfric::fem {

TopLoading::TopLoading(const PlateMesh& mesh, double pressure, double rampTime, double velocity, double angleDegrees,
                       const std::function<double(double, double)>& pressureShape)
    : comm_(mesh.comm()), pressure_(pressure), rampTime_(rampTime) {
  const double theta = angleDegrees * M_PI / 180.0;
  velocityX_ = velocity * std::cos(theta);
  velocityY_ = velocity * std::sin(theta);
  const std::vector<double> area = mesh.sumOverFaces(FaceSet::Top, pressureShape);
  for (const OwnedVertex& v : mesh.ownedVertices())
    if (area[v.block] > 0) nodes_.push_back({v.block, area[v.block]});
}

double TopLoading::pressureAt(double t, bool sliding) const {
  if (sliding || rampTime_ <= 0) return pressure_;
  return pressure_ * std::min(1.0, t / rampTime_);
}

void TopLoading::addPressure(double t, bool sliding, Vec F) const {
  const double p = pressureAt(t, sliding);
  PetscScalar* f = nullptr;
  GF_CALL(VecGetArray(F, &f));
  for (const Node& n : nodes_) f[6 * n.block + 5] -= p * n.area;
  GF_CALL(VecRestoreArray(F, &f));
}

void TopLoading::startSliding(Vec X) const {
  PetscScalar* x = nullptr;
  GF_CALL(VecGetArray(X, &x));
  for (const Node& n : nodes_) {
    x[6 * n.block + 3] = velocityX_;
    x[6 * n.block + 4] = velocityY_;
  }
  GF_CALL(VecRestoreArray(X, &x));
}

void TopLoading::constrainTangential(const std::vector<double>& mass, Vec F, ExactSum* driveX, ExactSum* driveY) const {
  PetscScalar* f = nullptr;
  GF_CALL(VecGetArray(F, &f));
  for (const Node& n : nodes_) {
    driveX->add(-(mass[n.block] * f[6 * n.block + 3]));
    driveY->add(-(mass[n.block] * f[6 * n.block + 4]));
    f[6 * n.block + 3] = f[6 * n.block + 4] = 0.0;
  }
  GF_CALL(VecRestoreArray(F, &f));
}

ExactSum TopLoading::areaWeightedLift(Vec X) const {
  const PetscScalar* x = nullptr;
  GF_CALL(VecGetArrayRead(X, &x));
  ExactSum z;
  for (const Node& n : nodes_) z.add(n.area * x[6 * n.block + 2]);
  GF_CALL(VecRestoreArrayRead(X, &x));
  return z;
}

double TopLoading::area() const {
  ExactSum a;
  for (const Node& n : nodes_) a.add(n.area);
  return sumOverRanks(comm_, a);
}

}  // namespace gradfric::fem
