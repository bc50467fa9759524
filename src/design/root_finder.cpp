// The stochastic root finder (include/gradfric/design/root_finder.hpp).
#include "gradfric/design/root_finder.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace gradfric::design {

namespace {

class RootSearch {
public:
  RootSearch(const EvaluateFunction& evaluate, const Problem& problem, SearchLog& log)
      : evaluate_(evaluate), problem_(problem), log_(log) {}

  SearchResult run() {
    const FreeParameter& f = problem_.free[0];
    std::vector<Evaluation> grid;  // settled evaluations, sorted by x
    for (double x : {f.lower, f.upper}) {
      const Evaluation e = settle(x, problem_.coarse, "bracket");
      if (const auto done = finished(e)) return *done;
      grid.push_back(e);
    }
    // Interior points until the target is bracketed: 1/2, then 1/4, 3/4, then eighths, ...
    for (int k = 0, level = 1; k < problem_.scanPoints && !bracket(grid); ++level)
      for (int odd = 1; odd < (1 << level) && k < problem_.scanPoints && !bracket(grid); odd += 2, ++k) {
        const double x = f.lower + (f.upper - f.lower) * odd / double(1 << level);
        const Evaluation e = settle(x, problem_.coarse, "scan");
        if (const auto done = finished(e)) return *done;
        grid.insert(std::upper_bound(grid.begin(), grid.end(), x, [](double v, const Evaluation& g) { return v < g.x[0]; }), e);
      }
    const auto ends = bracket(grid);
    if (!ends) return unreachable();
    return regulaFalsi(ends->first, ends->second);
  }

private:
  double gap(const Evaluation& e) const { return e.value - problem_.target; }

  // An evaluation at x; if its CI holds the target, refined to the tolerance.
  Evaluation settle(double x, double halfWidth, const char* phase) {
    ++tried_;
    Evaluation e = log_.add(evaluate_({x}, halfWidth, phase));
    if (e.side(problem_.target) == 0 && !log_.meets(e) && e.realisations < problem_.cap)
      e = log_.add(evaluate_({x}, problem_.tolerance, "refine"));
    return e;
  }

  // The search ends at e: the target met, or held by a CI the cap keeps wider than the tolerance.
  std::optional<SearchResult> finished(const Evaluation& e) const {
    if (log_.meets(e)) return SearchResult{Status::Found, e, "root", "the target lies in the CI of the design"};
    if (e.side(problem_.target) == 0)
      return SearchResult{Status::NotConverged, e, "root",
                          "the CI holds the target but the realisation cap keeps it wider than the tolerance"};
    return std::nullopt;
  }

  // Two neighbours of the grid on either side of the target (the first such pair).
  static std::optional<std::pair<Evaluation, Evaluation>> bracketOf(const std::vector<Evaluation>& grid, double target) {
    for (std::size_t i = 0; i + 1 < grid.size(); ++i)
      if (grid[i].side(target) * grid[i + 1].side(target) < 0) return std::pair{grid[i], grid[i + 1]};
    return std::nullopt;
  }
  std::optional<std::pair<Evaluation, Evaluation>> bracket(const std::vector<Evaluation>& grid) const {
    return bracketOf(grid, problem_.target);
  }

  // No sign change within the bounds: the closest value the family reached, at the tolerance.
  SearchResult unreachable() {
    const Evaluation closest = log_.closest();
    Evaluation e = log_.add(evaluate_(closest.x, problem_.tolerance, "closest"));
    if (const auto done = finished(e)) return *done;
    return {Status::Unreachable, e, "root",
            "the target is outside what the family reaches within the bounds (scanned " +
                std::to_string(2 + problem_.scanPoints) + " points); the design is the closest attainable value"};
  }

  SearchResult regulaFalsi(Evaluation a, Evaluation b) {
    double fa = gap(a), fb = gap(b);
    int lastReplaced = 0;  // -1: a, +1: b (Illinois: halve the end kept twice)
    while (tried_ < problem_.maxEvaluations) {
      const double xa = a.x[0], xb = b.x[0], width = xb - xa;
      double x = (xa * fb - xb * fa) / (fb - fa);
      x = std::clamp(x, xa + 0.01 * width, xb - 0.01 * width);
      const double halfWidth = std::clamp(0.5 * std::min(std::fabs(gap(a)), std::fabs(gap(b))), problem_.tolerance,
                                          problem_.coarse);
      const Evaluation e = settle(x, halfWidth, "step");
      if (auto done = finished(e)) {
        done->slope = localSlope(e.x[0]);
        return *done;
      }
      if (e.side(problem_.target) == a.side(problem_.target)) {
        a = e;
        fa = gap(e);
        if (lastReplaced == -1) fb *= 0.5;
        lastReplaced = -1;
      } else {
        b = e;
        fb = gap(e);
        if (lastReplaced == 1) fa *= 0.5;
        lastReplaced = 1;
      }
    }
    const Evaluation& best = std::fabs(gap(a)) < std::fabs(gap(b)) ? a : b;
    return {Status::NotConverged, best, "root",
            "-design_max_evaluations = " + std::to_string(problem_.maxEvaluations) +
                " reached; the design is the bracket's end closest to the target"};
  }

  // d value / d x near x: a least-squares line through the latest evaluation at each of the four
  // parameter values closest to x (the design among them). Several points: a two-point secant of
  // evaluations at different precisions would carry their noise.
  double localSlope(double x) const {
    std::vector<std::pair<double, double>> latest;  // (x, value), the latest evaluation per x
    for (const auto& e : log_.all()) {
      auto at = std::find_if(latest.begin(), latest.end(), [&](const auto& p) { return p.first == e.x[0]; });
      if (at == latest.end()) latest.emplace_back(e.x[0], e.value);
      else at->second = e.value;
    }
    std::stable_sort(latest.begin(), latest.end(),
                     [&](const auto& p, const auto& q) { return std::fabs(p.first - x) < std::fabs(q.first - x); });
    latest.resize(std::min<std::size_t>(latest.size(), 4));
    double mx = 0, my = 0;
    for (const auto& [u, v] : latest) mx += u / latest.size(), my += v / latest.size();
    double sxy = 0, sxx = 0;
    for (const auto& [u, v] : latest) sxy += (u - mx) * (v - my), sxx += (u - mx) * (u - mx);
    return sxy / sxx;
  }

  const EvaluateFunction& evaluate_;
  const Problem& problem_;
  SearchLog& log_;
  int tried_ = 0;  // parameter values tried (refinements not counted)
};

}  // namespace

SearchResult findRoot(const EvaluateFunction& evaluate, const Problem& problem, SearchLog& log) {
  return RootSearch(evaluate, problem, log).run();
}

SearchResult findRoot(DesignModel& model, const Problem& problem, SearchLog& log) {
  const EvaluateFunction evaluate = [&](const std::vector<double>& x, double halfWidth, const std::string& phase) {
    return model.evaluate(x, halfWidth, phase);
  };
  return findRoot(evaluate, problem, log);
}

}  // namespace gradfric::design
