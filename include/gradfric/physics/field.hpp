#pragma once
// A property field over the plate: the plate's value (E, mu_s, mu_k or p) times a dimensionless
// profile f(x, y). The profile runs along any in-plane direction or radially from a point, or is
// a 2D map; it can be rescaled so that its mean over a model's sites is 1 (the plate's value is
// then the mean, the paper's premise). Pure arithmetic, no PETSc: both models sample the same
// description (the SBM at block centres, the FEM at cell centroids and contact nodes).
//
// Coordinates: u = x / L, v = y / L in [0, 1]. Along a direction (angle theta from +x) the profile
// sees s in [0, 1] across the plate's extent in that direction, d = s * extent [m] from the plate's
// first corner; theta = 0 gives s = u exactly (the paper's gradings along x). Radially from
// (x_c, y_c) it sees the distance d [m] and s = d / (largest distance to a corner).
#include <memory>
#include <string>
#include <vector>

namespace gradfric {

struct SiteGrid;  // property_sampler.hpp

enum class FieldShape { Constant, Linear, Triangular, Exponential, Power, Step, Stripes, Bands, Map };
const char* toString(FieldShape shape);

// A 2D map of the profile: values on a regular grid of nx x ny pixels covering [x0, x1] x [y0, y1]
// (metres), pixel (i, j) centred at x0 + (i + 1/2) dx, y0 + (j + 1/2) dy, stored row-major with
// j (y) the row. Sampled bilinearly between pixel centres; constant beyond the outer centres.
struct FieldMap {
  int nx = 0, ny = 0;
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  std::vector<double> values;
  std::string source;  // the file it came from, for messages and the results file
  double at(double x, double y) const;
};

struct PropertyField {
  FieldShape shape = FieldShape::Constant;
  double delta = 0.0;      // relative amplitude (constant, linear, triangular, power, step, stripes)
  double exponent = 1.0;   // power law: f = 1 + delta (2 s^exponent - 1); exponential: f = exp(exponent (s - 1/2))
  int bands = 0;           // linear/triangular: 0 continuous, N >= 2 the paper's N homogeneous bands
  double angle = 0.0;      // direction of the profile [degree] from +x
  bool radial = false;     // profile of the distance to (centreX, centreY) instead
  double centreX = 0.0, centreY = 0.0;  // [m]
  double position = 0.0;   // step: where the second material starts; stripes: offset of the first stripe [m]
  double period = 0.0;     // stripes: period [m]
  double duty = 0.5;       // stripes: fraction of a period with f = 1 + delta
  std::vector<double> table;  // band table: N factors across the plate
  std::shared_ptr<const FieldMap> map;
  bool normalise = false;  // rescale so the mean over a model's sites is 1
  double length = 1.0;     // plate side L [m]
  // The option a value out of range is blamed on (its shape's amplitude, table or map) and its value.
  std::string blameOption, blameValue;

  // The profile at (u, v), before normalisation.
  double profile(double u, double v) const;
  // The normalisation factor for a model whose sites are the centres of an nx x ny grid of equal
  // cells (SBM blocks, FEM bottom faces): 1 / mean of the profile there, or 1.
  double scaleFor(int nx, int ny) const;
  // The same over a grid of unequal cells (a mesh graded toward the edges): 1 / the area-weighted
  // mean of the profile at their centres.
  double scaleFor(const SiteGrid& grid) const;
  // Whether f changes along y (the SBM then needs its stiffnesses, or strengths, per block).
  bool variesAlongY() const;
  // The scalar parameters a sweep can set by name: delta, exponent, angle, position, period, duty.
  static const std::vector<std::string>& scalarParameters();
  bool setParameter(const std::string& name, double value);  // false: no such parameter
  std::string describe() const;
};

// The property fields of a plate; an absent field leaves its property to the -grading_* options.
// mu_s and mu_k may share one field (their ratio kept) or have their own.
struct PlateFields {
  std::shared_ptr<const PropertyField> modulus, muStatic, muKinetic, pressure;
  bool any() const { return modulus || muStatic || muKinetic || pressure; }
};

// A copy of `fields` with one scalar parameter of one property's field set: `parameter` is
// "<property>_<name>" (mu_delta, E_exponent, p_position, mu_s_period, ...). Throws
// std::invalid_argument naming what is wrong (no such property field, no such parameter).
std::shared_ptr<const PlateFields> withParameter(const std::shared_ptr<const PlateFields>& fields,
                                                 const std::string& parameter, double value);

// One line per field: "property field of mu_s and mu_k: stripes, Delta = 0.3, ...".
std::vector<std::string> describeFields(const PlateFields& fields);

// Where a property leaves its allowed range first (row-major scan of the grid's centres).
struct FieldViolation {
  bool found = false;
  double x = 0.0, y = 0.0;  // [m]
  double value = 0.0;
};

}  // namespace gradfric
