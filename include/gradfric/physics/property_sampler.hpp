#pragma once
// The local factors of E, mu_s, mu_k and p at a model's sites: the property fields where the
// scene has them (field.hpp), the -grading_* bands elsewhere (exactly grading.hpp's factors, so
// the paper's gradings give the same numbers as before). A model's sites are the centres of an
// nx x ny grid of equal cells (SBM blocks, FEM bottom faces), or of the unequal cells of a mesh
// graded toward the edges (SiteGrid): mean-preserving fields are normalised over that grid, area
// weighted. PETSc-free.
#include "gradfric/physics/field.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/physics/plate.hpp"

#include <string>
#include <vector>

namespace gradfric {

// The sites of a tensor-product grid of unequal cells, over L: centres u (along x), v (along y)
// and widths du, dv (the cells' areas du dv weigh the normalisation).
struct SiteGrid {
  std::vector<double> u, du, v, dv;
};

class PropertySampler {
public:
  PropertySampler(const Grading& grading, int nx, int ny);
  PropertySampler(const Grading& grading, const SiteGrid& grid);

  // Factors at u = x / L, v = y / L (the plate's value times the factor is the local value).
  double modulus(double u, double v) const;
  double muStatic(double u, double v) const;
  double muKinetic(double u, double v) const;
  double pressure(double u, double v) const;

  bool gradesModulus() const;
  // Friction or pressure differ between sites (a friction site's strength is mu p l^2).
  bool gradesFriction() const;
  // Whether the friction strengths need one value per site rather than per column.
  bool frictionVariesAlongY() const;
  bool modulusVariesAlongY() const;

private:
  double field(const std::shared_ptr<const PropertyField>& f, double scale, double u, double v) const {
    return scale * f->profile(u, v);
  }
  const Grading& grading_;
  const PlateFields* fields_ = nullptr;
  double scaleE_ = 1.0, scaleS_ = 1.0, scaleK_ = 1.0, scaleP_ = 1.0;
};

// The first site of the nx x ny grid (row-major) where a local value leaves its range: E, mu_s, p
// positive and finite, 0 < mu_k <= mu_s. `property` names it ("E", "mu_s", "mu_k", "p"), empty if
// every site is fine.
struct SiteProblem {
  std::string property;
  std::string allowed;
  FieldViolation where;
};
SiteProblem checkSites(const Grading& grading, const Plate& plate, int nx, int ny);
// The same at the centres of the unequal cells of `grid`, sampled as the model samples them.
SiteProblem checkSites(const PropertySampler& sampler, const Plate& plate, const SiteGrid& grid);
// The centres and widths of an nx x ny grid of equal cells.
SiteGrid uniformSiteGrid(int nx, int ny);

}  // namespace gradfric
