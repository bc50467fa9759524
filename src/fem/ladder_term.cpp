#include "gradfric/fem/ladder_term.hpp"

#include "gradfric/core/refinement_ladder.hpp"

#include <cmath>
#include <cstdio>

namespace gradfric::fem {

ErrorTerm ladderTerm(const char* term, const std::string& ladder, const StudyRow* const m[3], int member) {
  const LadderRung rungs[3] = {{m[0]->mu}, {m[1]->mu}, {m[2]->mu}};
  const LadderVerdict v = judgeLadder(rungs, member);
  const double coarse = m[0]->mu, medium = m[1]->mu, fine = m[2]->mu;
  char text[300];
  if (!v.converged()) {
    std::snprintf(text, sizeof text, "%s not converged: %s give %.6f, %.6f, %.6f (differences %+.2f %%, %+.2f %%: %s)",
                  term, ladder.c_str(), coarse, medium, fine, 100 * v.first / coarse, 100 * v.second / medium,
                  v.first * v.second > 0 ? "observed order <= 0.5" : "they change sign and do not shrink");
    return {false, 0, text};
  }
  if (v.outcome == LadderOutcome::Oscillating)
    std::snprintf(text, sizeof text, "%s %s: %.6f, %.6f, %.6f, oscillating convergence (limit between the last two), bound %s",
                  term, ladder.c_str(), coarse, medium, fine, percentText(v.bound).c_str());
  else
    std::snprintf(text, sizeof text, "%s %s: %.6f, %.6f, %.6f, observed order %.2f, extrapolated %.6f, GCI %s", term,
                  ladder.c_str(), coarse, medium, fine, v.order, v.extrapolated, percentText(v.bound).c_str());
  return {true, v.bound, text};
}

ErrorTerm throughFinerValue(const char* term, const ErrorTerm& own, double value, const ErrorTerm& finest,
                            double finestValue) {
  char text[160];
  std::snprintf(text, sizeof text, "; bounded through the finest value %.6f: |difference| %s + its bound %s", finestValue,
                percentText(std::fabs(value - finestValue) / std::fabs(finestValue)).c_str(), percentText(finest.relative).c_str());
  return {true, boundThroughFinerValue({value}, {finestValue}, finest.relative),
          std::string(term) + ": own ladder" + own.basis.substr(own.basis.find(" not converged")) + "; " + finest.basis + text};
}

}  // namespace gradfric::fem
