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
//    map (the gradfric-fem results file, /fem/pressure_response/g) and sampled bilinearly at the
//    block centres, then its weighted mean removed (its moment is what the FEM measured).
// Pure arithmetic, no PETSc (the options: pressure_response_options.hpp).
#include "gradfric/physics/field.hpp"
#include "gradfric/physics/grading.hpp"

#include <memory>
#include <string>
#include <vector>

namespace gradfric {

enum class PressureResponseSource { None, MomentBalance, Fem };

// gradfric-fem measures g as the linear response of the contact pressure over mu(t) in
// [0.2, 0.8] of its run's mu_s; a shape is required to keep every block's pressure positive up
// to the window's top (the file's mu_window; kResponseWindowHigh -plate_mu_s for the moment
// balance and files without one); beyond, a block whose factor would turn negative lifts off
// (clamped at 0, counted by the coupling's record).
inline constexpr double kResponseWindowLow = 0.2, kResponseWindowHigh = 0.8;

// The grading of the FEM run that measured a g (its /scene record): the key that selects a g per
// sweep point. Every non-graded plate (profile none or Delta = 0) has the same key.
struct ResponseGrading {
  bool graded = false;
  std::string property, profile;  // as the options spell them: E|friction|both, linear|triangular
  double delta = 0.0;
  int bands = 0;
  double theta = 0.0;  // sliding angle [degree]
  std::string describe() const;
};
// The key of a sweep point: its grading and sliding angle.
ResponseGrading responseGradingOf(const Grading& grading, double thetaDegrees);
// Equal keys: the same property, profile and bands, Delta and theta within 1e-9 (or both non-graded
// at the same angle).
bool sameGrading(const ResponseGrading& a, const ResponseGrading& b);

// One g measured by gradfric-fem, with the grading it was measured under.
struct MeasuredResponse {
  std::shared_ptr<const FieldMap> map;  // g on the FEM's bottom node grid
  ResponseGrading grading;
  std::string file;
  double measuredUpTo = 0.0;  // top of the mu(t) window the FEM fitted it on (0: not known)
};

struct PressureResponse {
  PressureResponseSource source = PressureResponseSource::None;
  double edgeLength = 0.0;              // moment balance: decay length lambda of the edge concentration [m]
  std::shared_ptr<const FieldMap> map;  // FEM: g on the FEM's bottom node grid (the one for every point)
  // FEM with -pressure_response_select grading: every g read, each run takes the one measured
  // under its own grading (selectedFor); `map` is then empty.
  bool perGrading = false;
  std::vector<MeasuredResponse> measured;
  bool active() const { return source != PressureResponseSource::None; }
  std::string describe() const;
};

// The response one run uses: `response` itself, or under -pressure_response_select grading the
// one whose map was measured under this grading and angle. None: InputError naming
// -pressure_response_file, its value, the run (`run`, e.g. "sweep point 3") and its grading, and the
// gradings the files hold (the ensemble checks every sweep point so before any work).
PressureResponse selectedFor(const PressureResponse& response, const Grading& grading, double thetaDegrees,
                             const std::string& run = "this run");
// The gradings the files hold, for messages: "non-graded (a.h5); E linear Delta = 0.2 ... (b.h5)".
std::string describeMeasured(const PressureResponse& response);

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
