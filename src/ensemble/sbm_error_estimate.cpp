// The discretisation bar of the spring-block ensemble means (include/gradfric/ensemble/
// sbm_error_estimate.hpp), from the study's own measurements (docs/sbm_study.tsv, embedded at build
// time; docs/accuracy.md, "The discretisation bar"):
//  - lattice: the ladder N_b, 2 N_b, 4 N_b of ensemble means at the run's grading, law and
//    observable, by the FEM's rule (docs/accuracy_fem.md, "When a ladder converges") made to
//    account for the means' statistical error (latticeLadderTerm);
//  - time step: the default step's error against RK4 at 1e-9 s (velocity Verlet), 1.25 x that
//    error, scaled by dt / dt_study above the studied step (the error is first order in dt).
// A setting the study did not run (another plate, sigma, integrator, grading, law, N_b, ...) gets
// no bar, with the reason.
#include "gradfric/ensemble/sbm_error_estimate.hpp"

#include "gradfric/core/data_table.hpp"
#include "gradfric/core/refinement_ladder.hpp"
#include "gradfric/ensemble/sbm_study_data.hpp"  // generated: kSbmStudyTable, the text of docs/sbm_study.tsv
#include "gradfric/physics/field.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace gradfric::ensemble {

namespace {

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f %%", 100 * fraction);
  return text;
}

// The scene the study ran: the paper's plate and layer, sigma 2.8 %, exact springs, uniform
// pressure, default damping, velocity Verlet, the default peak rule and mu_k window, no property
// fields, sliding along the grading, a linear friction grading of 10 bands (or none).
std::string outsideStudiedScene(const sbm::Parameters& p, const Grading& g, const FrictionMeasurement& m,
                                bool kinetic) {
  const Plate& q = p.plate;
  const std::string plate = differenceFromPapersPlate(q, PlateThickness::Ignored);  // H does not enter the SBM
  if (!plate.empty()) return plate;
  if (q.slidingAngle != 0.0) return "sliding angle other than 0";
  if (!sameStudiedValue(p.layerThickness, sbm::Parameters{}.layerThickness)) return "l_z other than 5.7e-5 m";
  if (!sameStudiedValue(p.sigmaStatic, 0.028) || !sameStudiedValue(p.sigmaKinetic, 0.028))
    return "sigma other than the study's 2.8 %";
  if (p.smallStrain) return "small-strain springs";
  if (p.pressureResponse.active()) return "load-dependent pressure";
  if (!sameStudiedValue(p.damping, 0.1 * std::sqrt(p.axialStiffness(q.youngsModulus) / p.blockMass())))
    return "damping other than 0.1 sqrt(K_int/m)";
  if (p.integrator != sbm::Integrator::VelocityVerlet) return "integrator other than velocity Verlet (the study's)";
  if (!sameStudiedValue(p.frictionLaw.criticalVelocity, FrictionLawSettings::kCriticalVelocity) ||
      !sameStudiedValue(p.frictionLaw.slipLength, FrictionLawSettings::kSlipLength))
    return "friction law parameters other than the defaults";
  const double load = p.loadingTime();
  if (!sameStudiedValue(m.peakDrop, FrictionMeasurement{}.peakDrop) || !sameStudiedValue(m.peakHold, 0.25 * load))
    return "peak rule other than the default";
  if (kinetic && (!sameStudiedValue(m.kineticDelay, 0.5 * load) || !sameStudiedValue(m.kineticWidth, load) ||
                  m.kineticSteadyTolerance != 0.0))
    return "mu_k window other than the default";
  if (g.fields && g.fields->any()) return "property fields";
  if (g.active() && (g.profile != GradingProfile::Linear || g.property != GradedProperty::Friction))
    return "grading other than a linear friction grading";
  if (g.active() && g.bands != 10) return "grading bands other than 10";
  return "";
}

std::string gradingName(const Grading& g) { return g.active() ? "friction" : "none"; }

const SbmStudyRow* findLattice(const std::vector<SbmStudyRow>& study, const std::string& law, const std::string& grading,
                               double delta, int blocks, const std::string& observable) {
  for (const SbmStudyRow& r : study)
    if (r.kind == "lattice" && r.law == law && r.grading == grading && std::fabs(r.delta - delta) < 1e-9 &&
        r.blocks == blocks && r.observable == observable)
      return &r;
  return nullptr;
}

// The ladder rule (core/refinement_ladder.hpp) on three lattice rows, for the bound of `member`.
LadderVerdict judgeRows(const SbmStudyRow* const m[3], int member) {
  LadderRung rungs[3];
  for (int i = 0; i < 3; ++i) rungs[i] = {m[i]->value, m[i]->stdError, m[i]->realisations};
  return judgeLadder(rungs, member);
}

// The lattice term: the finest ladder holding the run's N_b (nearest the asymptotic range), taken
// whether or not it converges (no choosing among ladders by their outcome); every finer ladder
// must converge as well.
SbmBarTerm latticeTerm(const std::vector<SbmStudyRow>& study, const sbm::Parameters& p, const Grading& g,
                       const std::string& observable) {
  const std::string grading = gradingName(g), &law = p.frictionLaw.name;
  const double delta = g.active() ? g.delta : 0.0;
  bool anyRow = false;
  for (const SbmStudyRow& r : study)
    anyRow = anyRow || (r.kind == "lattice" && r.law == law && r.grading == grading &&
                        std::fabs(r.delta - delta) < 1e-9 && r.observable == observable);
  char text[200];
  if (!anyRow) {  // name what the study holds (the same text for every point it lacks)
    std::vector<std::string> held;
    for (const SbmStudyRow& r : study)
      if (r.kind == "lattice" && r.law == law && r.observable == observable) {
        char one[64];
        std::snprintf(one, sizeof one, "%s Delta = %g", r.grading.c_str(), r.delta);
        if (std::find(held.begin(), held.end(), one) == held.end()) held.push_back(one);
      }
    std::string list;
    for (const std::string& h : held) list += (list.empty() ? "" : ", ") + h;
    std::snprintf(text, sizeof text, "no lattice ladder of %s for law %s and this grading (the study's: %s)",
                  observable.c_str(), law.c_str(), list.empty() ? "none" : list.c_str());
    return {false, 0, text};
  }
  const int n = p.blocksPerSide;
  for (int member = 0; member <= 2; ++member) {
    const int coarsest = n >> member;
    if (coarsest < 1 || (coarsest << member) != n) continue;
    const auto findLadder = [&](int first, const SbmStudyRow* (&m)[3]) {
      bool complete = true;
      for (int k = 0; k < 3; ++k)
        complete = complete && (m[k] = findLattice(study, law, grading, delta, first << k, observable)) != nullptr;
      return complete;
    };
    const SbmStudyRow* m[3];
    if (!findLadder(coarsest, m)) continue;
    const SbmStudyRow* f[3];
    const FinerLadders finer = walkFinerLadders(
        coarsest, [&](int first) { return findLadder(first, f); },
        [&](int) { return judgeRows(f, 0).outcome == LadderOutcome::NotConverged; });  // no signal disproves nothing
    if (finer.disproving)
      return {false, 0, latticeLadderTerm(f, 0).basis + " (a finer ladder: no bar for N_b = " + std::to_string(n) + ")"};
    const SbmBarTerm own = latticeLadderTerm(m, member);
    if (own.measured || finer.finest == coarsest) return own;
    findLadder(finer.finest, f);  // the finest value bounds the run's through the triangle inequality
    const SbmBarTerm through = latticeLadderTerm(f, 2);
    if (!through.measured) return own;
    const auto rung = [](const SbmStudyRow* r) { return LadderRung{r->value, r->stdError, r->realisations}; };
    const double bound = boundThroughFinerValue(rung(m[member]), rung(f[2]), through.relative);
    std::snprintf(text, sizeof text, "; bounded through the finest N_b = %d (%.6f): %s", f[2]->blocks, f[2]->value,
                  percent(bound).c_str());
    return {true, bound, own.basis + "; " + through.basis + text};
  }
  std::snprintf(text, sizeof text, "N_b = %d not in a lattice ladder of the study (N_b, 2 N_b, 4 N_b)", n);
  return {false, 0, text};
}

// The default step's error (kind dt rows), 1.25 x, scaled by dt / dt_study above the studied step
// (first order in dt, docs/accuracy.md); a step more than 5 % above it is outside the study.
SbmBarTerm timeStepTerm(const std::vector<SbmStudyRow>& study, const sbm::Parameters& p, const std::string& observable) {
  const SbmStudyRow* rung = nullptr;
  for (const SbmStudyRow& r : study)
    if (r.kind == "dt" && r.law == p.frictionLaw.name && r.observable == observable) rung = &r;
  if (!rung) return {false, 0, "no time-step study of " + observable + " for law " + p.frictionLaw.name};
  char text[200];
  if (p.timeStep > 1.05 * rung->dt) {
    std::snprintf(text, sizeof text, "dt = %.3g s above the studied default step %.3g s", p.timeStep, rung->dt);
    return {false, 0, text};
  }
  const double bound = 1.25 * rung->value * std::max(1.0, p.timeStep / rung->dt);
  std::snprintf(text, sizeof text, "dt %.3g s: velocity Verlet at %.3g s vs RK4 at 1e-9 s, error %.1e (N_b = %d)",
                p.timeStep, rung->dt, rung->value, rung->blocks);
  return {true, bound, text};
}

}  // namespace

std::vector<SbmStudyRow> parseSbmStudy(const std::string& text) {
  std::vector<SbmStudyRow> rows;
  forEachDataRow(text, "the spring-block study table (docs/sbm_study.tsv)", [&](std::istringstream& fields) {
    SbmStudyRow r;
    std::string dt;
    if (!(fields >> r.kind >> r.law >> r.grading >> r.delta >> r.blocks >> r.observable >> r.realisations >> r.value >>
          r.stdError >> dt))
      return false;
    if (dt == "default") {
      r.dt = 0.0;
    } else {
      std::istringstream step(dt);
      if (!(step >> r.dt) || !step.eof()) return false;
    }
    rows.push_back(r);
    return true;
  });
  return rows;
}

const std::vector<SbmStudyRow>& sbmStudy() {
  static const std::vector<SbmStudyRow> rows = parseSbmStudy(kSbmStudyTable);
  return rows;
}

SbmBarTerm latticeLadderTerm(const SbmStudyRow* const m[3], int member) {
  const LadderVerdict v = judgeRows(m, member);
  const double coarse = m[0]->value, medium = m[1]->value, fine = m[2]->value;
  char ladder[200], text[500];
  std::snprintf(ladder, sizeof ladder, "lattice N_b %d/%d/%d: %.6f, %.6f, %.6f (differences %+.3f %% +- %.3f %%, %+.3f %% +- %.3f %%)",
                m[0]->blocks, m[1]->blocks, m[2]->blocks, coarse, medium, fine, 100 * v.first / coarse,
                100 * v.firstHalfWidth / coarse, 100 * v.second / medium, 100 * v.secondHalfWidth / medium);
  switch (v.outcome) {
    case LadderOutcome::NoSignal:
      std::snprintf(text, sizeof text, "%s: a difference within its 95 %% statistical half-width, the ladder proves nothing",
                    ladder);
      return {false, 0, text};
    case LadderOutcome::NotConverged:
      std::snprintf(text, sizeof text, "%s: not converged, observed order %.2f %s", ladder, v.order,
                    v.order <= 0.5 ? "<= 0.5" : "not above 0.5 across the statistical error");
      return {false, 0, text};
    case LadderOutcome::Oscillating:
      std::snprintf(text, sizeof text, "%s, oscillating (limit between the last two), bound %s", ladder,
                    percent(v.bound).c_str());
      return {true, v.bound, text};
    case LadderOutcome::Monotone:
      break;
  }
  std::snprintf(text, sizeof text, "%s, observed order %.2f, extrapolated %.6f, GCI %s", ladder, v.order, v.extrapolated,
                percent(v.bound).c_str());
  return {true, v.bound, text};
}

SbmDiscretisation sbmDiscretisationError(const sbm::Parameters& parameters, const Grading& grading,
                                         const FrictionMeasurement& measurement, bool kinetic,
                                         const std::vector<SbmStudyRow>& study) {
  SbmDiscretisation e;
  const std::string outside = outsideStudiedScene(parameters, grading, measurement, kinetic);
  if (!outside.empty()) {
    e.basis = outside;
    return e;
  }
  const std::string observable = kinetic ? "mu_k" : "mu_s";
  e.lattice = latticeTerm(study, parameters, grading, observable);
  e.timeStep = timeStepTerm(study, parameters, observable);
  e.measured = e.lattice.measured && e.timeStep.measured;
  if (e.measured) {
    e.relative = e.lattice.relative + e.timeStep.relative;
    e.basis = e.lattice.basis + "; " + e.timeStep.basis;
  } else {
    for (const SbmBarTerm* t : {&e.lattice, &e.timeStep})
      if (!t->measured) e.basis += (e.basis.empty() ? "" : "; ") + t->basis;
  }
  return e;
}

std::string describeBar(const SbmDiscretisation& e) {
  if (!e.measured) return "discretisation error not measured: " + e.basis;
  return "discretisation +- " + percent(e.relative) + " (lattice " + percent(e.lattice.relative) + ", dt " +
         percent(e.timeStep.relative) + ")";
}

}  // namespace gradfric::ensemble
