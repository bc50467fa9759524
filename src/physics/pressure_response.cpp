// The shape g of the load-dependent pressure (pressure_response.hpp).
#include "gradfric/physics/pressure_response.hpp"

#include "gradfric/core/input_error.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace gradfric {

namespace {

// cos and sin of an angle in degrees, exact at multiples of 90 degrees (the paper's 0 and 90).
void direction(double degrees, double& cx, double& cy) {
  const double turns = degrees / 90.0;
  if (turns == std::floor(turns)) {
    static const double c[4] = {1, 0, -1, 0}, s[4] = {0, 1, 0, -1};
    const int q = static_cast<int>(((static_cast<long long>(turns) % 4) + 4) % 4);
    cx = c[q];
    cy = s[q];
    return;
  }
  cx = std::cos(degrees * M_PI / 180.0);
  cy = std::sin(degrees * M_PI / 180.0);
}

double weight(const std::vector<double>& weights, std::size_t i) { return weights.empty() ? 1.0 : weights[i]; }

}  // namespace

std::string PressureResponse::describe() const {
  std::ostringstream s;
  switch (source) {
    case PressureResponseSource::None: return "uniform normal force per block (no pressure response)";
    case PressureResponseSource::MomentBalance:
      s << "load-dependent pressure p_i = p_i^0 (1 + mu(t) g_i), g from the moment balance (H F), edge decay length "
        << edgeLength << " m";
      return s.str();
    case PressureResponseSource::Fem:
      s << "load-dependent pressure p_i = p_i^0 (1 + mu(t) g_i), g measured by gradfric-fem (";
      if (perGrading)
        s << "per sweep point, the g measured under its grading: " << describeMeasured(*this) << ")";
      else
        s << (map ? map->source : std::string("?")) << ")";
      return s.str();
  }
  return {};
}

std::string ResponseGrading::describe() const {
  std::ostringstream s;
  if (graded)
    s << property << " " << profile << " Delta = " << delta << ", " << bands << " bands";
  else
    s << "non-graded";
  s << ", theta = " << theta;
  return s.str();
}

ResponseGrading responseGradingOf(const Grading& g, double thetaDegrees) {
  ResponseGrading k;
  k.theta = thetaDegrees;
  if (!g.active()) return k;
  k.graded = true;
  k.property = toString(g.property);
  k.profile = toString(g.profile);
  k.delta = g.delta;
  k.bands = g.bands;
  return k;
}

bool sameGrading(const ResponseGrading& a, const ResponseGrading& b) {
  const double tolerance = 1e-9;
  if (std::fabs(a.theta - b.theta) > tolerance || a.graded != b.graded) return false;
  if (!a.graded) return true;
  return a.property == b.property && a.profile == b.profile && a.bands == b.bands &&
         std::fabs(a.delta - b.delta) <= tolerance;
}

std::string describeMeasured(const PressureResponse& r) {
  std::string text;
  for (const MeasuredResponse& m : r.measured) {
    if (!text.empty()) text += "; ";
    text += m.grading.describe() + " (" + m.file + ")";
  }
  return text;
}

PressureResponse selectedFor(const PressureResponse& r, const Grading& grading, double thetaDegrees,
                             const std::string& run) {
  if (!r.perGrading) return r;
  const ResponseGrading key = responseGradingOf(grading, thetaDegrees);
  for (const MeasuredResponse& m : r.measured)
    if (sameGrading(m.grading, key)) {
      PressureResponse one = r;
      one.perGrading = false;
      one.measured = {m};
      one.map = m.map;
      return one;
    }
  std::string files;
  for (const MeasuredResponse& m : r.measured) files += (files.empty() ? "" : ",") + m.file;
  throw InputError("-pressure_response_file", files,
                   "a g measured under the grading of every run (-pressure_response_select grading): " + run + " (" +
                       key.describe() + ") has none; the files hold " + describeMeasured(r));
}

std::vector<double> slidingCoordinates(int nb, double length, double angleDegrees) {
  double cx = 0, cy = 0;
  direction(angleDegrees, cx, cy);
  const double l = length / nb;
  std::vector<double> s(std::size_t(nb) * nb);
  for (int r = 0; r < nb; ++r)
    for (int c = 0; c < nb; ++c)
      s[std::size_t(r) * nb + c] = ((c + 0.5) * l - 0.5 * length) * cx + ((r + 0.5) * l - 0.5 * length) * cy;
  return s;
}

std::vector<double> momentBalanceShape(int nb, double length, double thickness, double angleDegrees,
                                       double edgeLength) {
  if (!(edgeLength > 0)) throw std::invalid_argument("moment-balance shape: the edge length must be positive");
  double cx = 0, cy = 0;
  direction(angleDegrees, cx, cy);
  const double l = length / nb;
  // Along one axis: +1 concentrated at the far edge (index nb-1), -1 at the near edge (index 0),
  // measured from the outermost block centres so that no value underflows at the edge itself.
  std::vector<double> edge(nb);
  for (int k = 0; k < nb; ++k)
    edge[k] = std::exp(-(nb - 1 - k) * l / edgeLength) - std::exp(-k * l / edgeLength);
  std::vector<double> g(std::size_t(nb) * nb);
  for (int r = 0; r < nb; ++r)
    for (int c = 0; c < nb; ++c) g[std::size_t(r) * nb + c] = cx * edge[c] + cy * edge[r];
  // Its first moment along the sliding direction, then scaled to H.
  const ShapeMoments m = shapeMoments(g, slidingCoordinates(nb, length, angleDegrees));
  for (double& v : g) v *= thickness / m.moment;
  return g;
}

std::vector<double> sampledShape(const FieldMap& map, int nb, double length) {
  std::vector<double> g(std::size_t(nb) * nb);
  const double l = length / nb;
  for (int r = 0; r < nb; ++r)
    for (int c = 0; c < nb; ++c) g[std::size_t(r) * nb + c] = map.at((c + 0.5) * l, (r + 0.5) * l);
  return g;
}

ShapeMoments shapeMoments(const std::vector<double>& g, const std::vector<double>& s, const std::vector<double>& w) {
  double sum = 0.0, moment = 0.0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    sum += weight(w, i) * g[i];
    moment += weight(w, i) * s[i] * g[i];
  }
  const double n = static_cast<double>(g.size());
  return {sum / n, moment / n};
}

std::vector<double> pressureResponseShape(const PressureResponse& response, int nb, double length, double thickness,
                                          double angleDegrees, const std::vector<double>& weights) {
  const std::size_t n = std::size_t(nb) * nb;
  if (response.source == PressureResponseSource::None) return std::vector<double>(n, 0.0);
  std::vector<double> g = response.source == PressureResponseSource::MomentBalance
                              ? momentBalanceShape(nb, length, thickness, angleDegrees, response.edgeLength)
                              : sampledShape(*response.map, nb, length);
  // Zero weighted mean: the total normal force sum p_i^0 l^2 (1 + mu g_i) stays p L^2.
  double weightSum = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    weightSum += weight(weights, i);
    sum += weight(weights, i) * g[i];
  }
  const double mean = sum / weightSum;
  for (double& v : g) v -= mean;
  if (response.source == PressureResponseSource::MomentBalance) {  // moment exactly H under the weights
    const ShapeMoments m = shapeMoments(g, slidingCoordinates(nb, length, angleDegrees), weights);
    for (double& v : g) v *= thickness / m.moment;
  }
  return g;
}

}  // namespace gradfric
