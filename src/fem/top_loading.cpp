#include "gradfric/fem/top_loading.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/reproducible_sum.hpp"
#include "gradfric/fem/lumped_mass.hpp"
#include "gradfric/fem/state_view.hpp"

#include <cmath>

namespace gradfric::fem {

TopLoading::TopLoading(const PlateMesh& mesh, const PlateProperties& properties)
    : comm_(mesh.comm()), properties_(properties) {
  const Plate& plate = properties.plate();
  const double theta = plate.slidingAngle * M_PI / 180.0;
  velocityX_ = plate.velocity * std::cos(theta);
  velocityY_ = plate.velocity * std::sin(theta);
}

void TopLoading::addForce(const LayerContext& ctx, Vec X, Vec F, ContactSums& sums) {
  addPressure(ctx.pressure, F);
  const ReadState x(X);
  for (const TopNode& n : properties_.topNodes()) sums.topZ.add(n.load * x.displacement(n.block)[2]);
}

void TopLoading::addPressure(double p, Vec F) const {
  const WriteState f(F);
  for (const TopNode& n : properties_.topNodes()) f.force(n.block)[2] -= p * n.load;
}

void TopLoading::addDeadLoad(Vec F) const { addPressure(properties_.plate().pressure, F); }

void TopLoading::constrain(const LayerContext& ctx, Vec, Vec F, ContactSums& sums) {
  if (!ctx.sliding) return;
  const std::vector<double>& mass = ctx.mass->perBlock();
  const WriteState f(F);
  for (const TopNode& n : properties_.topNodes()) {
    double* a = f.force(n.block);
    sums.driveX.add(-(mass[n.block] * a[0]));
    sums.driveY.add(-(mass[n.block] * a[1]));
    a[0] = a[1] = 0.0;
  }
}

void TopLoading::startSliding(Vec X) const {
  const WriteState x(X);
  for (const TopNode& n : properties_.topNodes()) {
    x.velocity(n.block)[0] = velocityX_;
    x.velocity(n.block)[1] = velocityY_;
  }
}

double TopLoading::area() const {
  ExactSum a;
  for (const TopNode& n : properties_.topNodes()) a.add(n.load);
  return sumOverRanks(comm_, a);
}

std::string TopLoading::describe() const {
  return "pressure ramped then held on the top face, which slides at v, theta in step 2";
}

void TopLoading::writeProperties(PropertySink& sink) const {
  std::vector<PetscInt> blocks;
  std::vector<double> factor;
  for (const TopNode& n : properties_.topNodes()) {
    blocks.push_back(n.block);
    factor.push_back(properties_.plate().pressure * (n.load / n.area));
  }
  sink.nodeField("p", "Pa", "top pressure of the node at full load (its faces' pressure factors, area-weighted)",
                 blocks, factor);
}

}  // namespace gradfric::fem
