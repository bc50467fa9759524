#pragma once
// What a campaign is for any model: a sweep of points, each point's grading, and the results
// file they land in (its layout, its /sweep table, the /scene and /run records, the output path).
// The spring-block scene (ensemble::Scene) and the FEM sweep (fem::FemSweep) are this record
// plus their model's parameters; what one point's run is belongs to the model.
#include "gradfric/campaign/precision_target.hpp"
#include "gradfric/campaign/sweep.hpp"
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/io/results_file.hpp"
#include "gradfric/physics/grading.hpp"

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace gradfric::campaign {

struct Campaign {
  Grading baseGrading;  // the base plate's grading; its fields (-field_*) are every point's unless swept
  std::vector<std::shared_ptr<const PlateFields>> pointFields;  // per point with -ensemble_field (else empty)
  Sweep sweep;
  io::EnsembleLayout layout;
  io::SweepTable table;
  std::vector<io::Attribute> sceneAttributes;  // stored under /scene: define the results
  std::vector<io::Attribute> runAttributes;    // stored under /run: steer this run only
  std::string output;                          // the results file (-output)
  // Realisations per point (-ensemble_realisations; with a target, its cap -ensemble_target_max),
  // the precision target (-ensemble_target*, inactive for a fixed count), and whether realisation
  // r of every point has the same random surface (paired relative variations).
  int realisations = 1;
  PrecisionTarget target;
  bool commonStreams = false;
  bool resume = false;     // -resume: continue <output>.partial
  bool extend = false;     // -ensemble_extend: add realisations or points to a finished file
  bool overwrite = false;  // -output_overwrite

  int points() const { return static_cast<int>(sweep.points.size()); }
  int tasks() const { return points() * realisations; }
  // The grading of sweep point p: its profile, property and amplitude, and its property fields.
  Grading pointGrading(int p) const;
  // Fills sceneAttributes and runAttributes from the run's options: those in runControl (they
  // steer this run, not its results) go under /run. The target's and -ensemble_extend are not
  // stored while off, so that the files of scenes without them stay as they were, byte for byte.
  void recordOptions(const RunParameters& record, const std::set<std::string>& runControl);
};

}  // namespace gradfric::campaign
