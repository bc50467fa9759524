#include "gradfric/physics/field.hpp"

#include "gradfric/physics/property_sampler.hpp"  // SiteGrid

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace gradfric {

namespace {

// cos and sin of an angle in degrees, exact at multiples of 90 (sin(pi) is 1.2e-16, not 0).
void direction(double degrees, double* c, double* s) {
  const double turns = degrees / 90.0;
  if (turns == std::floor(turns)) {
    const int quarter = ((static_cast<int>(std::fmod(turns, 4.0)) % 4) + 4) % 4;
    const double cs[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
    *c = cs[quarter];
    *s = sn[quarter];
    return;
  }
  *c = std::cos(degrees * M_PI / 180.0);
  *s = std::sin(degrees * M_PI / 180.0);
}

// The paper's band factor (grading.hpp's bandFactor, the same operations): t = -1 .. 1.
double bandCoordinate(double s, int bands) {
  const int band = std::clamp(static_cast<int>(std::floor(s * bands)), 0, bands - 1);
  return 2.0 * band / (bands - 1) - 1.0;
}

}  // namespace

const char* toString(FieldShape shape) {
  switch (shape) {
    case FieldShape::Constant: return "constant";
    case FieldShape::Linear: return "linear";
    case FieldShape::Triangular: return "triangular";
    case FieldShape::Exponential: return "exponential";
    case FieldShape::Power: return "power";
    case FieldShape::Step: return "step";
    case FieldShape::Stripes: return "stripes";
    case FieldShape::Bands: return "bands";
    case FieldShape::Map: return "map";
  }
  return "constant";
}

double FieldMap::at(double x, double y) const {
  const double dx = (x1 - x0) / nx, dy = (y1 - y0) / ny;
  // Position in pixel-centre units, clamped to the outer centres.
  const double fi = std::clamp((x - x0) / dx - 0.5, 0.0, double(nx - 1));
  const double fj = std::clamp((y - y0) / dy - 0.5, 0.0, double(ny - 1));
  const int i = std::min(static_cast<int>(fi), std::max(nx - 2, 0));
  const int j = std::min(static_cast<int>(fj), std::max(ny - 2, 0));
  const double a = nx > 1 ? fi - i : 0.0, b = ny > 1 ? fj - j : 0.0;
  const int i1 = std::min(i + 1, nx - 1), j1 = std::min(j + 1, ny - 1);
  auto v = [&](int ii, int jj) { return values[static_cast<std::size_t>(jj) * nx + ii]; };
  return (1 - b) * ((1 - a) * v(i, j) + a * v(i1, j)) + b * ((1 - a) * v(i, j1) + a * v(i1, j1));
}

double PropertyField::profile(double u, double v) const {
  if (shape == FieldShape::Constant) return 1.0 + delta;
  if (shape == FieldShape::Map) return map->at(u * length, v * length);
  double s = 0.0, d = 0.0;  // coordinate across the plate [0, 1] and distance [m]
  if (radial) {
    const double dx = u * length - centreX, dy = v * length - centreY;
    d = std::sqrt(dx * dx + dy * dy);
    double farthest = 0.0;
    for (double cx : {0.0, length})
      for (double cy : {0.0, length}) farthest = std::max(farthest, std::hypot(cx - centreX, cy - centreY));
    s = d / farthest;
  } else {
    double c = 1.0, sn = 0.0;
    direction(angle, &c, &sn);
    if (c == 1.0 && sn == 0.0) {
      s = u;  // along x: exactly the paper's coordinate
    } else {
      const double span = std::fabs(c) + std::fabs(sn);
      s = ((u - 0.5) * c + (v - 0.5) * sn) / span + 0.5;
    }
    d = s * length * (std::fabs(c) + std::fabs(sn));
  }
  switch (shape) {
    case FieldShape::Linear:
      return 1.0 + delta * (bands >= 2 ? bandCoordinate(s, bands) : 2.0 * s - 1.0);
    case FieldShape::Triangular:
      return 1.0 + delta * (1.0 - 2.0 * std::fabs(bands >= 2 ? bandCoordinate(s, bands) : 2.0 * s - 1.0));
    case FieldShape::Exponential: return std::exp(exponent * (s - 0.5));
    case FieldShape::Power: return 1.0 + delta * (2.0 * std::pow(std::clamp(s, 0.0, 1.0), exponent) - 1.0);
    case FieldShape::Step: return d < position ? 1.0 - delta : 1.0 + delta;
    case FieldShape::Stripes: {
      const double phase = (d - position) / period;
      return phase - std::floor(phase) < duty ? 1.0 + delta : 1.0;
    }
    case FieldShape::Bands: {
      const int n = static_cast<int>(table.size());
      return table[std::clamp(static_cast<int>(std::floor(s * n)), 0, n - 1)];
    }
    default: return 1.0;
  }
}

double PropertyField::scaleFor(int nx, int ny) const {
  if (!normalise) return 1.0;
  double sum = 0.0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) sum += profile((i + 0.5) / nx, (j + 0.5) / ny);
  return double(nx) * ny / sum;
}

double PropertyField::scaleFor(const SiteGrid& grid) const {
  if (!normalise) return 1.0;
  double sum = 0.0, area = 0.0;
  for (std::size_t j = 0; j < grid.v.size(); ++j)
    for (std::size_t i = 0; i < grid.u.size(); ++i) {
      const double a = grid.du[i] * grid.dv[j];
      sum += a * profile(grid.u[i], grid.v[j]);
      area += a;
    }
  return area / sum;
}

bool PropertyField::variesAlongY() const {
  if (shape == FieldShape::Constant) return false;
  if (shape == FieldShape::Map || radial) return true;
  double c = 1.0, s = 0.0;
  direction(angle, &c, &s);
  return s != 0.0;
}

std::string PropertyField::describe() const {
  std::ostringstream out;
  out << toString(shape);
  switch (shape) {
    case FieldShape::Constant: out << ", factor " << 1.0 + delta; break;
    case FieldShape::Linear:
    case FieldShape::Triangular:
      out << ", Delta = " << delta;
      if (bands >= 2) out << ", " << bands << " bands";
      break;
    case FieldShape::Exponential: out << ", rate " << exponent; break;
    case FieldShape::Power: out << ", Delta = " << delta << ", exponent " << exponent; break;
    case FieldShape::Step: out << ", Delta = " << delta << " from " << position << " m"; break;
    case FieldShape::Stripes:
      out << ", Delta = " << delta << ", period " << period << " m, duty " << duty << ", offset " << position << " m";
      break;
    case FieldShape::Bands: out << ", " << table.size() << " bands"; break;
    case FieldShape::Map: out << " " << map->source << " (" << map->nx << " x " << map->ny << ", bilinear)"; break;
  }
  if (shape != FieldShape::Constant && shape != FieldShape::Map) {
    if (radial) out << ", radial from (" << centreX << ", " << centreY << ") m";
    else out << ", along " << angle << " degree";
  }
  if (normalise) out << ", mean-preserving";
  return out.str();
}

std::vector<std::string> describeFields(const PlateFields& f) {
  std::vector<std::string> lines;
  auto add = [&](const char* what, const std::shared_ptr<const PropertyField>& field) {
    if (field) lines.push_back(std::string("property field of ") + what + ": " + field->describe());
  };
  add("E", f.modulus);
  if (f.muStatic && f.muStatic == f.muKinetic) {
    add("mu_s and mu_k (ratio kept)", f.muStatic);
  } else {
    add("mu_s", f.muStatic);
    add("mu_k", f.muKinetic);
  }
  add("the normal pressure p", f.pressure);
  return lines;
}

const std::vector<std::string>& PropertyField::scalarParameters() {
  static const std::vector<std::string> names = {"delta", "exponent", "angle", "position", "period", "duty"};
  return names;
}

bool PropertyField::setParameter(const std::string& name, double value) {
  double* target = name == "delta"      ? &delta
                   : name == "exponent" ? &exponent
                   : name == "angle"    ? &angle
                   : name == "position" ? &position
                   : name == "period"   ? &period
                   : name == "duty"     ? &duty
                                        : nullptr;
  if (!target) return false;
  *target = value;
  return true;
}

std::shared_ptr<const PlateFields> withParameter(const std::shared_ptr<const PlateFields>& fields,
                                                 const std::string& parameter, double value) {
  for (const std::string& name : PropertyField::scalarParameters()) {
    const std::string tail = "_" + name;
    if (parameter.size() <= tail.size() || parameter.compare(parameter.size() - tail.size(), tail.size(), tail) != 0)
      continue;
    const std::string property = parameter.substr(0, parameter.size() - tail.size());
    PlateFields copy = fields ? *fields : PlateFields{};
    const bool together = copy.muStatic && copy.muStatic == copy.muKinetic;
    std::shared_ptr<const PropertyField>* slot = property == "E"                  ? &copy.modulus
                                                 : property == "p"                ? &copy.pressure
                                                 : property == "mu" && together   ? &copy.muStatic
                                                 : property == "mu_s" && !together ? &copy.muStatic
                                                 : property == "mu_k" && !together ? &copy.muKinetic
                                                                                   : nullptr;
    if (!slot || !*slot)
      throw std::invalid_argument("a parameter of a property field the scene sets (-field_" + property +
                                  "_profile is not set)");
    PropertyField changed = **slot;
    changed.setParameter(name, value);
    changed.blameOption = "-ensemble_field_values";
    std::ostringstream v;
    v << value;
    changed.blameValue = v.str() + " (-field_" + parameter + ")";
    *slot = std::make_shared<const PropertyField>(changed);
    if (property == "mu") copy.muKinetic = copy.muStatic;
    return std::make_shared<const PlateFields>(copy);
  }
  throw std::invalid_argument("<property>_<parameter> with parameter one of delta, exponent, angle, position, period, duty");
}

}  // namespace gradfric
