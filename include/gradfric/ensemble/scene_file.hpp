#pragma once
// The statistics of a spring-block scene run: the campaign's, with each point's discretisation
// bar. Planning, opening (fresh, resumed, extended) and finishing the file are the campaign's
// (campaign/campaign_file.hpp), the same for the FEM sweep.
#include "gradfric/ensemble/scene.hpp"
#include "gradfric/campaign/campaign_file.hpp"
#include "gradfric/io/output_plan.hpp"
#include "gradfric/io/results_file.hpp"

#include <mpi.h>

#include <vector>

namespace gradfric::ensemble {

// Collective: the statistics of every point from the file's P x R tables, written to /statistics.
std::vector<campaign::PointStatistics> writeStatistics(io::ResultsFile& file, const Scene& scene);

}  // namespace gradfric::ensemble
