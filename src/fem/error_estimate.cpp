// The measured error bar of the FEM's mu_s (docs/accuracy_fem.md, "Error bar"). Three terms, each
// the largest difference measured against a finer setting of the same scene:
//  - mesh: the element study (q1/q1i, 25/50/100 in-plane, 5/10 through the thickness), the one
//    200 x 200 x 10 run and the graded convergence study (linear E or friction grading, Delta +-0.2
//    and +-0.4, triangular E +-0.2, friction +0.2 at 90 degrees: 50/100/200 in-plane, nz 5/10), for
//    the paper's plate, non-graded or graded where graded runs were made (a bar holds for
//    |Delta| up to the largest studied, and is the largest of the studied points it covers);
//  - time step: the gfverlet dt ladders (50x50x2 and the paper mesh): 0.1 % at dt_safety <= 0.3,
//    0.4 % at <= 0.6 (the default), 1.0 % at <= 0.9;
//  - contact: 0 for the kinematic contact (the reference), 0.4 % for the default penalty
//    k_n = k_t = 250 G/H (against the kinematic contact), other stiffnesses not measured.
// The terms are added (their signs are not known). Anything outside these settings is "not
// measured"; so is mu_k (its bar is the steady window's spread; two meshes, no dt study).
#include "gradfric/fem/error_estimate.hpp"

#include "gradfric/physics/field.hpp"

#include <cmath>
#include <cstdio>

namespace gradfric::fem {

namespace {

bool near(double a, double b) { return std::fabs(a - b) <= 1e-9 * std::fabs(b); }

// The scene the studies ran: the paper's plate and friction law, sliding along the grading axis,
// no damping in step 2, no property fields.
std::string outsideStudiedScene(const FemParameters& q, const Grading& g) {
  const Plate paper;
  const Plate& p = q.plate;
  if (!near(p.length, paper.length) || !near(p.thickness, paper.thickness) || !near(p.youngsModulus, paper.youngsModulus) ||
      !near(p.poissonRatio, paper.poissonRatio) || !near(p.density, paper.density) || !near(p.pressure, paper.pressure) ||
      !near(p.velocity, paper.velocity) || !near(p.muStatic, paper.muStatic) || !near(p.muKinetic, paper.muKinetic) ||
      !near(q.frictionLaw.criticalVelocity, FemParameters{}.frictionLaw.criticalVelocity))
    return "plate or friction law other than the paper's";
  FemParameters derived;  // the studies' pressure step: the derived ramp and hold
  derived.plate = p;
  derived.resolveDerived();
  if (!near(q.rampTime, derived.rampTime) || !near(q.settleTime, derived.settleTime) ||
      !near(q.settleDamping, derived.settleDamping))
    return "pressure step other than the derived ramp, hold and damping";
  if (q.slideDamping > 0 || q.stiffnessDamping > 0 || q.bulkLinear > 0 || q.bulkQuadratic > 0)
    return "damping while sliding";
  if (g.fields && g.fields->any()) return "property fields";
  if (!q.contact) return "no contact";
  return "";
}

// The studied gradings: linear E or friction up to |Delta| 0.2 and from 0.2 to 0.4 (sliding along
// the grading), triangular E up to 0.2, and linear friction up to 0.2 sliding across the grading
// (90 degrees: +Delta and -Delta are mirror images there, so the +0.2 run measures both).
enum class GradingClass {
  None, ModulusLinear, FrictionLinear, ModulusLinearLarge, FrictionLinearLarge, ModulusTriangular,
  FrictionAcross, OtherAngle, Other
};

GradingClass classify(const Grading& g, double slidingAngle) {
  if (!g.active()) return slidingAngle == 0.0 ? GradingClass::None : GradingClass::OtherAngle;
  if (g.property == GradedProperty::Both) return GradingClass::Other;
  const bool modulus = g.property == GradedProperty::YoungsModulus, linear = g.profile == GradingProfile::Linear;
  const bool small = std::fabs(g.delta) <= 0.2 + 1e-12, large = std::fabs(g.delta) <= 0.4 + 1e-12;
  if (slidingAngle == 90.0) return !modulus && linear && small ? GradingClass::FrictionAcross : GradingClass::OtherAngle;
  if (slidingAngle != 0.0) return GradingClass::OtherAngle;
  if (g.profile == GradingProfile::Triangular) return modulus && small ? GradingClass::ModulusTriangular : GradingClass::Other;
  if (!linear || !large) return GradingClass::Other;
  if (small) return modulus ? GradingClass::ModulusLinear : GradingClass::FrictionLinear;
  return modulus ? GradingClass::ModulusLinearLarge : GradingClass::FrictionLinearLarge;
}

// Which runs a row of the mesh study holds for.
enum class RowGrading { None, Modulus, Friction, AnyLinear, ModulusLarge, FrictionLarge, ModulusTriangular, FrictionAcross };

bool holdsFor(RowGrading row, GradingClass g) {
  switch (row) {
    case RowGrading::None: return g == GradingClass::None;
    case RowGrading::Modulus: return g == GradingClass::ModulusLinear;
    case RowGrading::Friction: return g == GradingClass::FrictionLinear;
    case RowGrading::AnyLinear: return g == GradingClass::ModulusLinear || g == GradingClass::FrictionLinear;
    case RowGrading::ModulusLarge: return g == GradingClass::ModulusLinearLarge;
    case RowGrading::FrictionLarge: return g == GradingClass::FrictionLinearLarge;
    case RowGrading::ModulusTriangular: return g == GradingClass::ModulusTriangular;
    case RowGrading::FrictionAcross: return g == GradingClass::FrictionAcross;
  }
  return false;
}

struct MeshRow {
  int nx, ny, nz;
  ElementType element;
  RowGrading grading;  // linear grading rows hold for |Delta| <= 0.2 (runs at 0 and +-0.2)
  double relative;
  const char* basis;
};

// docs/accuracy_fem.md, "Element and mesh", "The one run of 200 x 200 x 10" and "Graded
// convergence" (the non-graded 100 and 50 rows: its runs at the current penalty, 50/100/200 x 5,
// whose differences grow, plus the thickness term of the element study). The first row that holds wins.
const MeshRow kMeshRows[] = {
    {100, 100, 5, ElementType::Trilinear, RowGrading::None, 0.057,
     "100x100x5 q1: 200x200x5 +5.3 % (differences grow from 50), 100x100x10 -0.48 % (old penalty)"},
    {100, 100, 5, ElementType::Trilinear, RowGrading::Modulus, 0.057,
     "100x100x5 q1, E grading: 200x200x5 +5.7 % (differences grow: a lower bound) and 100x100x10 +0.04 % (Delta -0.2; +0.2: 1.5 %)"},
    {100, 100, 5, ElementType::Trilinear, RowGrading::Friction, 0.071,
     "100x100x5 q1, friction grading: Richardson 50/100/200x5 6.8 % and 100x100x10 +0.26 % (Delta -0.2; +0.2: >= 1.7 %)"},
    {100, 100, 5, ElementType::Trilinear, RowGrading::ModulusLarge, 0.065,
     "100x100x5 q1, E grading 0.2 < |Delta| <= 0.4: 200x200x5 +6.08 % (no extrapolation: a lower bound) (Delta -0.4); thickness 0.37 % (largest of +-0.2)"},
    {100, 100, 5, ElementType::Trilinear, RowGrading::FrictionLarge, 0.116,
     "100x100x5 q1, friction grading 0.2 < |Delta| <= 0.4: 200x200x5 +11.22 % (no extrapolation: a lower bound) (Delta -0.4); thickness 0.37 % (largest of +-0.2)"},
    {100, 100, 5, ElementType::Trilinear, RowGrading::ModulusTriangular, 0.058,
     "100x100x5 q1, triangular E grading: 200x200x5 +5.40 % (no extrapolation: a lower bound) (Delta -0.2); thickness 0.37 % (largest of +-0.2)"},
    {100, 100, 5, ElementType::Trilinear, RowGrading::FrictionAcross, 0.010,
     "100x100x5 q1, friction grading at 90 degrees: Richardson 50/100/200x5 0.61 % (Delta 0.2); thickness 0.37 % (largest of +-0.2)"},
    {50, 50, 5, ElementType::Trilinear, RowGrading::Modulus, 0.094, "50x50x5 q1, E grading: 200x200x5 +9.4 % (Delta -0.2)"},
    {50, 50, 5, ElementType::Trilinear, RowGrading::Friction, 0.088,
     "50x50x5 q1, friction grading: 200x200x5 +8.8 % (Delta -0.2)"},
    {50, 50, 5, ElementType::Trilinear, RowGrading::None, 0.114, "50x50x5 q1: 200x200x5 +9.3 %, 50x50x10 +2.1 % (old penalty)"},
    {25, 25, 5, ElementType::Trilinear, RowGrading::None, 0.031, "25x25x5 q1: 50x50x10 +3.1 %, 50x50x5 +1.0 %"},
    {25, 25, 5, ElementType::Trilinear, RowGrading::AnyLinear, 0.033, "25x25x5 q1, graded: 50x50x5 up to 3.3 %"},
    {50, 50, 10, ElementType::Trilinear, RowGrading::None, 0.029, "50x50x10 q1: 100x100x10 -2.9 %"},
    {25, 25, 10, ElementType::Trilinear, RowGrading::None, 0.031, "25x25x10 q1: 50x50x10 +3.1 %"},
    {100, 100, 5, ElementType::IncompatibleModes, RowGrading::None, 0.015, "100x100x5 q1i: q1 100x100x10 -1.5 %"},
    {50, 50, 5, ElementType::IncompatibleModes, RowGrading::None, 0.015,
     "50x50x5 q1i: 100x100x5 q1i -1.5 %, 50x50x10 q1i -0.1 %"},
    {25, 25, 5, ElementType::IncompatibleModes, RowGrading::None, 0.056, "25x25x5 q1i: 50x50x5 q1i +5.6 %"},
    {25, 25, 5, ElementType::IncompatibleModes, RowGrading::AnyLinear, 0.035,
     "25x25x5 q1i, graded: 50x50x5 q1i up to 3.5 %"},
};

ErrorTerm meshTerm(const FemParameters& q, const Grading& g) {
  const GradingClass grading = classify(g, q.plate.slidingAngle);
  if (grading == GradingClass::OtherAngle)
    return {false, 0, "sliding angle other than 0 (or 90 with linear friction grading, |Delta| <= 0.2)"};
  if (grading == GradingClass::Other)
    return {false, 0, "grading other than linear E or friction with |Delta| <= 0.4, or triangular E with |Delta| <= 0.2"};
  for (const MeshRow& row : kMeshRows) {
    if (row.nx != q.nx || row.ny != q.ny || row.nz != q.nz || row.element != q.element) continue;
    if (!holdsFor(row.grading, grading)) continue;
    return {true, row.relative, row.basis};
  }
  char text[160];
  std::snprintf(text, sizeof text, "mesh %dx%dx%d %s%s not in the mesh study", q.nx, q.ny, q.nz,
                elementTypeName(q.element), grading == GradingClass::None ? "" : " (graded)");
  return {false, 0, text};
}

ErrorTerm timeStepTerm(double dtRatio) {
  if (dtRatio <= 0.3 + 1e-9) return {true, 0.001, "dt_safety <= 0.3: 0.1 %"};
  if (dtRatio <= 0.6 + 1e-9) return {true, 0.004, "dt_safety <= 0.6: 0.4 %"};
  if (dtRatio <= 0.9 + 1e-9) return {true, 0.010, "dt_safety <= 0.9: 1.0 %"};
  return {false, 0, "dt above 0.9 of the stable step"};
}

ErrorTerm contactTerm(const FemParameters& q) {
  if (q.contactMethod == ContactMethod::Kinematic) return {true, 0.0, "kinematic contact (the reference)"};
  const double defaultStiffness = FemParameters::penaltyFactor * q.plate.shearModulus() / q.plate.thickness;
  if (near(q.kn, defaultStiffness) && near(q.kt, defaultStiffness))
    return {true, 0.004, "penalty 250 G/H vs kinematic: 0.4 %"};
  return {false, 0, "penalty stiffness other than 250 G/H"};
}

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", 100 * fraction);
  return text;
}

}  // namespace

DiscretisationError discretisationError(const FemParameters& q, const Grading& g, double dtRatio) {
  DiscretisationError e;
  const std::string outside = outsideStudiedScene(q, g);
  if (!outside.empty()) {
    e.basis = e.kineticBasis = outside;
    return e;
  }
  e.mesh = meshTerm(q, g);
  e.timeStep = timeStepTerm(dtRatio);
  e.contact = contactTerm(q);
  e.measured = e.mesh.measured && e.timeStep.measured && e.contact.measured;
  if (e.measured) {
    e.relative = e.mesh.relative + e.timeStep.relative + e.contact.relative;
    e.basis = "mesh " + percent(e.mesh.relative) + ", dt " + percent(e.timeStep.relative) + ", contact " +
              percent(e.contact.relative) + "; " + e.mesh.basis;
  } else {
    for (const ErrorTerm* t : {&e.mesh, &e.timeStep, &e.contact})
      if (!t->measured) {
        e.basis = t->basis;
        break;
      }
  }
  // The steady window's mu_k (docs/accuracy_fem.md, "Graded convergence"): two meshes, no dt study.
  e.kineticBasis = "mu_k's bar is its window's spread; 50x50x5 and 100x100x5 agree within 0.01 % (Delta 0, +-0.2), "
                   "no dt study";
  return e;
}

std::string withErrorBar(double mu, const DiscretisationError& e) {
  char text[400];
  if (e.measured)
    std::snprintf(text, sizeof text, "%.6f +- %s (discretisation: %s)", mu, percent(e.relative).c_str(), e.basis.c_str());
  else
    std::snprintf(text, sizeof text, "%.6f (discretisation error not measured: %s)", mu, e.basis.c_str());
  return text;
}

std::string withKineticErrorBar(double mu, const DiscretisationError& e) {
  char text[300];
  std::snprintf(text, sizeof text, "%.6f (discretisation error not measured: %s)", mu, e.kineticBasis.c_str());
  return text;
}

}  // namespace gradfric::fem
