#include "gradfric/fem/contact_resultants.hpp"

#include "gradfric/core/reproducible_sum.hpp"

#include <algorithm>
#include <cmath>

namespace gradfric::fem {

ContactResultants contactResultants(const PlateModel& model) {
  const MeshAxis& axis = model.mesh().axisX();
  const double L = model.mesh().size().length;
  // The node line nearest x = L/2 (an odd nx has none on it exactly), and the half widths of the
  // cells at the edges and there: a node line is taken within half its cell's width.
  const int centreNode = static_cast<int>(std::round(0.5 * axis.cells()));
  const double centreLine = axis.nodes[centreNode];
  const double trailHalf = 0.5 * axis.width(0), leadHalf = 0.5 * axis.width(axis.cells() - 1),
               centreHalf = 0.5 * axis.width(std::min(centreNode, axis.cells() - 1));
  enum { Fx, Fy, Fn, My, Mx, TrailSum, TrailCount, LeadSum, LeadCount, CentreSum, CentreCount, Count };
  ExactSum local[Count];  // exact: the same bits on any number of ranks
  for (const ContactBoundary::Node& n : model.contact().nodes()) {
    const double force = n.pressure * n.area;
    local[Fx].add(n.tx * n.area);
    local[Fy].add(n.ty * n.area);
    local[Fn].add(force);
    local[My].add((n.x - 0.5 * L) * force);
    local[Mx].add((n.y - 0.5 * L) * force);
    if (n.x < trailHalf) local[TrailSum].add(n.pressure), local[TrailCount].add(1);
    if (n.x > L - leadHalf) local[LeadSum].add(n.pressure), local[LeadCount].add(1);
    if (std::fabs(n.x - centreLine) < centreHalf) local[CentreSum].add(n.pressure), local[CentreCount].add(1);
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
