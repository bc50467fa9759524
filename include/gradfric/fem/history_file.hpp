#pragma once
// The FEM history file's content (the file is described in output.hpp and docs/fem.md): the
// sampled mu(t), the run's scalars with their units, the property fields used, the pressure
// response, the resolved options and the provenance. Serial: rank 0 writes it.
#include "gradfric/core/options.hpp"
#include "gradfric/fem/pressure_response_recorder.hpp"
#include "gradfric/fem/property_profiles.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/io/provenance.hpp"

#include <hdf5.h>

#include <cstdint>
#include <optional>

namespace gradfric::fem {

struct HistoryContent {
  const PlateModel& model;
  const FemRunResult& result;
  const RunParameters& record;
  int historyEvery = 1;  // every n-th step of mu(t) is kept
  const io::Provenance& provenance;
  const std::optional<PressureResponseMap>& response;
  const std::vector<PropertyProfile>& properties;  // the physics' values (gatherPropertyProfiles)
};

// Fills an open, empty HDF5 file.
void writeHistoryFile(hid_t file, const HistoryContent& content);
// The size of that file, generously (the room reserved for it).
std::uint64_t historyFileBytes(const HistoryContent& content);

}  // namespace gradfric::fem
