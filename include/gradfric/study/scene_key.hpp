#pragma once
// The scene key of a run (core/study_table.hpp): the settings that must equal a study row's for the
// row's bar to apply. Every option the user set to a value other than its default counts, except
// the ladder's own coordinates and the options that steer a run without changing its results
// (output, sweep lists and ensemble size, monitors, partitioner), and with the options PETSc's
// objects read under our prefixes (-fem_ts_*): a new option is outside every study until a study
// varies it.
#include "gradfric/campaign/sweep.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/core/study_table.hpp"

#include <string>
#include <vector>

namespace gradfric::study {

// coordinates: the ladder's options ("-fem_nx", ...). point: a sweep point, whose grading, angle,
// dispersion and swept field parameter (-ensemble_field X: -field_X) replace the base values. An inactive grading (profile none or Delta 0) has no effect,
// so its settings are left out.
SceneKey sceneKey(const RunParameters& record, const std::vector<std::string>& coordinates,
                  const campaign::SweepPoint* point = nullptr);

}  // namespace gradfric::study
