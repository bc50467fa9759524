#include "gradfric/fem/contact_resultants.hpp"

#include "gradfric/core/reproducible_sum.hpp"

#include <cmath>

namespace gradfric::fem {

ContactResultants contactResultants(const PlateModel& model) {
  const double L = model.mesh().size().length, hx = model.mesh().hx();
  // The node line nearest x = L/2 (an odd nx has none on it exactly).
  const double centreLine = std::round(0.5 * model.mesh().size().nx) * hx;
  enum { Fx, Fy, Fn, My, Mx, TrailSum, TrailCount, LeadSum, LeadCount, CentreSum, CentreCount, Count };
  ExactSum local[Count];  // exact: the same bits on any number of ranks
  for (const ContactBoundary::Node& n : model.contact().nodes()) {
    const double force = n.pressure * n.area;
    local[Fx].add(n.tx * n.area);
    local[Fy].add(n.ty * n.area);
    local[Fn].add(force);
    local[My].add((n.x - 0.5 * L) * force);
    local[Mx].add((n.y - 0.5 * L) * force);
    if (n.x < 0.5 * hx) local[TrailSum].add(n.pressure), local[TrailCount].add(1);
    if (n.x > L - 0.5 * hx) local[LeadSum].add(n.pressure), local[LeadCount].add(1);
    if (std::fabs(n.x - centreLine) < 0.5 * hx) local[CentreSum].add(n.pressure), local[CentreCount].add(1);
  }
  allreduceExact(model.comm(), local, Count);
  double sum[Count];
  for (int i = 0; i < Count; ++i) sum[i] = local[i].value();
  ContactResultants r;
  r.forceX = sum[Fx];
  r.forceY = sum[Fy];
  r.normalForce = sum[Fn];
  r.momentAboutY = sum[My];
  r.momentAboutX = sum[Mx];
  r.trailingEdgePressure = sum[TrailSum] / sum[TrailCount];
  r.leadingEdgePressure = sum[LeadSum] / sum[LeadCount];
  r.centrePressure = sum[CentreSum] / sum[CentreCount];
  return r;
}

}  // namespace gradfric::fem
