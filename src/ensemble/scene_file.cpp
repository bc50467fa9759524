// The statistics of a spring-block scene run (include/gradfric/ensemble/scene_file.hpp).
#include "gradfric/ensemble/scene_file.hpp"

#include "gradfric/io/provenance.hpp"

#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/campaign/log_events.hpp"
#include "gradfric/campaign/statistics_columns.hpp"
#include "gradfric/physics/observables.hpp"

#include <limits>
#include <string>
#include <utility>

namespace gradfric::ensemble {

// The spring-block campaign is the campaign component's: its names without the prefix, in this file.
using namespace campaign;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

std::vector<PointStatistics> writeStatistics(io::ResultsFile& file, const Scene& scene) {
  auto stats = writeStatistics(file, scene.realisations, scene.sweep.reference, scene.commonStreams,
                               scene.target.active() ? &scene.target : nullptr);
  // Each point's discretisation bar as fields (their text attributes came with the layout).
  std::vector<std::pair<std::string, std::vector<double>>> bars;
  for (int k = 0; k < 2; ++k) {
    const auto values = discretisationValues(k ? "mu_k" : "mu_s", scene.bars[k]);
    bars.insert(bars.end(), values.begin(), values.end());
  }
  file.writeStatistics(bars, {});
  return stats;
}

}  // namespace gradfric::ensemble
