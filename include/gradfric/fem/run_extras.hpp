#pragma once
// The FEM extras of a single run's results file (docs/fem.md, "Output"): what one gradfric-fem run
// stores beside the campaign layout it shares with a FEM sweep (io/results_file.hpp), all under
// /fem: the run's own scalars (/fem/results), the normal force at the stored history's samples
// (/fem/history), what the run derived once built (/fem/derived, an option record like /scene:
// its time step, the stable step, the interface resolution), the property values the physics used (/fem/properties), the property-field maps
// (/fem/fields), the pressure response (/fem/pressure_response) and the first-slip map
// (/fem/first_slip/time). Serial: rank 0 writes them into the closed results file
// (io::ResultsFile::addGroups).
#include "gradfric/fem/first_slip_map.hpp"
#include "gradfric/fem/pressure_response_recorder.hpp"
#include "gradfric/fem/property_profiles.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/io/hdf5_attributes.hpp"

#include <hdf5.h>

#include <cstdint>
#include <optional>
#include <string>

namespace gradfric::fem {

// The version of the /fem group's layout (its attribute format_version). 5: the single run's file
// is the campaign layout with these extras under /fem (1 to 4: the gradfric-fem-history file).
inline constexpr int kFemExtrasVersion = 5;

struct RunExtras {
  const PlateModel& model;
  const FemRunResult& result;
  const std::optional<PressureResponseMap>& response;
  const std::optional<FirstSlipMap>& firstSlips;   // with first_slip in -friction_observables
  const std::vector<PropertyProfile>& properties;  // the physics' values (gatherPropertyProfiles)
  std::string fieldsXdmf;                          // the snapshots' .xmf beside the file, or empty
  std::vector<io::Attribute> derived;  // what the run derived once built (its dt, the interface resolution)
  std::string errorBasis[2];           // the mu_s and mu_k bars for people (study::describeBar)
};

// Adds /fem to an open results file that has the campaign layout (its root scales point,
// realisation and sample are attached to /fem/history).
void writeRunExtras(hid_t file, const RunExtras& extras);
// The size of /fem, generously (before the room for HDF5's records).
std::uint64_t runExtrasBytes(const RunExtras& extras);
// The normal force / (p L^2) at each sample of the stored history (the observer's sample times,
// found among the run's steps), NaN where a sample has no step.
std::vector<double> normalForceAtSamples(const FemRunResult& result);

}  // namespace gradfric::fem
