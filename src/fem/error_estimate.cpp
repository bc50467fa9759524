// The error bar of the FEM's mu_s, computed from the convergence study's own measurements
// (docs/fem_study.tsv, embedded at build time; docs/accuracy_fem.md, "Convergence of mu_s"):
//  - mesh: the run's ladder (three in-plane meshes at ratio 2, same law, D_c, grading, nz and
//    element). Only a ladder whose differences keep their sign and shrink with an observed order
//    p > 0.5 gives a bar: Roache's grid convergence index with safety factor 1.25 about the
//    Richardson extrapolation (p capped at 2, the element's order), 1.25 |mu(n) - mu_ext| / mu_ext;
//    a ladder that does not converge gives none (never a bar the study does not prove);
//  - thickness: nz 5 against 10 on the non-graded paper mesh, 1.25 |difference| / (2 - 1)
//    (first order assumed: larger than the second-order value);
//  - time step: dt_safety 0.6 against 0.3 on the same mesh, the same way (covers dt_safety <= 0.6);
//  - contact: penalty 250 G/H against the kinematic contact (the reference) on the same mesh.
// The thickness, time-step and contact terms were measured on the non-graded plate and are
// applied to the graded ones (said in the basis). The terms are added: their signs are not known.
#include "gradfric/fem/error_estimate.hpp"

#include "gradfric/fem/fem_study_data.hpp"  // generated: kFemStudyTable, the text of docs/fem_study.tsv
#include "gradfric/physics/field.hpp"
#include "gradfric/physics/state_weakening_law.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

namespace gradfric::fem {

namespace {

bool near(double a, double b) { return std::fabs(a - b) <= 1e-9 * std::fabs(b); }

struct StudyRow {
  std::string law, property, element, contact;
  double slipLength = 0, delta = 0, dtSafety = 0, mu = 0;
  int n = 0, nz = 0;
};

const std::vector<StudyRow>& studyRows() {
  static const std::vector<StudyRow> rows = [] {
    std::vector<StudyRow> parsed;
    std::istringstream table(kFemStudyTable);
    std::string line;
    while (std::getline(table, line)) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream fields(line);
      StudyRow r;
      if (fields >> r.law >> r.slipLength >> r.property >> r.delta >> r.n >> r.nz >> r.element >> r.dtSafety >> r.contact >>
          r.mu)
        parsed.push_back(r);
    }
    return parsed;
  }();
  return rows;
}

// The scene the study ran: the paper's plate, the state law, the derived pressure step, no
// damping in step 2, no property fields.
std::string outsideStudiedScene(const FemParameters& q, const Grading& g) {
  const Plate paper;
  const Plate& p = q.plate;
  if (!near(p.length, paper.length) || !near(p.thickness, paper.thickness) || !near(p.youngsModulus, paper.youngsModulus) ||
      !near(p.poissonRatio, paper.poissonRatio) || !near(p.density, paper.density) || !near(p.pressure, paper.pressure) ||
      !near(p.velocity, paper.velocity) || !near(p.muStatic, paper.muStatic) || !near(p.muKinetic, paper.muKinetic))
    return "plate other than the paper's";
  if (q.frictionLaw.name != StateWeakening::name ||
      !near(q.frictionLaw.criticalVelocity, FemParameters{}.frictionLaw.criticalVelocity))
    return "friction law other than the state law with the paper's v_c (no other law converges)";
  FemParameters derived;  // the study's pressure step: the derived ramp and hold
  derived.plate = p;
  derived.resolveDerived();
  if (!near(q.rampTime, derived.rampTime) || !near(q.settleTime, derived.settleTime) ||
      !near(q.settleDamping, derived.settleDamping))
    return "pressure step other than the derived ramp, hold and damping";
  if (q.slideDamping > 0 || q.stiffnessDamping > 0 || q.bulkLinear > 0 || q.bulkQuadratic > 0)
    return "damping while sliding";
  if (g.fields && g.fields->any()) return "property fields";
  if (!q.contact) return "no contact";
  if (g.active() && (g.profile != GradingProfile::Linear || g.property == GradedProperty::Both))
    return "grading other than linear E or friction";
  if (q.plate.slidingAngle != 0.0) return "sliding angle other than 0";
  if (q.nx != q.ny) return "nx != ny";
  return "";
}

std::string gradingName(const Grading& g) {
  if (!g.active()) return "none";
  return g.property == GradedProperty::YoungsModulus ? "E" : "friction";
}

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f %%", 100 * fraction);
  return text;
}

// The study's mu_s for the settings given (nullptr: not run).
const StudyRow* find(const FemParameters& q, const std::string& property, double delta, int n, int nz,
                     double dtSafety, const char* contact) {
  for (const StudyRow& r : studyRows())
    if (r.law == q.frictionLaw.name && near(r.slipLength, q.frictionLaw.slipLength) && r.property == property &&
        std::fabs(r.delta - delta) < 1e-9 && r.n == n && r.nz == nz && r.element == elementTypeName(q.element) &&
        std::fabs(r.dtSafety - dtSafety) < 1e-9 && r.contact == contact)
      return &r;
  return nullptr;
}

ErrorTerm meshTerm(const FemParameters& q, const Grading& g) {
  const std::string property = gradingName(g);
  const double delta = g.active() ? g.delta : 0.0;
  // The ladder n, 2n, 4n holding the run's mesh: first the one in which it is the finest mesh.
  for (int coarsest : {q.nx / 4, q.nx / 2, q.nx}) {
    if (coarsest < 1 || (q.nx % coarsest) != 0) continue;
    const StudyRow* m[3];
    bool complete = true;
    for (int k = 0; k < 3; ++k)
      complete = complete && (m[k] = find(q, property, delta, coarsest << k, q.nz, 0.6, "penalty")) != nullptr;
    if (!complete) continue;
    const double coarse = m[0]->mu, medium = m[1]->mu, fine = m[2]->mu;
    char text[300];
    const double first = medium - coarse, second = fine - medium;
    if (!(first * second > 0) || !(std::fabs(second) < std::fabs(first) / std::sqrt(2.0))) {
      std::snprintf(text, sizeof text,
                    "mesh not converged: %dx%d/%d/%d x %d give %.6f, %.6f, %.6f (differences %+.2f %%, %+.2f %%: %s)",
                    coarsest, coarsest, 2 * coarsest, 4 * coarsest, q.nz, coarse, medium, fine, 100 * first / coarse,
                    100 * second / medium, first * second > 0 ? "observed order <= 0.5" : "they change sign");
      return {false, 0, text};
    }
    const double order = std::log(first / second) / std::log(2.0);
    const double used = std::min(order, 2.0);
    const double extrapolated = fine + second / (std::pow(2.0, used) - 1.0);
    const double run = q.nx == coarsest ? coarse : q.nx == 2 * coarsest ? medium : fine;
    const double bound = 1.25 * std::fabs(run - extrapolated) / std::fabs(extrapolated);
    std::snprintf(text, sizeof text,
                  "%dx%d/%d/%d x %d: %.6f, %.6f, %.6f, observed order %.2f, extrapolated %.6f, GCI of %dx%d %s",
                  coarsest, coarsest, 2 * coarsest, 4 * coarsest, q.nz, coarse, medium, fine, order, extrapolated, q.nx,
                  q.nx, percent(bound).c_str());
    return {true, bound, text};
  }
  char text[200];
  std::snprintf(text, sizeof text, "mesh %dx%dx%d %s (%s) not in the mesh study", q.nx, q.ny, q.nz,
                elementTypeName(q.element), g.active() ? "graded" : "non-graded");
  return {false, 0, text};
}

// A pair measured on the non-graded plate: 1.25 |reference - setting| / |reference| (divided by
// r^p - 1 = 1 for a refinement pair: first order assumed).
ErrorTerm pairTerm(const StudyRow* setting, const StudyRow* reference, const char* what) {
  if (!setting || !reference) return {false, 0, std::string(what) + " not measured for this D_c and mesh"};
  const double bound = 1.25 * std::fabs(setting->mu - reference->mu) / std::fabs(reference->mu);
  char text[200];
  std::snprintf(text, sizeof text, "%s %.6f vs %.6f (non-graded %dx%d)", what, setting->mu, reference->mu, setting->n,
                setting->n);
  return {true, bound, text};
}

ErrorTerm thicknessTerm(const FemParameters& q) {
  if (q.nz != 5) return {false, 0, "nz other than 5 (the thickness study: 5 against 10)"};
  return pairTerm(find(q, "none", 0, 100, 5, 0.6, "penalty"), find(q, "none", 0, 100, 10, 0.6, "penalty"),
                  "thickness nz 5 vs 10:");
}

ErrorTerm timeStepTerm(const FemParameters& q, double dtRatio) {
  if (dtRatio > 0.6 + 1e-9) return {false, 0, "dt above 0.6 of the stable step"};
  return pairTerm(find(q, "none", 0, 100, 5, 0.6, "penalty"), find(q, "none", 0, 100, 5, 0.3, "penalty"),
                  "dt_safety 0.6 vs 0.3:");
}

ErrorTerm contactTerm(const FemParameters& q) {
  if (q.contactMethod == ContactMethod::Kinematic) return {true, 0.0, "kinematic contact (the reference)"};
  const double defaultStiffness = FemParameters::penaltyFactor * q.plate.shearModulus() / q.plate.thickness;
  if (!near(q.kn, defaultStiffness) || !near(q.kt, defaultStiffness))
    return {false, 0, "penalty stiffness other than 250 G/H"};
  return pairTerm(find(q, "none", 0, 100, 5, 0.6, "penalty"), find(q, "none", 0, 100, 5, 0.6, "kinematic"),
                  "penalty vs kinematic:");
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
  e.thickness = thicknessTerm(q);
  e.timeStep = timeStepTerm(q, dtRatio);
  e.contact = contactTerm(q);
  const ErrorTerm* terms[] = {&e.mesh, &e.thickness, &e.timeStep, &e.contact};
  e.measured = std::all_of(std::begin(terms), std::end(terms), [](const ErrorTerm* t) { return t->measured; });
  if (e.measured) {
    e.relative = e.mesh.relative + e.thickness.relative + e.timeStep.relative + e.contact.relative;
    e.basis = "mesh " + percent(e.mesh.relative) + ", thickness " + percent(e.thickness.relative) + ", dt " +
              percent(e.timeStep.relative) + ", contact " + percent(e.contact.relative) + "; " + e.mesh.basis +
              (g.active() ? "; thickness, dt and contact terms of the non-graded plate" : "");
  } else {
    for (const ErrorTerm* t : terms)
      if (!t->measured) {
        e.basis = t->basis;
        break;
      }
  }
  e.kineticBasis = "no convergence study of mu_k with the state law yet";
  return e;
}

std::string withErrorBar(double mu, const DiscretisationError& e) {
  char text[600];
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
