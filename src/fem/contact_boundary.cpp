#include "gradfric/fem/contact_boundary.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/core/gather.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/reproducible_sum.hpp"
#include "gradfric/fem/log_events.hpp"
#include "gradfric/fem/lumped_mass.hpp"
#include "gradfric/fem/state_view.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace gradfric::fem {

ContactBoundary::ContactBoundary(const PlateProperties& properties, MPI_Comm comm, const ContactSettings& settings)
    : comm_(comm), settings_(settings), stiffness_(settings.stiffness), randomSurface_(properties.surface().dispersed()) {
  FrictionSites sites;
  sites.layout = SiteLayout::PerSite;
  for (const BottomNode& b : properties.bottomNodes()) {
    nodes_.push_back(Node{b.block, b.x, b.y, b.area});
    sites.staticStrength.push_back(b.muStatic);
    sites.kineticStrength.push_back(b.muKinetic);
  }
  sites.columns = static_cast<int>(nodes_.size());
  law_ = makeContactLaw(settings.law, std::move(sites), nodes_.size(), settings.memoryLength, settings.healingOnly);
}

void ContactBoundary::addForce(const LayerContext& ctx, Vec X, Vec F, ContactSums& sums) {
  const LogEventScope timed(femLogEvents().contact);
  if (settings_.kinematic)
    addKinematicForce(X, F, ctx.mass->perBlock(), ctx.damping, ctx.dt, sums);
  else
    addPenaltyForce(X, F, ctx.dt, sums);
}

void ContactBoundary::addPenaltyForce(Vec X, Vec F, double dt, ContactSums& totals) {
  const ReadState x(X);
  const WriteState f(F);
  NormalStressMemory& memory = law_.normalStress;
  law_.visitStrength([&](auto& law) {
    const bool state = law.hasState();
    for (std::size_t site = 0; site < nodes_.size(); ++site) {
      Node& n = nodes_[site];
      const int i = static_cast<int>(site);
      const PetscScalar* u = x.displacement(n.block);
      const PetscScalar* v = x.velocity(n.block);
      const bool wasSlipping = n.state == ContactState::Slip;
      const double slip = wasSlipping && (state || memory.active()) ? tangentialStep(n, u) : 0.0;
      const ContactTraction r = penaltyContact(stiffness_, law, i, u[2], u[0], u[1], n.anchorX, n.anchorY, v[0], v[1],
                                               wasSlipping, slip, dt, memory, memory.rememberedAt(i, 0.0));
      if (r.state == ContactState::Open) law.keepOpen(i);
      memory.setPending(i, r.frictionPressure);
      n.pendingX = r.anchorX;
      n.pendingY = r.anchorY;
      n.pendingState = r.state;
      n.pressure = r.pressure;
      n.tx = r.tx;
      n.ty = r.ty;
      applyNodeForce(n, u, f.force(n.block), n.area * r.tx, n.area * r.ty, n.area * r.pressure, totals);
    }
  });
  totals.nodes += static_cast<long long>(nodes_.size());
}

void ContactBoundary::addKinematicForce(Vec X, Vec F, const std::vector<double>& mass, const SlidingDamping& damping,
                                        double dt, ContactSums& totals) {
  const ReadState x(X);
  const WriteState f(F);
  NormalStressMemory& memory = law_.normalStress;
  law_.visitStrength([&](auto& law) {
    const bool state = law.hasState();
    for (std::size_t site = 0; site < nodes_.size(); ++site) {
      Node& n = nodes_[site];
      const int i = static_cast<int>(site);
      const PetscScalar* u = x.displacement(n.block);
      const PetscScalar* xv = x.velocity(n.block);
      PetscScalar* fb = f.force(n.block);
      const double m = mass[n.block];
      const double v[3] = {xv[0], xv[1], xv[2]};
      const double aFree[3] = {fb[0] / m + damping.acceleration(v, 0), fb[1] / m + damping.acceleration(v, 1),
                               fb[2] / m + damping.acceleration(v, 2)};
      const double slip = state || memory.active() ? tangentialStep(n, u) : 0.0;
      const KinematicContactForce r =
          kinematicContact(law, i, m, dt, u[2], v, aFree, slip, memory, memory.rememberedAt(i, 0.0) * n.area);
      if (r.state == ContactState::Open) law.keepOpen(i);
      memory.setPending(i, r.frictionForce / n.area);
      n.pendingState = r.state;
      n.pressure = r.fn / n.area;
      n.tx = r.fx / n.area;
      n.ty = r.fy / n.area;
      applyNodeForce(n, u, fb, r.fx, r.fy, r.fn, totals);
    }
  });
  totals.nodes += static_cast<long long>(nodes_.size());
}

// Both contact methods end the same way: the node's force is kept for the work of the step, added
// to its block's force slots and counted (n.pendingState is set by the caller).
void ContactBoundary::applyNodeForce(Node& n, const PetscScalar* u, PetscScalar* force, double fx, double fy,
                                     double fz, ContactSums& totals) {
  n.pendingForce[0] = fx;
  n.pendingForce[1] = fy;
  n.pendingForce[2] = fz;
  for (int d = 0; d < 3; ++d) n.pendingU[d] = u[d];
  force[0] += fx;
  force[1] += fy;
  force[2] += fz;
  totals.fx.add(fx);
  totals.fy.add(fy);
  totals.fn.add(fz);
  if (n.pendingState == ContactState::Stick) ++totals.stick;
  else if (n.pendingState == ContactState::Slip) ++totals.slip;
  else ++totals.open;
  if (n.everSlipped || n.pendingState != ContactState::Stick) ++totals.everSlipped;
}

// The node's tangential displacement since the last commit: its slip over the step when it slides.
double ContactBoundary::tangentialStep(const Node& n, const PetscScalar* u) {
  return std::hypot(u[0] - n.u[0], u[1] - n.u[1]);
}

double ContactBoundary::committedStrength(int site) const {
  double strength = 0;
  law_.visitStrength([&](const auto& law) { strength = law.committedStrength(site); });
  return strength;
}

double ContactBoundary::contactWork() const {
  ExactSum total;  // the nodes' own sums, added exactly: the same bits on any number of ranks
  for (const Node& n : nodes_) total.add(n.work);
  return sumOverRanks(comm_, total);
}

void ContactBoundary::archive(StateArchive& a) {
  std::size_t count = nodes_.size();
  a.field("contact.nodes.count", count);
  if (count != nodes_.size()) throw CheckpointMismatch("the checkpoint has another number of contact nodes");
  a.fixedField("contact.nodes", nodes_);
  law_.archive(a);
  a.field("contact.lastStepSlip", lastStepSlip_);
  std::vector<double> record;  // (time, running maximum) pairs, flat
  for (const auto& [t, slip] : slipRecord_) record.insert(record.end(), {t, slip});
  a.field("contact.slipRecord", record);
  slipRecord_.clear();
  for (std::size_t i = 0; i + 1 < record.size(); i += 2) slipRecord_.emplace_back(record[i], record[i + 1]);
  std::vector<double> rates;  // the same for the slip rates at mu > 1
  for (const auto& [t, rate] : aboveOneRates_) rates.insert(rates.end(), {t, rate});
  a.field("contact.aboveOneRates", rates);
  aboveOneRates_.clear();
  for (std::size_t i = 0; i + 1 < rates.size(); i += 2) aboveOneRates_.emplace_back(rates[i], rates[i + 1]);
}

LayerWork ContactBoundary::work() const {
  LayerWork w;  // over ranks already, subtracted after the exact sums (the balance's bits)
  w.overRanks = -contactWork();
  w.hasOverRanks = true;
  return w;
}

std::string ContactBoundary::describe() const {
  std::string text = std::string(settings_.kinematic ? "kinematic" : "penalty") +
                     " contact with the rigid plane, friction law " + settings_.law.name + ", one site per bottom node";
  if (law_.normalStress.active()) text += ", " + law_.normalStress.describe();
  return text;
}

void ContactBoundary::writeProperties(PropertySink& sink) const {
  std::vector<PetscInt> blocks;
  std::vector<double> muS, muK;
  law_.visitStrength([&](const auto& law) {
    const FrictionSites& sites = law.sites;
    for (std::size_t site = 0; site < nodes_.size(); ++site) {
      const int slot = sites.slotOfSite(static_cast<int>(site));
      blocks.push_back(nodes_[site].block);
      muS.push_back(sites.staticAt(slot));
      muK.push_back(sites.kineticAt(slot));
    }
  });
  const std::string how = std::string("of the bottom node: the area-weighted mean of its faces' factors") +
                          (randomSurface_ ? ", times the random surface averaged over its tributary rectangle" : "");
  sink.nodeField("mu_s", "1", "local static coefficient " + how, blocks, muS);
  sink.nodeField("mu_k", "1", "local kinetic coefficient " + how, blocks, muK);
}

double ContactBoundary::largestStaticCoefficient() const {
  double local = 0, global = 0;
  law_.visitStrength([&](const auto& law) {
    for (double s : law.sites.staticStrength) local = std::max(local, s);
  });
  GF_CALL_MPI(MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, comm_));
  return global;
}

void ContactBoundary::commit() {
  lastStepSlip_ = 0;
  law_.commit();
  for (Node& n : nodes_) {
    n.anchorX = n.pendingX;
    n.anchorY = n.pendingY;
    n.state = n.pendingState;
    n.stepSlip = n.pendingState == ContactState::Slip ? std::hypot(n.pendingU[0] - n.u[0], n.pendingU[1] - n.u[1]) : 0.0;
    lastStepSlip_ = std::max(lastStepSlip_, n.stepSlip);
    for (int d = 0; d < 3; ++d) {
      n.work += 0.5 * (n.force[d] + n.pendingForce[d]) * (n.pendingU[d] - n.u[d]);
      n.force[d] = n.pendingForce[d];
      n.u[d] = n.pendingU[d];
    }
    if (n.state != ContactState::Stick) n.everSlipped = true;  // slipped or lost contact
  }
}

void ContactBoundary::resetSlipRecord() {
  for (Node& n : nodes_) {
    n.everSlipped = false;
    n.firstSlip = std::numeric_limits<double>::quiet_NaN();
  }
  slipRecord_.clear();
}

void ContactBoundary::recordFirstSlips(double t) {
  for (Node& n : nodes_)
    if (n.state == ContactState::Slip && std::isnan(n.firstSlip)) n.firstSlip = t;
}

void ContactBoundary::settleRememberedPressure() {
  for (std::size_t site = 0; site < nodes_.size(); ++site) law_.normalStress.settle(static_cast<int>(site), nodes_[site].pressure);
}

void ContactBoundary::recordOnset(double t, double dt) {
  if (lastStepSlip_ > (slipRecord_.empty() ? 0.0 : slipRecord_.back().second)) slipRecord_.push_back({t, lastStepSlip_});
  double fastest = aboveOneRates_.empty() ? 0.0 : aboveOneRates_.back().second;
  const double fastestBefore = fastest;
  law_.visitStrength([&](const auto& law) {
    const FrictionSites& sites = law.sites;
    for (std::size_t site = 0; site < nodes_.size(); ++site) {
      Node& n = nodes_[site];
      const double strength = law.committedStrength(static_cast<int>(site));
      // Sliding, not stuck or open: the flutter needs the friction force to act on a slip.
      if (n.state == ContactState::Slip && strength > 1.0 + 1e-9) {
        if (n.slidAboveOne < 0) n.slidAboveOne = t;
        fastest = std::max(fastest, n.stepSlip / dt);
      }
      if (n.weakenEnd >= 0) continue;
      const int slot = sites.slotOfSite(static_cast<int>(site));
      const double s = sites.staticAt(slot), k = sites.kineticAt(slot);
      if (!(s - k > 1e-12 * s)) continue;  // no weakening to measure
      const double left = (strength - k) / (s - k);
      if (n.weakenStart < 0 && left < 0.9) n.weakenStart = t;
      if (left < 0.1) n.weakenEnd = t;
    }
  });
  if (fastest > fastestBefore) aboveOneRates_.push_back({t, fastest});
}

ProcessZone ContactBoundary::processZone(double latestStart) const {
  int rank = 0;
  GF_CALL_MPI(MPI_Comm_rank(comm_, &rank));
  std::vector<double> mine;  // x, y, start, end per node
  for (const Node& n : nodes_) mine.insert(mine.end(), {n.x, n.y, n.weakenStart, n.weakenEnd});
  const std::vector<double> all = gatherOnRoot(comm_, mine);
  double result[5] = {0, 0, 0, 0, 0};
  if (rank == 0) {
    WeakeningTimes times;
    for (std::size_t i = 0; i + 3 < all.size(); i += 4) {
      times.x.push_back(all[i]);
      times.y.push_back(all[i + 1]);
      times.start.push_back(all[i + 2]);
      times.end.push_back(all[i + 3]);
    }
    const ProcessZone z = measureProcessZone(times, latestStart);
    result[0] = z.nodes;
    result[1] = z.median;
    result[2] = z.low;
    result[3] = z.medianElements;
    result[4] = z.lowElements;
  }
  GF_CALL_MPI(MPI_Bcast(result, 5, MPI_DOUBLE, 0, comm_));
  return ProcessZone{static_cast<int>(result[0]), result[1], result[2], result[3], result[4]};
}

double ContactBoundary::largestSlipPerStep(double until) const {
  double local = 0, global = 0;
  for (const auto& [t, largest] : slipRecord_)
    if (t <= until) local = largest;
  GF_CALL_MPI(MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, comm_));
  return global;
}

SlidingAboveOne ContactBoundary::slidAboveOne(double until, const MeshAxis& x, const MeshAxis& y) const {
  // The larger of the two cells on either side of a node along an axis.
  const auto side = [](const MeshAxis& axis, double at) {
    const int node = axis.nearestNode(at);
    double h = 0;
    if (node > 0) h = std::max(h, axis.width(node - 1));
    if (node < axis.cells()) h = std::max(h, axis.width(node));
    return h;
  };
  ExactSum sums[3];  // nodes, their area, all the area: exact, so the same on any partition
  double largest[2] = {0, 0};  // element side, slip rate: maxima, the same on any partition
  for (const Node& n : nodes_) {
    const bool slid = n.slidAboveOne >= 0 && n.slidAboveOne <= until;
    sums[0].add(slid ? 1.0 : 0.0);
    sums[1].add(slid ? n.area : 0.0);
    sums[2].add(n.area);
    if (slid) largest[0] = std::max({largest[0], side(x, n.x), side(y, n.y)});
  }
  for (const auto& [t, rate] : aboveOneRates_)
    if (t <= until) largest[1] = rate;
  allreduceExact(comm_, sums, 3);
  GF_CALL_MPI(MPI_Allreduce(MPI_IN_PLACE, largest, 2, MPI_DOUBLE, MPI_MAX, comm_));
  SlidingAboveOne s;
  s.nodes = std::lround(sums[0].value());
  s.areaFraction = sums[2].value() > 0 ? sums[1].value() / sums[2].value() : 0.0;
  s.largestElement = largest[0];
  s.fastestRate = largest[1];
  return s;
}

void ContactBoundary::penetration(Vec X, double* mean, double* minimum, double* maximum) const {
  ExactSum s[2];
  double lo = 1e300, hi = -1e300;
  const ReadState x(X);
  for (const Node& n : nodes_) {
    const double pen = -x.displacement(n.block)[2];
    s[0].add(pen);
    s[1].add(1);
    lo = std::min(lo, pen);
    hi = std::max(hi, pen);
  }
  allreduceExact(comm_, s, 2);
  const double sum[2] = {s[0].value(), s[1].value()};
  GF_CALL_MPI(MPI_Allreduce(MPI_IN_PLACE, &lo, 1, MPI_DOUBLE, MPI_MIN, comm_));
  GF_CALL_MPI(MPI_Allreduce(MPI_IN_PLACE, &hi, 1, MPI_DOUBLE, MPI_MAX, comm_));
  *mean = sum[0] / sum[1];
  *minimum = lo;
  *maximum = hi;
}

}  // namespace gradfric::fem
