#include "gradfric/fem/plate_model.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/reproducible_sum.hpp"
#include "gradfric/fem/log_events.hpp"
#include "gradfric/fem/mesh_sites.hpp"

#include <cmath>

namespace gradfric::fem {

namespace {

FemParameters resolved(FemParameters q) {
  q.resolveDerived();
  return q;
}

MeshSize meshSize(const FemParameters& q) { return {q.nx, q.ny, q.nz, q.plate.length, q.plate.thickness, q.edge}; }

// A static pressure field (-field_p_*) as the top load's shape p(x, y)/p; empty when uniform. Used
// while the top loading is built only.
std::function<double(double, double)> pressureShapeOf(const Grading& grading, const FemParameters& q) {
  if (!grading.fields || !grading.fields->pressure) return {};
  const double length = q.plate.length;
  return [sampler = meshSampler(grading, q), length](double x, double y) {
    return sampler.pressure(x / length, y / length);
  };
}

}  // namespace

PlateModel::PlateModel(MPI_Comm comm, const FemParameters& params, const Grading& grading)
    : params_(resolved(params)),
      grading_(grading),
      mesh_(comm, meshSize(params_), params_.partitioner),
      mass_(mesh_, params_.plate.density),
      elastic_(mesh_, params_.plate.youngsModulus, params_.plate.poissonRatio, params_.stiffnessDamping, grading,
                params_.element, params_.blockedKernel),
      bulk_(mesh_, params_.plate.youngsModulus, params_.plate.poissonRatio, params_.plate.density, params_.bulkLinear,
            params_.bulkQuadratic, grading),
      contact_(mesh_, PenaltyStiffness{params_.kn, params_.kt}, params_.plate.muStatic, params_.plate.muKinetic,
               params_.frictionLaw, grading, params_.slipLength, params_.slipHealingOnly),
      top_(mesh_, params_.plate.pressure, params_.rampTime, params_.plate.velocity, params_.plate.slidingAngle,
           pressureShapeOf(grading, params_)) {
  stableDt_ = fem::stableTimeStep(params_, grading_);
  dt_ = fem::chooseTimeStep(params_, grading_);
  dampingStep_.assign(mesh_.ownedBlocks(), 0.0);
  dampingWork_.assign(mesh_.ownedBlocks(), 0.0);
  if (dt_ > stableDt_)  // only with -fem_dt_check false
    GF_CALL(PetscPrintf(comm,
                        "WARNING: -fem_dt_check false (testing only): dt %.4g s is above the stable step %.4g s; the "
                        "blow-up monitor will stop the run\n",
                        dt_, stableDt_));
}

Vec PlateModel::createState() const {
  Vec X = nullptr;
  GF_CALL(DMCreateGlobalVector(mesh_.dm(), &X));
  GF_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(X), "state"));
  GF_CALL(VecZeroEntries(X));
  return X;
}

// The one right-hand side: each layer adds its force to the force slots of F, then
// F = [v ; M^-1 f - gamma v], and the slider's constraint on the top.
void PlateModel::rhs(double t, Vec X, Vec F) {
  const FemLogEvents& events = femLogEvents();
  const LogEventScope timed(events.rhs);
  const bool sliding = phase_ == Phase::Sliding;
  elastic_.setForce(X, F);
  top_.addPressure(t, sliding, F);
  bulkStep_ = ExactSum();
  bulk_.addForce(X, F, &bulkStep_, dt_);
  if (params_.energyAudit && elastic_.stiffnessDamping() > 0) stiffnessPower_ = stiffnessDampingPower(X);
  const SlidingDamping damping = massDamping();
  ContactSums totals;
  if (params_.contact) {
    const LogEventScope timedContact(events.contact);
    if (params_.contactMethod == ContactMethod::Kinematic)
      totals = contact_.addKinematicForce(X, F, mass_.perBlock(), damping, dt_);
    else
      totals = contact_.addForce(X, F, dt_);
  }
  const std::vector<double>& inverseMass = mass_.inversePerBlock();
  const std::vector<double>& blockMass = mass_.perBlock();
  const PetscScalar* x = nullptr;
  PetscScalar* f = nullptr;
  GF_CALL(VecGetArrayRead(X, &x));
  GF_CALL(VecGetArray(F, &f));
  for (std::size_t b = 0; b < inverseMass.size(); ++b) {
    PetscScalar* fb = f + 6 * b;
    const PetscScalar* xb = x + 6 * b;
    for (int d = 0; d < 3; ++d) {
      fb[d] = xb[3 + d];
      fb[3 + d] = fb[3 + d] * inverseMass[b] + damping.acceleration(xb + 3, d);
    }
    dampingStep_[b] = damping.power(blockMass[b], xb + 3) * dt_;
  }
  GF_CALL(VecRestoreArray(F, &f));
  GF_CALL(VecRestoreArrayRead(X, &x));
  totals.topZ = top_.areaWeightedLift(X);
  if (sliding) top_.constrainTangential(mass_.perBlock(), F, &totals.driveX, &totals.driveY);
  lastTotals_ = totals;
}

void PlateModel::commitContact() {
  contact_.commit();
  for (std::size_t b = 0; b < dampingWork_.size(); ++b)  // the rhs of the step saw the mid-step velocities
    dampingWork_[b] += dampingStep_[b];
  if (bulk_.active()) bulkWork_ += bulkStep_;
  stiffnessWork_ += stiffnessPower_ * dt_;
}

double PlateModel::dissipatedEnergy() const {
  ExactSum damping = bulkWork_;
  for (double w : dampingWork_) damping.add(w);
  return sumOverRanks(comm(), damping) + stiffnessWork_ - contact_.work();
}

// beta v . K v = 2 beta x (the elastic energy of the velocity field taken as a displacement).
double PlateModel::stiffnessDampingPower(Vec X) {
  if (!velocityAsDisplacement_) GF_CALL(VecDuplicate(X, velocityAsDisplacement_.out()));
  const PetscScalar* x = nullptr;
  PetscScalar* w = nullptr;
  PetscInt n = 0;
  GF_CALL(VecGetLocalSize(X, &n));
  GF_CALL(VecGetArrayRead(X, &x));
  GF_CALL(VecGetArray(velocityAsDisplacement_, &w));
  for (PetscInt b = 0; b < n; b += 6)
    for (int d = 0; d < 3; ++d) {
      w[b + d] = x[b + 3 + d];
      w[b + 3 + d] = 0;
    }
  GF_CALL(VecRestoreArray(velocityAsDisplacement_, &w));
  GF_CALL(VecRestoreArrayRead(X, &x));
  return 2.0 * elastic_.stiffnessDamping() * elastic_.energy(velocityAsDisplacement_);
}

SlidingDamping PlateModel::massDamping() const {
  SlidingDamping d;
  if (phase_ != Phase::Sliding) {
    d.lab = params_.settleDamping;
    return d;
  }
  d.lab = params_.slideDamping;
  if (peakDampingOn_) {
    const double theta = params_.plate.angleRadians();
    d.slider = params_.peakDamping;
    d.sliderVelocity[0] = params_.plate.velocity * std::cos(theta);
    d.sliderVelocity[1] = params_.plate.velocity * std::sin(theta);
  }
  return d;
}

bool PlateModel::startPeakDamping() {
  if (peakDampingOn_ || phase_ != Phase::Sliding) return false;
  peakDampingOn_ = true;
  if (params_.peakStiffnessDamping > 0) elastic_.setStiffnessDamping(params_.stiffnessDamping + params_.peakStiffnessDamping);
  return params_.peakDamping > 0 || params_.peakStiffnessDamping > 0;
}

void PlateModel::startSliding(Vec X) {
  phase_ = Phase::Sliding;
  top_.startSliding(X);
  contact_.resetSlipRecord();
}

ContactTotals PlateModel::contactTotals() const {
  const ContactSums& l = lastTotals_;
  // One reduction per step (a synchronisation point less on a busy machine), exact sums so that
  // the totals have the same bits on any number of ranks; the node counts travel with them.
  ExactSum s[11] = {l.fx, l.fy, l.fn, l.topZ, l.driveX, l.driveY};
  const long long counts[5] = {l.stick, l.slip, l.open, l.everSlipped, l.nodes};
  for (int i = 0; i < 5; ++i) s[6 + i].add(static_cast<double>(counts[i]));
  allreduceExact(comm(), s, 11);
  double sum[11];
  for (int i = 0; i < 11; ++i) sum[i] = s[i].value();
  long long csum[5];
  for (int i = 0; i < 5; ++i) csum[i] = static_cast<long long>(sum[6 + i]);
  ContactTotals t;
  t.fx = sum[0];
  t.fy = sum[1];
  t.fn = sum[2];
  t.topZ = sum[3];
  t.driveX = sum[4];
  t.driveY = sum[5];
  t.stick = csum[0];
  t.slip = csum[1];
  t.open = csum[2];
  t.everSlipped = csum[3];
  t.nodes = csum[4];
  return t;
}

}  // namespace gradfric::fem
