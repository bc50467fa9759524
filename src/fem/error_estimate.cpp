// The error bar of the FEM's mu_s, computed from the convergence study's own measurements
// (docs/fem_study.tsv, embedded at build time; docs/accuracy_fem.md, "Convergence of mu_s"):
//  - mesh: the run's ladder (three in-plane meshes at ratio 2, same law, D_c, grading, nz and
//    element). Only a ladder whose differences shrink (an observed order p > 0.5) gives a bar
//    (ladderTerm): Roache's grid convergence index with safety factor 1.25 about the Richardson
//    extrapolation when they keep their sign, the bracket of the last two values when they
//    alternate; a ladder that does not converge gives none (never a bar the study does not prove).
//    A ladder refined in every direction (50x50x5, 100x100x10, 200x200x20) is preferred: it bounds
//    the thickness as well. Of several ladders holding the run's mesh, the finest is taken, and
//    every finer ladder of the study must converge too;
//  - thickness (for an in-plane ladder), time step and contact: thickness_dt_contact_terms.hpp.
// The thickness, time-step and contact terms were measured on the non-graded plate and are
// applied to the graded ones (said in the basis). The terms are added: their signs are not known.
// A uniform run's mesh bound is then checked against the meshes graded toward the edges, which can
// refute it or bound the run where its own ladders prove nothing (edge_graded_bounds.hpp).
#include "gradfric/fem/error_estimate.hpp"

#include "gradfric/core/data_table.hpp"
#include "gradfric/core/refinement_ladder.hpp"
#include "gradfric/fem/edge_graded_bounds.hpp"
#include "gradfric/fem/fem_study_data.hpp"  // generated: kFemStudyTable, the text of docs/fem_study.tsv
#include "gradfric/fem/kinetic_error_estimate.hpp"
#include "gradfric/fem/ladder_term.hpp"
#include "gradfric/fem/study_table.hpp"
#include "gradfric/fem/thickness_dt_contact_terms.hpp"
#include "gradfric/physics/field.hpp"
#include "gradfric/physics/state_weakening_law.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace gradfric::fem {

namespace {

// The scene the study ran: the paper's plate, the state law, the derived pressure step, no
// damping in step 2, no property fields.
std::string outsideStudiedScene(const FemParameters& q, const Grading& g) {
  const std::string plate = differenceFromPapersPlate(q.plate, PlateThickness::Compared);
  if (!plate.empty()) return plate;
  if (q.frictionLaw.name != StateWeakening::name ||
      !sameStudiedValue(q.frictionLaw.criticalVelocity, FemParameters{}.frictionLaw.criticalVelocity))
    return "friction law other than the state law with the paper's v_c (no other law converges)";
  const FemParameters derived(q.plate);  // the study's pressure step: the derived ramp and hold
  if (!sameStudiedValue(q.rampTime, derived.rampTime) || !sameStudiedValue(q.settleTime, derived.settleTime) ||
      !sameStudiedValue(q.settleDamping, derived.settleDamping))
    return "pressure step other than the derived ramp, hold and damping";
  if (q.slideDamping > 0 || q.stiffnessDamping > 0 || q.bulkLinear > 0 || q.bulkQuadratic > 0)
    return "damping while sliding";
  if (g.fields && g.fields->any()) return "property fields";
  if (!q.contact) return "no contact";
  if (g.active() && g.property == GradedProperty::Both) return "grading of E and friction together";
  if (q.nx != q.ny) return "nx != ny";
  return "";
}

// The mesh ladder of one kind holding the run's mesh: refined in every direction (n x n x nz, 2n x 2n x
// 2nz, 4n x 4n x 4nz) or in-plane (n, 2n, 4n at the run's nz). Of those holding the run's mesh, the
// finest: the three finest meshes are the likeliest to lie in the asymptotic range (Roache). Every
// finer ladder the study has must converge as well (core/refinement_ladder.hpp, walkFinerLadders).
struct MeshLadder {
  bool held = false;  // the study holds a ladder of this kind with the run's mesh
  ErrorTerm term;     // its bound of the run's mesh, or why none
  const StudyRow* rows[3] = {nullptr, nullptr, nullptr};
  int member = 0;     // the run's mesh in rows
};

// The mesh refined each direction apart: the in-plane ladder at the run's nz and the thickness
// ladder at its in-plane mesh (and the finer ones), whose bounds add.
struct DirectionsApart {
  ErrorTerm inPlane, thickness;
  bool measured() const { return inPlane.measured && thickness.measured; }
  double relative() const { return inPlane.relative + thickness.relative; }
  std::string whyNot() const {  // the reasons of the terms without a bound
    if (!inPlane.measured && !thickness.measured) return inPlane.basis + "; " + thickness.basis;
    return inPlane.measured ? thickness.basis : inPlane.basis;
  }
};

struct DirectionsTest {
  bool passed = false;
  std::string text;
};

// The bounds the study's rows prove (the embedded docs/fem_study.tsv, or another table for tests).
class StudyBounds {
public:
  explicit StudyBounds(const std::vector<StudyRow>& rows) : rows_(rows) {}
  DiscretisationError discretisationError(const FemParameters& q, const Grading& g, double dtRatio) const;

private:
  MeshLadder meshLadder(const FemParameters& q, const Grading& g, bool allDirections) const;
  DirectionsApart eachDirectionApart(const FemParameters& q, const Grading& g) const;
  DirectionsTest testDirectionsApart(const FemParameters& q, const Grading& g, const MeshLadder& all,
                                     const DirectionsApart& run) const;

  const std::vector<StudyRow>& rows_;
};

std::string meshName(const FemParameters& q) {
  char text[200] = "";
  if (!q.edge.uniform()) std::snprintf(text, sizeof text, " edge-graded (ratio %g, band %g m)", q.edge.ratio, q.edge.band);
  if (q.normalFilter.active())
    std::snprintf(text + std::strlen(text), sizeof text - std::strlen(text), " with the Prakash-Clifton filter (L %g m, V* %g m/s)",
                  q.normalFilter.length, q.normalFilter.speed);
  return text;
}

MeshLadder StudyBounds::meshLadder(const FemParameters& q, const Grading& g, bool allDirections) const {
  const StudySettings settings = meshStudySettings(q, g);
  // The ladder whose coarsest mesh is n x n x nz (nz doubling with n when refined in every direction).
  const auto findLadder = [&](int n, int nz, const StudyRow* (&m)[3]) {
    return findMeshLadder(rows_, q, settings, n, nz, allDirections, m);
  };
  const auto ladderName = [&](int n, int nz) {
    char run[80];
    if (allDirections)
      std::snprintf(run, sizeof run, ", all directions (run %dx%dx%d)", q.nx, q.nx, q.nz);
    else
      std::snprintf(run, sizeof run, " (run %dx%d)", q.nx, q.nx);
    return ladderMeshes(n, nz, allDirections) + meshName(q) + run;
  };
  MeshLadder ladder;
  for (int member = 0; member <= 2; ++member) {
    const int coarsest = q.nx >> member, coarsestNz = allDirections ? q.nz >> member : q.nz;
    if (coarsest < 1 || (coarsest << member) != q.nx) continue;
    if (allDirections && (coarsestNz < 1 || (coarsestNz << member) != q.nz)) continue;
    if (!findLadder(coarsest, coarsestNz, ladder.rows)) continue;
    ladder.held = true;
    ladder.member = member;
    // The ladder starting at in-plane mesh `first` (its nz scaled alike when refined in every direction).
    const auto nzOf = [&](int first) { return allDirections ? coarsestNz * (first / coarsest) : q.nz; };
    const StudyRow* f[3];
    ErrorTerm check;
    const FinerLadders finer = walkFinerLadders(
        coarsest, [&](int first) { return findLadder(first, nzOf(first), f); },
        [&](int first) { return !(check = ladderTerm("mesh", ladderName(first, nzOf(first)), f, 0)).measured; });
    if (finer.disproving) {
      ladder.term = {false, 0, check.basis + "; so the coarser " + ladderName(coarsest, coarsestNz) + " proves no bar"};
      return ladder;
    }
    const ErrorTerm own = ladderTerm("mesh", ladderName(coarsest, coarsestNz), ladder.rows, member);
    if (own.measured || finer.finest == coarsest) {
      ladder.term = own;
      return ladder;
    }
    const int finest = finer.finest;
    findLadder(finest, nzOf(finest), f);  // the walk's last probe (one finer) left f partly filled
    ladder.term =
        throughFinerValue("mesh", own, ladder.rows[member]->mu, ladderTerm("mesh", ladderName(finest, nzOf(finest)), f, 2), f[2]->mu);
    return ladder;
  }
  return ladder;
}

// For a filtered run: whether its time-step and contact terms were measured with its filter.
std::string filterOfTerms(const FemParameters& q, const ErrorTerm& timeStep, const ErrorTerm& contact) {
  if (!q.normalFilter.active()) return "";
  if (timeStep.filtered && contact.filtered) return " with the filter";
  if (!timeStep.filtered && !contact.filtered) return " without the filter";
  return timeStep.filtered ? " (dt with the filter, contact without)" : " (contact with the filter, dt without)";
}

// The in-plane mesh term where the study holds no ladder of the run's mesh.
ErrorTerm notInTheStudy(const FemParameters& q, const Grading& g) {
  const StudiedPlate plate = studiedPlate(g, q.plate.slidingAngle);
  char name[80];
  if (g.active())
    std::snprintf(name, sizeof name, "%s %+g", plate.property.c_str(), plate.delta);
  else  // "none" or "none,theta=90"
    std::snprintf(name, sizeof name, "non-graded%s", plate.property.substr(4).c_str());
  char text[300];
  std::snprintf(text, sizeof text, "mesh %dx%dx%d%s %s (%s) not in the mesh study", q.nx, q.ny, q.nz,
                meshName(q).c_str(), elementTypeName(q.element), name);
  return {false, 0, text};
}

DirectionsApart StudyBounds::eachDirectionApart(const FemParameters& q, const Grading& g) const {
  const MeshLadder inPlane = meshLadder(q, g, false);
  return {inPlane.held ? inPlane.term : notInTheStudy(q, g), thicknessTerm(rows_, q, g)};
}

// Refined each direction apart, the bar assumes that the in-plane and the thickness errors add (the
// thickness error measured on the run's in-plane mesh and the finer ones, not on the limit). Where
// the ladder refined in every direction holds the run but does not converge, its other meshes test
// that: each bounded the same way must share a limit with the run (core shareALimit), and at least
// one must be bounded, or the assumption is untested. Returns the test, and whether it passed.
DirectionsTest StudyBounds::testDirectionsApart(const FemParameters& q, const Grading& g, const MeshLadder& all,
                                                const DirectionsApart& run) const {
  std::vector<BoundedValue> values{{all.rows[all.member]->mu, run.relative()}};
  std::string others;
  for (int k = 0; k < 3; ++k) {
    if (k == all.member) continue;
    FemParameters other = q;
    other.nx = other.ny = all.rows[k]->n;
    other.nz = all.rows[k]->nz;
    const DirectionsApart apart = eachDirectionApart(other, g);
    if (!apart.measured()) continue;
    values.push_back({all.rows[k]->mu, apart.relative()});
    char text[120];
    std::snprintf(text, sizeof text, "%s%dx%dx%d %.6f +- %s", others.empty() ? "" : ", ", other.nx, other.nx, other.nz,
                  all.rows[k]->mu, percentText(apart.relative()).c_str());
    others += text;
  }
  if (values.size() < 2)
    return {false, "no other mesh of the ladder refined in every direction is bounded each direction apart, so "
                   "their sum is untested"};
  if (!shareALimit(values.data(), int(values.size())))
    return {false, "bounded the same way, " + others + " share no limit with the run's " + percentText(run.relative()) +
                       ": the in-plane and thickness errors do not add"};
  return {true, "tested against the ladder refined in every direction: " + others + " share a limit with the run"};
}

DiscretisationError StudyBounds::discretisationError(const FemParameters& q, const Grading& g, double dtRatio) const {
  DiscretisationError e;
  const std::string outside = outsideStudiedScene(q, g);
  if (!outside.empty()) {
    e.basis = e.kineticBasis = outside;
    return e;
  }
  // The ladder refined in every direction first: it bounds the thickness too. Where the study holds
  // none with the run's mesh, each direction apart; where it holds one that does not converge, each
  // direction apart if that is measured and passes the ladder's test (refined together, in-plane and
  // thickness errors of opposite signs can keep a ladder out of its asymptotic range).
  const MeshLadder all = meshLadder(q, g, true);
  bool coversThickness = all.held;
  const ErrorTerm inTheLadder{true, 0.0, "in the mesh ladder (all directions refined)", q.normalFilter.active()};
  if (all.held && all.term.measured) {
    e.mesh = all.term;
    e.thickness = inTheLadder;
  } else {
    const DirectionsApart apart = eachDirectionApart(q, g);
    if (!all.held) {
      e.mesh = apart.inPlane;
      e.thickness = apart.thickness;
    } else {
      const DirectionsTest test = apart.measured() ? testDirectionsApart(q, g, all, apart) : DirectionsTest{};
      coversThickness = !test.passed;
      if (test.passed) {
        e.mesh = apart.inPlane;
        e.mesh.basis = all.term.basis + "; each direction apart, " + apart.inPlane.basis + " (" + test.text + ")";
        e.thickness = apart.thickness;
      } else {
        e.mesh = all.term;
        e.mesh.basis += "; each direction apart: " + (apart.measured() ? test.text : apart.whyNot());
        e.thickness = inTheLadder;
      }
    }
  }
  // The second mesh family checks the first (edge_graded_bounds.hpp): a uniform run's study row
  // against the converging ladders graded toward the edges of its plate.
  const StudyRow* run = q.edge.uniform() ? findStudyRow(rows_, q, meshStudySettings(q, g), q.nx, q.nz) : nullptr;
  const std::vector<GradedLadder> graded = run ? edgeGradedLadders(rows_, q, g) : std::vector<GradedLadder>{};
  if (run && e.mesh.measured && e.thickness.measured) {  // the run's bound from its own family, both directions
    ErrorTerm own = e.mesh;
    own.relative += coversThickness ? 0.0 : e.thickness.relative;
    const std::string refuted = refutedByEdgeGradedLadder(*run, graded, own);
    if (!refuted.empty()) e.mesh = {false, 0, refuted};
  }
  if (run && (!e.mesh.measured || !e.thickness.measured)) {
    const ErrorTerm through = throughEdgeGradedLadder(*run, graded, q);
    if (through.measured) {
      const std::string own = e.mesh.measured ? e.thickness.basis : e.mesh.basis;
      e.mesh = through;
      e.mesh.basis = "own ladders prove none (" + own + "); " + through.basis;
      e.thickness = inTheLadder;
      coversThickness = true;
    }
  }
  if (!e.mesh.measured)  // the graded ladders run for this plate, which prove nothing either
    for (const GradedLadder& ladder : graded)
      if (!ladder.term.measured) e.mesh.basis += "; " + ladder.term.basis;
  e.timeStep = timeStepTerm(rows_, q, dtRatio);
  e.contact = contactTerm(rows_, q);
  const ErrorTerm* terms[] = {&e.mesh, &e.thickness, &e.timeStep, &e.contact};
  e.measured = std::all_of(std::begin(terms), std::end(terms), [](const ErrorTerm* t) { return t->measured; });
  if (e.measured) {
    e.relative = e.mesh.relative + e.thickness.relative + e.timeStep.relative + e.contact.relative;
    e.basis = "mesh " + percentText(e.mesh.relative) + ", thickness " + percentText(e.thickness.relative) + ", dt " +
              percentText(e.timeStep.relative) + ", contact " + percentText(e.contact.relative) + "; " + e.mesh.basis +
              (coversThickness ? "" : "; " + e.thickness.basis) +
              (g.active() || q.normalFilter.active()
                   ? "; dt and contact terms of the non-graded 100x100 plate" + filterOfTerms(q, e.timeStep, e.contact)
                   : "");
  } else {
    for (const ErrorTerm* t : terms)  // every term without a bound, each with its reason
      if (!t->measured) e.basis += (e.basis.empty() ? "" : "; ") + t->basis;
  }
  e.kineticBasis = kineticErrorBasis(q, g, dtRatio);
  return e;
}

}  // namespace

DiscretisationError discretisationError(const FemParameters& q, const Grading& g, double dtRatio) {
  static const std::vector<StudyRow> rows = parseStudyTable(kFemStudyTable);
  return StudyBounds(rows).discretisationError(q, g, dtRatio);
}

DiscretisationError discretisationError(const FemParameters& q, const Grading& g, double dtRatio,
                                        const std::string& studyTable) {
  const std::vector<StudyRow> rows = parseStudyTable(studyTable);
  return StudyBounds(rows).discretisationError(q, g, dtRatio);
}

std::string withErrorBar(double mu, const DiscretisationError& e) {
  char value[32];
  std::snprintf(value, sizeof value, "%.6f", mu);
  if (e.measured) return std::string(value) + " +- " + percentText(e.relative) + " (discretisation: " + e.basis + ")";
  return std::string(value) + " (discretisation error not measured: " + e.basis + ")";
}

std::string withKineticErrorBar(double mu, const DiscretisationError& e) {
  char text[300];
  std::snprintf(text, sizeof text, "%.6f (discretisation error not measured: %s)", mu, e.kineticBasis.c_str());
  return text;
}

}  // namespace gradfric::fem
