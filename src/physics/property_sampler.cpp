#include "gradfric/physics/property_sampler.hpp"

#include <cmath>

namespace gradfric {

PropertySampler::PropertySampler(const Grading& grading, int nx, int ny)
    : grading_(grading), fields_(grading.fields.get()) {
  if (!fields_) return;
  if (fields_->modulus) scaleE_ = fields_->modulus->scaleFor(nx, ny);
  if (fields_->muStatic) scaleS_ = fields_->muStatic->scaleFor(nx, ny);
  if (fields_->muKinetic) scaleK_ = fields_->muKinetic == fields_->muStatic ? scaleS_ : fields_->muKinetic->scaleFor(nx, ny);
  if (fields_->pressure) scaleP_ = fields_->pressure->scaleFor(nx, ny);
}

PropertySampler::PropertySampler(const Grading& grading, const SiteGrid& grid)
    : grading_(grading), fields_(grading.fields.get()) {
  if (!fields_) return;
  if (fields_->modulus) scaleE_ = fields_->modulus->scaleFor(grid);
  if (fields_->muStatic) scaleS_ = fields_->muStatic->scaleFor(grid);
  if (fields_->muKinetic) scaleK_ = fields_->muKinetic == fields_->muStatic ? scaleS_ : fields_->muKinetic->scaleFor(grid);
  if (fields_->pressure) scaleP_ = fields_->pressure->scaleFor(grid);
}

double PropertySampler::modulus(double u, double v) const {
  if (fields_ && fields_->modulus) return field(fields_->modulus, scaleE_, u, v);
  return grading_.modulusFactor(u);
}

double PropertySampler::muStatic(double u, double v) const {
  if (fields_ && fields_->muStatic) return field(fields_->muStatic, scaleS_, u, v);
  return grading_.frictionFactor(u);
}

double PropertySampler::muKinetic(double u, double v) const {
  if (fields_ && fields_->muKinetic) return field(fields_->muKinetic, scaleK_, u, v);
  return grading_.frictionFactor(u);
}

double PropertySampler::pressure(double u, double v) const {
  if (fields_ && fields_->pressure) return field(fields_->pressure, scaleP_, u, v);
  return 1.0;
}

bool PropertySampler::gradesModulus() const { return (fields_ && fields_->modulus) || grading_.gradesModulus(); }

bool PropertySampler::gradesFriction() const {
  return (fields_ && (fields_->muStatic || fields_->muKinetic || fields_->pressure)) || grading_.gradesFriction();
}

bool PropertySampler::frictionVariesAlongY() const {
  if (!fields_) return false;
  for (const auto* f : {&fields_->muStatic, &fields_->muKinetic, &fields_->pressure})
    if (*f && (*f)->variesAlongY()) return true;
  return false;
}

bool PropertySampler::modulusVariesAlongY() const { return fields_ && fields_->modulus && fields_->modulus->variesAlongY(); }

SiteGrid uniformSiteGrid(int nx, int ny) {
  SiteGrid grid;
  for (int i = 0; i < nx; ++i) {
    grid.u.push_back((i + 0.5) / nx);
    grid.du.push_back(1.0 / nx);
  }
  for (int j = 0; j < ny; ++j) {
    grid.v.push_back((j + 0.5) / ny);
    grid.dv.push_back(1.0 / ny);
  }
  return grid;
}

SiteProblem checkSites(const Grading& grading, const Plate& plate, int nx, int ny) {
  return checkSites(PropertySampler(grading, nx, ny), plate, uniformSiteGrid(nx, ny));
}

SiteProblem checkSites(const PropertySampler& sampler, const Plate& plate, const SiteGrid& grid) {
  const int nx = static_cast<int>(grid.u.size()), ny = static_cast<int>(grid.v.size());
  SiteProblem problem;
  auto fail = [&](const char* property, const char* allowed, double u, double v, double value) {
    problem.property = property;
    problem.allowed = allowed;
    problem.where = FieldViolation{true, u * plate.length, v * plate.length, value};
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double u = grid.u[i], v = grid.v[j];
      const double e = plate.youngsModulus * sampler.modulus(u, v);
      const double s = plate.muStatic * sampler.muStatic(u, v);
      const double k = plate.muKinetic * sampler.muKinetic(u, v);
      const double p = plate.pressure * sampler.pressure(u, v);
      if (!(std::isfinite(e) && e > 0)) fail("E", "E > 0 [Pa] everywhere on the plate", u, v, e);
      else if (!(std::isfinite(s) && s > 0)) fail("mu_s", "mu_s > 0 everywhere on the plate", u, v, s);
      else if (!(std::isfinite(k) && k > 0)) fail("mu_k", "mu_k > 0 everywhere on the plate", u, v, k);
      else if (k > s) fail("mu_k", "mu_k <= mu_s everywhere on the plate", u, v, k);
      else if (!(std::isfinite(p) && p > 0)) fail("p", "p > 0 [Pa] everywhere on the plate", u, v, p);
      if (!problem.property.empty()) return problem;
    }
  return problem;
}

}  // namespace gradfric
