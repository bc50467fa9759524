#pragma once
// Datasets of the gradfric files: created allocated and filled (so that later writes by one rank
// touch no metadata), written and read whole or by hyperslab.
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/io/hdf5_handle.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace gradfric::io {

// Contiguous, allocated and filled with `fill` at creation.
template <typename T>
H5Dataset createDataset(hid_t parent, const char* name, hid_t fileType, hid_t memType, const std::vector<hsize_t>& dims,
                        T fill) {
  H5Space space(GF_H5(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr)));
  H5PropertyList dcpl(GF_H5(H5Pcreate(H5P_DATASET_CREATE)));
  GF_H5(H5Pset_obj_track_times(dcpl, false));
  GF_H5(H5Pset_layout(dcpl, H5D_CONTIGUOUS));
  GF_H5(H5Pset_alloc_time(dcpl, H5D_ALLOC_TIME_EARLY));
  GF_H5(H5Pset_fill_time(dcpl, H5D_FILL_TIME_ALLOC));
  GF_H5(H5Pset_fill_value(dcpl, memType, &fill));
  return H5Dataset(GF_H5(H5Dcreate2(parent, name, fileType, space, H5P_DEFAULT, dcpl, H5P_DEFAULT)));
}

// createDataset with its units and description set and scales[i] attached along dimension i.
template <typename T>
H5Dataset createDescribedDataset(hid_t parent, const char* name, hid_t fileType, hid_t memType,
                                 const std::vector<hsize_t>& dims, T fill, const std::string& units,
                                 const std::string& description, const std::vector<hid_t>& scales) {
  H5Dataset d = createDataset(parent, name, fileType, memType, dims, fill);
  describe(d, units, description);
  for (unsigned i = 0; i < scales.size(); ++i) attachScale(d, scales[i], i);
  return d;
}

// Fixed-width, null-padded strings, allocated at creation.
H5Dataset createStringDataset(hid_t parent, const char* name, hsize_t count, size_t width);
void writeStrings(hid_t dataset, const std::vector<std::string>& values, hid_t dxpl);
std::vector<std::string> readStrings(hid_t dataset);

// A dimension scale named name holding 0, 1, ..., size - 1 (int32, described): h5py and xarray
// (h5netcdf) see a named axis.
H5Dataset createIndexScale(hid_t parent, const char* name, hsize_t size, const std::string& description);
// A described float64 axis (positions, times) made a dimension scale named name.
H5Dataset createCoordinateScale(hid_t parent, const char* name, const std::vector<double>& values,
                                const std::string& units, const std::string& description);
// A float64 column written whole, described (units, description) and attached to scale along its
// one dimension; returned for further attributes.
H5Dataset writeDescribedColumn(hid_t parent, const std::string& name, const std::vector<double>& values,
                               const std::string& units, const std::string& description, hid_t scale);

// Writes a hyperslab [offset, offset + count) of a dataset from contiguous memory.
void writeSlab(hid_t dataset, hid_t memType, const std::vector<hsize_t>& offset, const std::vector<hsize_t>& count,
               const void* data, hid_t dxpl);

template <typename T>
std::vector<T> readAll(hid_t dataset, hid_t memType) {
  H5Space space(GF_H5(H5Dget_space(dataset)));
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  std::vector<T> out(static_cast<size_t>(std::max<hssize_t>(count, 0)));
  if (!out.empty()) GF_H5(H5Dread(dataset, memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()));
  return out;
}

template <typename T>
T readScalarAttribute(hid_t object, const char* name, hid_t memType, T fallback) {
  if (GF_H5(H5Aexists(object, name)) <= 0) return fallback;
  H5Attribute attribute(GF_H5(H5Aopen(object, name, H5P_DEFAULT)));
  T value{};
  GF_H5(H5Aread(attribute, memType, &value));
  return value;
}

}  // namespace gradfric::io
