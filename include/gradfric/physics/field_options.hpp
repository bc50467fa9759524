#pragma once
// The -field_<property>_* options (E, mu, mu_s, mu_k, p): one property field each (field.hpp),
// maps read from HDF5 or greyscale PNG. PETSc/HDF5 part of the library; docs/fields.md.
#include "gradfric/core/options.hpp"
#include "gradfric/io/hdf5_handle.hpp"
#include "gradfric/physics/field.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/physics/plate.hpp"
#include "gradfric/physics/property_sampler.hpp"

#include <memory>

namespace gradfric {

// A map from an HDF5 dataset: rank 2, [ny][nx] (rows along y), attribute "extent" = x0, x1, y0,
// y1 [m]. Refuses (InputError naming `option` and `path`) what cannot be read; datasetOption names
// where the dataset's name comes from (default: the option's "_dataset" companion).
FieldMap readHdf5Map(const std::string& option, const std::string& path, const std::string& dataset,
                     const std::string& datasetOption = "");
// The same in two steps, for a reader that takes more than the map from the file in one open:
// the file opened read-only (refused as above when missing or not HDF5), then the map from it.
io::H5File openHdf5Map(const std::string& option, const std::string& path);
FieldMap readHdf5Map(const std::string& option, const std::string& path, hid_t file, const std::string& dataset,
                     const std::string& datasetOption = "");

// Reads every field's options (all listed by -help) and its map; refuses bad options, unreadable
// or malformed maps and a field that a -grading_* option grades too. Null when no field is set.
std::shared_ptr<const PlateFields> readPlateFields(MPI_Comm comm, RunParameters* record, const Plate& plate,
                                                   const Grading& grading);

// Refuses, naming the field's option, a property out of range at a site of the model's nx x ny
// grid (E, mu_s, p <= 0, mu_k > mu_s): its value and where on the plate. Same on every rank.
void checkPlateFields(const Grading& grading, const Plate& plate, int nx, int ny);
// The same at the sites of a grid of unequal cells (the FEM's edge-graded mesh), sampled by
// `sampler` as the model samples them.
void checkPlateFields(const Grading& grading, const Plate& plate, const PropertySampler& sampler, const SiteGrid& grid);

// The spring-block model's check: the above on its block centres (an E field that varies along
// y is taken: its stiffnesses are then per block, sbm/lattice.hpp).
void checkSpringBlockFields(const Grading& grading, const Plate& plate, int blocksPerSide);

}  // namespace gradfric
