#pragma once
// The one rule by which a refinement ladder proves an error bar, for both models (the FEM's mesh,
// thickness and time-step ladders, fem/error_estimate.cpp; the spring-block lattice ladder,
// ensemble/sbm_error_estimate.cpp; docs/accuracy_fem.md, "When a ladder converges").
// Three results at refinement ratio 2 (coarse, medium, fine), each a deterministic number or an
// ensemble mean with its standard error:
//  - a statistical ladder proves nothing unless each difference exceeds its 95 % half-width;
//  - it converges when the second difference stays below 1/sqrt(2) of the first (an observed order
//    p > 0.5), across both half-widths;
//  - monotone: Roache's GCI of a member, 1.25 (|mu(member) - mu_ext| + h) / |mu_ext|, with mu_ext
//    the Richardson extrapolation (p capped at 2, the order of the elements) and h the half-width of
//    mu(member) - mu_ext;
//  - alternating while shrinking: the limit lies between the last two values, so 1.25 (the member's
//    distance to the farther of them + its half-width) / |fine|;
//  - otherwise no bound.
// Pure: part of the PETSc-free core (scripts/ladder_rule.py is the same rule for the docs' tables).

namespace gradfric {

struct LadderRung {
  double value = 0;
  double stdError = 0;   // 0: a deterministic result
  int realisations = 0;  // of an ensemble mean (for Student's t); unused when stdError is 0
};

enum class LadderOutcome {
  NoSignal,      // a difference within its statistical half-width
  NotConverged,  // observed order <= 0.5 (or not above it across the half-widths)
  Monotone,      // converged, the differences keep their sign
  Oscillating,   // converged, the differences alternate while shrinking
};

struct LadderVerdict {
  LadderOutcome outcome = LadderOutcome::NotConverged;
  double first = 0, second = 0;                // medium - coarse, fine - medium
  double firstHalfWidth = 0, secondHalfWidth = 0;  // their 95 % half-widths (0 if deterministic)
  double order = 0;         // log2 |first / second|
  double extrapolated = 0;  // Monotone only
  double bound = 0;         // relative bound of the member's value (Monotone, Oscillating)
  bool converged() const { return outcome == LadderOutcome::Monotone || outcome == LadderOutcome::Oscillating; }
};

// The verdict of a ladder on its member 0, 1 or 2.
LadderVerdict judgeLadder(const LadderRung (&rungs)[3], int member);

// A coarser ladder proves a bar only if every finer ladder of the study converges too: one that does
// not shows the sequence has not reached its asymptotic range (FEM friction -0.2: 100/200/400
// converges by the rule, 200/400/800 does not). Walks the ladders whose coarsest rung is coarsest x
// 2, x 4, ... while the study holds them (held(first)): the first of them that disproves
// (disproves(first)), 0 if none does, and the coarsest rung of the finest one held (coarsest if none).
struct FinerLadders {
  int disproving = 0;
  int finest = 0;
};
template <class Held, class Disproves>
FinerLadders walkFinerLadders(int coarsest, Held held, Disproves disproves) {
  FinerLadders walk{0, coarsest};
  for (int first = coarsest << 1; held(first); first <<= 1) {
    walk.finest = first;
    if (disproves(first)) {
      walk.disproving = first;
      break;
    }
  }
  return walk;
}

// A member whose own ladder does not converge, while every finer ladder the study holds does, is
// still bounded through the finest value f of those ladders: |mu - mu_lim| <= |mu - mu_f| +
// |mu_f - mu_lim| (the triangle inequality; the first term is measured, the second is f's bound).
// Relative to the limit, as the bounds are; an ensemble mean's difference is widened by its 95 %
// half-width.
double boundThroughFinerValue(const LadderRung& value, const LadderRung& finer, double finerBound);

// Whether some limit L satisfies every bound |value_i - L| <= bound_i |L| (relative bounds, as the
// rule's): the intervals [v / (1 + b), v / (1 - b)] of positive values overlap. Bounds of two
// results of one model that share no limit refute the assumption that made them (the FEM's mesh
// refined each direction apart, checked against the ladder refined in every direction).
struct BoundedValue {
  double value = 0;
  double bound = 0;  // relative to the limit
};
bool shareALimit(const BoundedValue* values, int count);

}  // namespace gradfric
