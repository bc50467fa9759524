#include "gradfric/fem/plate_model.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/reproducible_sum.hpp"
#include "gradfric/fem/log_events.hpp"
#include "gradfric/fem/state_view.hpp"
#include "gradfric/fem/term_registry.hpp"

namespace gradfric::fem {

namespace {

MeshSize meshSize(const FemParameters& q) { return {q.nx, q.ny, q.nz, q.plate.length, q.plate.thickness, q.edge}; }

ElasticSettings elasticSettings(const FemParameters& q) {
  return {q.plate.poissonRatio, q.stiffnessDamping, q.element, q.blockedKernel, q.energyAudit};
}

ContactSettings contactSettings(const FemParameters& q) {
  return {q.contactMethod == ContactMethod::Kinematic, PenaltyStiffness{q.kn, q.kt}, q.frictionLaw, q.slipLength,
          q.slipHealingOnly};
}

}  // namespace

// The layers, in the order their forces are added (docs/fem.md, "Adding a FEM term").
PlateModel::PlateModel(MPI_Comm comm, const FemParameters& params, const Grading& grading)
    : params_(params),
      grading_(grading),
      mesh_(comm, meshSize(params_), params_.partitioner),
      mass_(mesh_, params_.plate.density),
      properties_(mesh_, params_.plate, grading_, params_.surface, params_.surfaceRealisation),
      protocol_(params_) {
  const FemParameters& q = params_;
  elastic_ = add<ElasticOperator>(true, mesh_, properties_, elasticSettings(q));
  top_ = add<TopLoading>(true, mesh_, properties_);
  if (q.bulkLinear > 0 || q.bulkQuadratic > 0) add<BulkViscosity>(true, mesh_, properties_, q.bulkLinear, q.bulkQuadratic);
  for (const FemTerm& term : femTerms())  // the optional terms (term_registry.hpp), off ones not built
    if (term.wanted(q)) adopt(term.build({mesh_, mass_, properties_, q}), true);
  contact_ = add<ContactBoundary>(q.contact, properties_, comm, contactSettings(q));
  if (MassDamping::wanted(q)) damping_ = add<MassDamping>(true, q, mesh_.ownedBlocks());

  stableDt_ = fem::stableTimeStep(params_, grading_);
  dt_ = fem::chooseTimeStep(params_, grading_);
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

// The one right-hand side: each layer adds its force to the force slots of F (the first may set
// them), then F = [v ; M^-1 f - gamma v], then the layers' constraints on the accelerations.
void PlateModel::rhs(double t, Vec X, Vec F) {
  const LogEventScope timed(femLogEvents().rhs);
  LayerContext ctx;
  ctx.t = t;
  ctx.dt = dt_;
  ctx.sliding = protocol_.sliding();
  ctx.pressure = protocol_.pressureAt(t);
  ctx.damping = protocol_.massDamping();
  ctx.mass = &mass_;
  const bool firstSets = !layers_.empty() && layers_.front()->setsForce();
  if (!firstSets) {
    const WriteState f(F);
    for (PetscInt b = 0; b < mesh_.ownedBlocks(); ++b)
      for (int d = 0; d < 3; ++d) f.force(b)[d] = 0.0;
  }
  ContactSums sums;
  for (std::size_t i = 0; i < layers_.size(); ++i) {
    ctx.setForce = i == 0 && firstSets;
    layers_[i]->addForce(ctx, X, F, sums);
  }
  ctx.setForce = false;
  accelerate(ctx, X, F);
  for (Layer* layer : layers_) layer->constrain(ctx, X, F, sums);
  lastTotals_ = sums;
}

void PlateModel::accelerate(const LayerContext& ctx, Vec X, Vec F) {
  const std::vector<double>& inverseMass = mass_.inversePerBlock();
  const std::vector<double>& blockMass = mass_.perBlock();
  const SlidingDamping& damping = ctx.damping;
  double* energy = damping_ ? damping_->stepEnergy() : nullptr;
  const ReadState x(X);
  const WriteState f(F);
  for (std::size_t b = 0; b < inverseMass.size(); ++b) {
    const PetscScalar* v = x.velocity(b);
    PetscScalar* rate = f.displacement(b);
    PetscScalar* a = f.force(b);
    for (int d = 0; d < 3; ++d) {
      rate[d] = v[d];
      a[d] = a[d] * inverseMass[b] + damping.acceleration(v, d);
    }
    if (energy) energy[b] = damping.power(blockMass[b], v) * ctx.dt;
  }
}

void PlateModel::archive(StateArchive& a) {
  protocol_.archive(a);
  std::size_t terms = owned_.size();
  a.field("model.terms", terms);
  if (terms != owned_.size()) throw CheckpointMismatch("the checkpoint has another set of physics terms");
  for (auto& layer : owned_) layer->archive(a);
  a.field("model.lastTotals", lastTotals_);
}

void PlateModel::postStep() {
  for (Layer* layer : layers_) layer->postStep(dt_);
}

// The layers' exact shares summed over ranks at once, then the values already over ranks in the
// list's order (the stiffness audit's, minus the contact's work): the bits of the balance as before.
double PlateModel::dissipatedEnergy() const {
  ExactSum share;
  std::vector<double> overRanks;
  for (const Layer* layer : layers_) {
    const LayerWork w = layer->work();
    share += w.rankShare;
    if (w.hasOverRanks) overRanks.push_back(w.overRanks);
  }
  double e = sumOverRanks(comm(), share);
  for (double o : overRanks) e += o;
  return e;
}

bool PlateModel::startPeakDamping() {
  if (protocol_.peakDampingOn() || !protocol_.sliding()) return false;
  const bool any = protocol_.startPeakDamping();
  if (params_.peakStiffnessDamping > 0) elastic_->setStiffnessDamping(protocol_.stiffnessDamping());
  return any;
}

void PlateModel::startSliding(Vec X) {
  protocol_.setPhase(Phase::Sliding);
  top_->startSliding(X);
  contact_->resetSlipRecord();
  contact_->settleRememberedPressure();
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
