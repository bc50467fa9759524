#pragma once
// The load-dependent normal pressure of the spring-block model. In the 3D plate the tangential
// load F, applied at the top at height H, tilts the contact pressure: the moment balance
// integral (x - L/2) p_c dA = H F (x along the sliding direction) unloads the trailing edge and
// overloads the leading one. The spring-block model takes it as
//     p_i(t) = p_i^0 (1 + mu(t) g_i),   mu(t) = F(t) / (p L^2),
// with a dimensionless shape g on the block lattice: zero mean (weighted by p_i^0, so the total
// normal force stays p L^2), and either
//  - the moment balance: first moment mean(s_i g_i) = H (s along the sliding direction from the
//    plate's centre) with an exponential edge concentration of decay length lambda at the
//    leading and trailing edges; or
//  - an FEM run's measurement: the change of the bottom nodal pressure per unit of mu, read as a
//    map (the gradfric-fem results file, /pressure_response/g) and sampled bilinearly at the
//    block centres, then its weighted mean removed (its moment is what the FEM measured).
// Pure arithmetic, no PETSc (the options: pressure_response_options.hpp).
#include "gradfric/physics/field.hpp"

#include <memory>
#include <string>
#include <vector>

namespace gradfric {

enum class PressureResponseSource { None, MomentBalance, Fem };

struct PressureResponse {
  PressureResponseSource source = PressureResponseSource::None;
  double edgeLength = 0.0;              // moment balance: decay length lambda of the edge concentration [m]
  std::shared_ptr<const FieldMap> map;  // FEM: g on the FEM's bottom node grid
  bool active() const { return source != PressureResponseSource::None; }
  std::string describe() const;
};

// The sliding direction's signed distance from the plate's centre of the centre of block
// (row, column) of an N x N lattice [m]: s = (x - L/2) cos(theta) + (y - L/2) sin(theta).
std::vector<double> slidingCoordinates(int blocksPerSide, double length, double angleDegrees);

// g at the N x N block centres (row-major), before the mean removal of pressureResponseShape.
std::vector<double> momentBalanceShape(int blocksPerSide, double length, double thickness, double angleDegrees,
                                       double edgeLength);
std::vector<double> sampledShape(const FieldMap& map, int blocksPerSide, double length);

// The shape of a response on the lattice: zero mean under the weights p_i^0 / p (empty: uniform),
// and for the moment balance first moment sum(w_i s_i g_i) / N^2 = H exactly (to round-off).
std::vector<double> pressureResponseShape(const PressureResponse& response, int blocksPerSide, double length,
                                          double thickness, double angleDegrees,
                                          const std::vector<double>& weights = {});

// The weighted mean sum(w_i g_i) / N^2 and first moment sum(w_i s_i g_i) / N^2 [m] of a shape.
struct ShapeMoments {
  double mean = 0.0, moment = 0.0;
};
ShapeMoments shapeMoments(const std::vector<double>& shape, const std::vector<double>& coordinates,
                          const std::vector<double>& weights = {});

}  // namespace gradfric
