#include "gradfric/fem/contact_resultants.hpp"

#include "gradfric/core/petsc_call.hpp"

#include <cmath>

namespace gradfric::fem {

ContactResultants contactResultants(const PlateModel& model) {
  const double L = model.mesh().size().length, hx = model.mesh().hx();
  // The node line nearest x = L/2 (an odd nx has none on it exactly).
  const double centreLine = std::round(0.5 * model.mesh().size().nx) * hx;
  enum { Fx, Fy, Fn, My, Mx, TrailSum, TrailCount, LeadSum, LeadCount, CentreSum, CentreCount, Count };
  double local[Count] = {}, sum[Count] = {};
  for (const ContactBoundary::Node& n : model.contact().nodes()) {
    const double force = n.pressure * n.area;
    local[Fx] += n.tx * n.area;
    local[Fy] += n.ty * n.area;
    local[Fn] += force;
    local[My] += (n.x - 0.5 * L) * force;
    local[Mx] += (n.y - 0.5 * L) * force;
    if (n.x < 0.5 * hx) local[TrailSum] += n.pressure, local[TrailCount] += 1;
    if (n.x > L - 0.5 * hx) local[LeadSum] += n.pressure, local[LeadCount] += 1;
    if (std::fabs(n.x - centreLine) < 0.5 * hx) local[CentreSum] += n.pressure, local[CentreCount] += 1;
  }
  GF_CALL_MPI(MPI_Allreduce(local, sum, Count, MPI_DOUBLE, MPI_SUM, model.comm()));
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
