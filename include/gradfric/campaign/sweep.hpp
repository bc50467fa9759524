#pragma once
// The sweep of a scene: the Cartesian product of the swept lists, one point per combination,
// and the tasks (point, realisation) of a run. Pure functions, no MPI.
#include "gradfric/physics/grading.hpp"

#include <string>
#include <vector>

namespace gradfric::campaign {

struct SweepPoint {
  double delta = 0.0;
  double theta = 0.0;         // sliding angle [degree]
  double sigma = 0.0;         // relative dispersion of mu_s,i
  double sigmaKinetic = 0.0;  // relative dispersion of mu_k,i
  std::string property = "E";
  std::string profile = "none";
  // A swept property-field parameter (-ensemble_field): its value at this point; neutral when
  // the value makes the field uniform (an amplitude of 0), the reference of the relative variation.
  double fieldValue = 0.0;
  bool fieldSwept = false, fieldNeutral = true;
  bool graded() const { return (profile != "none" && delta != 0.0) || (fieldSwept && !fieldNeutral); }
};

// The lists of a scene; an empty list is not swept (the base value is used).
struct SweepLists {
  std::vector<std::string> property;
  std::vector<std::string> profile;
  std::vector<double> theta;
  std::vector<double> sigma;  // sets both relative dispersions
  std::vector<double> delta;
  // One scalar parameter of a property field (-ensemble_field mu_delta -ensemble_field_values ...),
  // innermost; `fieldNeutral` is the value that makes the field uniform, if there is one.
  std::string fieldParameter;
  std::vector<double> fieldValues;
  bool fieldHasNeutral = false;
  double fieldNeutral = 0.0;
};

struct Sweep {
  std::vector<std::string> axes;  // swept quantities, outermost first
  std::vector<SweepPoint> points;
  std::vector<int> reference;  // per point: the non-graded point it is compared with, or -1
};

// Loop order, outermost first: property, profile, theta, sigma, delta, field parameter.
Sweep buildSweep(const SweepLists& lists, const SweepPoint& base);

// The grading of one point (bands from the scene's -grading_bands).
Grading gradingOf(const SweepPoint& point, int bands);

struct Task {
  int point = 0;
  int realisation = 0;
};

// The tasks still to run, in the order they are handed out: most expensive first (large |Delta|
// takes longer to detach), so that the last tasks to start are short ones. `finished` is P x R
// (row-major), 1 for a finished task; empty means none finished.
std::vector<Task> pendingTasks(const Sweep& sweep, int realisations, const std::vector<unsigned char>& finished);
// The same for realisations r < counts[p] of each point p only (a batch of a precision target).
std::vector<Task> pendingTasks(const Sweep& sweep, int realisations, const std::vector<unsigned char>& finished,
                               const std::vector<int>& counts);

// Relative cost estimate of one task of this point (1 for the non-graded plate).
double estimatedCost(const SweepPoint& point);

// "Delta=0.1, theta=30" for the swept quantities of point p ("single point" without any).
std::string pointLabel(const Sweep& sweep, int p);

}  // namespace gradfric::campaign
