#pragma once
// Solution verification: the numerical uncertainty of one member of a refinement ladder, by the
// least-squares procedure of Eca and Hoekstra (J. Comput. Phys. 262 (2014) 104-130), the practice
// behind ASME V&V 20, with the 95 % statistical half-width of ensemble means added. The one
// procedure of gradfric: both models' bars, gradfric-study -judge and the docs' tables use it
// (docs/verification.md gives the formulas). PETSc-free.
#include <vector>

namespace gradfric::verification {

struct Member {
  double h = 1;         // typical cell size (any unit, the same for the whole ladder)
  double value = 0;     // the result on this discretisation
  double stdError = 0;  // of an ensemble mean; 0: a deterministic result
  int samples = 0;      // realisations behind stdError (Student's t)
};

enum class Convergence {
  TooFewMembers,          // fewer than 3 distinct cell sizes
  NoSignal,               // a difference within its 95 % half-width: its sign is not known
  Monotone,               // the differences keep their sign and the fit's order is at least 0.5
  SlowConvergence,        // they keep their sign, but the fit's order lies in (0, 0.5): no bound
  Oscillatory,            // the differences alternate while shrinking
  MonotoneDivergence,     // the differences keep their sign and do not shrink
  OscillatoryDivergence,  // they alternate without shrinking
};

// The fit that estimates the error: phi_i - phi_0 = alpha h^p (observed order), alpha h, alpha h^2
// or alpha_1 h + alpha_2 h^2; None where the ladder is judged by its data range alone.
enum class ErrorFit { ObservedOrder, FirstOrder, SecondOrder, FirstAndSecondOrder, None };

struct Verdict {
  Convergence convergence = Convergence::TooFewMembers;
  ErrorFit fit = ErrorFit::None;
  int member = 0;            // the judged member (index into the ladder as given)
  double value = 0;          // its value
  double order = 0;          // observed order p of the alpha h^p fit; oscillatory: that of |differences|
  double extrapolated = 0;   // phi_0 of the error fit (the value where fit is None)
  double fitStdDev = 0;      // U_s: the fit's standard deviation (0 for an exact fit)
  double dataRange = 0;      // Delta_phi = (max - min) / (n - 1)
  double safetyFactor = 0;   // 1.25 in the asymptotic range, 3 otherwise
  double halfWidth = 0;      // the 95 % statistical half-width included in the uncertainty
  double uncertainty = 0;    // U of the member, absolute (0 where not bounded)
  bool bounded() const { return convergence == Convergence::Monotone || convergence == Convergence::Oscillatory ||
                                convergence == Convergence::NoSignal; }
  double relative() const { return uncertainty / (value < 0 ? -value : value); }
};

// The verdict on ladder[member]. One departure from Eca and Hoekstra: a monotone ladder of observed
// order below 0.5 gets no bar (their fixed-order fits gave 1.7 % where the error was 2.4 % on
// phi = 0.8 + 0.02 h^0.3: tests/unit/test_verification.cpp). The ladder's members come in any order; formalOrder is the order
// of the discretisation (2 for Q1 elements and the lattices' second-order integrators), the top of
// the asymptotic range [0.5, formalOrder).
Verdict judge(const std::vector<Member>& ladder, int member, double formalOrder = 2.0);

// Names as the results files and gradfric-study store them ("monotone", "observed order", ...); the
// text for people is study::describeBar's.
const char* toString(Convergence c);
const char* toString(ErrorFit f);

}  // namespace gradfric::verification
