#include "gradfric/campaign/sweep.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/physics/grading.hpp"

#include <sstream>

#include <algorithm>
#include <cmath>

namespace gradfric::campaign {

Sweep buildSweep(const SweepLists& lists, const SweepPoint& base) {
  Sweep sweep;
  auto orBase = [](const auto& list, const auto& value) {
    using T = std::decay_t<decltype(value)>;
    return list.empty() ? std::vector<T>{value} : std::vector<T>(list.begin(), list.end());
  };
  if (!lists.property.empty()) sweep.axes.push_back("property");
  if (!lists.profile.empty()) sweep.axes.push_back("profile");
  if (!lists.theta.empty()) sweep.axes.push_back("theta");
  if (!lists.sigma.empty()) sweep.axes.push_back("sigma");
  if (!lists.delta.empty()) sweep.axes.push_back("delta");
  if (!lists.fieldValues.empty()) sweep.axes.push_back("field_" + lists.fieldParameter);
  const std::vector<double> fieldValues = lists.fieldValues.empty() ? std::vector<double>{0.0} : lists.fieldValues;
  const auto properties = orBase(lists.property, base.property);
  const auto profiles = orBase(lists.profile, base.profile);
  const auto thetas = orBase(lists.theta, base.theta);
  const auto deltas = orBase(lists.delta, base.delta);
  for (const auto& property : properties)
    for (const auto& profile : profiles)
      for (double theta : thetas)
        for (size_t s = 0; s < std::max<size_t>(lists.sigma.size(), 1); ++s)
          for (double delta : deltas)
            for (double value : fieldValues) {
              SweepPoint p = base;
              p.property = property;
              p.profile = profile;
              p.theta = theta;
              if (!lists.sigma.empty()) p.sigma = p.sigmaKinetic = lists.sigma[s];
              p.delta = delta;
              if (!lists.fieldValues.empty()) {
                p.fieldSwept = true;
                p.fieldValue = value;
                p.fieldNeutral = lists.fieldHasNeutral && value == lists.fieldNeutral;
              }
              sweep.points.push_back(p);
            }
  // The reference of a point: a non-graded point with the same angle and dispersions, preferring
  // the same property and profile (the Delta = 0 entry of its own Delta sweep).
  const int n = static_cast<int>(sweep.points.size());
  sweep.reference.assign(n, -1);
  for (int i = 0; i < n; ++i) {
    const SweepPoint& p = sweep.points[i];
    if (!p.graded()) {
      sweep.reference[i] = i;
      continue;
    }
    int best = -1;
    for (int j = 0; j < n && best < 0; ++j) {
      const SweepPoint& q = sweep.points[j];
      if (!q.graded() && q.theta == p.theta && q.sigma == p.sigma && q.sigmaKinetic == p.sigmaKinetic &&
          q.property == p.property && q.profile == p.profile)
        best = j;
    }
    for (int j = 0; j < n && best < 0; ++j) {
      const SweepPoint& q = sweep.points[j];
      if (!q.graded() && q.theta == p.theta && q.sigma == p.sigma && q.sigmaKinetic == p.sigmaKinetic) best = j;
    }
    sweep.reference[i] = best;
  }
  return sweep;
}

Grading gradingOf(const SweepPoint& point, int bands) {
  Grading g;
  g.profile = parseGradingProfile(point.profile);
  g.property = point.property == "friction" ? GradedProperty::Friction
               : point.property == "both"   ? GradedProperty::Both
                                            : GradedProperty::YoungsModulus;
  g.delta = point.delta;
  g.bands = bands;
  return g;
}

double estimatedCost(const SweepPoint& point) { return point.graded() ? 1.0 + 2.0 * std::fabs(point.delta) : 1.0; }

std::vector<Task> pendingTasks(const Sweep& sweep, int realisations, const std::vector<unsigned char>& finished) {
  return pendingTasks(sweep, realisations, finished, std::vector<int>(sweep.points.size(), realisations));
}

std::vector<Task> pendingTasks(const Sweep& sweep, int realisations, const std::vector<unsigned char>& finished,
                               const std::vector<int>& counts) {
  std::vector<Task> tasks;
  const int points = static_cast<int>(sweep.points.size());
  for (int p = 0; p < points; ++p)
    for (int r = 0; r < std::min(realisations, counts[p]); ++r) {
      const size_t index = static_cast<size_t>(p) * realisations + r;
      if (index < finished.size() && finished[index]) continue;
      tasks.push_back({p, r});
    }
  std::stable_sort(tasks.begin(), tasks.end(), [&](const Task& a, const Task& b) {
    return estimatedCost(sweep.points[a.point]) > estimatedCost(sweep.points[b.point]);
  });
  return tasks;
}

std::string pointLabel(const Sweep& sweep, int p) {
  const SweepPoint& q = sweep.points[p];
  std::ostringstream out;
  bool first = true;
  auto add = [&](const std::string& text) {
    out << (first ? "" : ", ") << text;
    first = false;
  };
  for (const auto& axis : sweep.axes) {
    if (axis == "delta") add("Delta=" + formatReal(q.delta));
    if (axis == "theta") add("theta=" + formatReal(q.theta));
    if (axis == "sigma") add("sigma=" + formatReal(q.sigma));
    if (axis == "property") add("property=" + q.property);
    if (axis == "profile") add("profile=" + q.profile);
    if (axis.rfind("field_", 0) == 0) add(axis.substr(6) + "=" + formatReal(q.fieldValue));
  }
  return first ? "single point" : out.str();
}

}  // namespace gradfric::campaign
