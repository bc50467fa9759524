// Datasets of the gradfric files (include/gradfric/io/hdf5_datasets.hpp).
#include "gradfric/io/hdf5_datasets.hpp"

#include "gradfric/io/hdf5_attributes.hpp"

#include <cstring>

namespace gradfric::io {

H5Dataset createStringDataset(hid_t parent, const char* name, hsize_t count, size_t width) {
  H5Type type(GF_H5(H5Tcopy(H5T_C_S1)));
  GF_H5(H5Tset_size(type, std::max<size_t>(width, 1)));
  GF_H5(H5Tset_strpad(type, H5T_STR_NULLPAD));
  H5Space space(GF_H5(H5Screate_simple(1, &count, nullptr)));
  H5PropertyList dcpl(GF_H5(H5Pcreate(H5P_DATASET_CREATE)));
  GF_H5(H5Pset_obj_track_times(dcpl, false));
  GF_H5(H5Pset_alloc_time(dcpl, H5D_ALLOC_TIME_EARLY));
  return H5Dataset(GF_H5(H5Dcreate2(parent, name, type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT)));
}

void writeStrings(hid_t dataset, const std::vector<std::string>& values, hid_t dxpl) {
  H5Type type(GF_H5(H5Dget_type(dataset)));
  const size_t width = H5Tget_size(type);
  std::vector<char> buffer(values.size() * width, '\0');
  for (size_t i = 0; i < values.size(); ++i)
    std::memcpy(buffer.data() + i * width, values[i].data(), std::min(width, values[i].size()));
  if (!values.empty()) GF_H5(H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, dxpl, buffer.data()));
}

std::vector<std::string> readStrings(hid_t dataset) {
  H5Type type(GF_H5(H5Dget_type(dataset)));
  const size_t width = H5Tget_size(type);
  H5Space space(GF_H5(H5Dget_space(dataset)));
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  std::vector<char> buffer(static_cast<size_t>(count) * width + 1, '\0');
  if (count > 0) GF_H5(H5Dread(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()));
  std::vector<std::string> out;
  for (hssize_t i = 0; i < count; ++i) {
    const char* start = buffer.data() + i * width;
    out.emplace_back(start, strnlen(start, width));
  }
  return out;
}

void writeSlab(hid_t dataset, hid_t memType, const std::vector<hsize_t>& offset, const std::vector<hsize_t>& count,
               const void* data, hid_t dxpl) {
  hsize_t total = 1;
  for (auto c : count) total *= c;
  if (total == 0) return;
  H5Space fileSpace(GF_H5(H5Dget_space(dataset)));
  GF_H5(H5Sselect_hyperslab(fileSpace, H5S_SELECT_SET, offset.data(), nullptr, count.data(), nullptr));
  H5Space memSpace(GF_H5(H5Screate_simple(1, &total, nullptr)));
  GF_H5(H5Dwrite(dataset, memType, memSpace, fileSpace, dxpl, data));
}

H5Dataset createIndexScale(hid_t parent, const char* name, hsize_t size, const std::string& description) {
  // Allocated and filled at creation like every dataset of a parallel file (createDataset).
  H5Dataset d = createDataset<int>(parent, name, H5T_STD_I32LE, H5T_NATIVE_INT, {size}, 0);
  std::vector<int> index(size);
  for (hsize_t i = 0; i < size; ++i) index[i] = static_cast<int>(i);
  writeSlab(d, H5T_NATIVE_INT, {0}, {size}, index.data(), H5P_DEFAULT);
  describe(d, "1", description);
  makeDimensionScale(d, name);
  return d;
}

H5Dataset createCoordinateScale(hid_t parent, const char* name, const std::vector<double>& values,
                                const std::string& units, const std::string& description) {
  const hsize_t n = values.size();
  H5Space space(GF_H5(H5Screate_simple(1, &n, nullptr)));
  H5Dataset d(GF_H5(H5Dcreate2(parent, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)));
  if (n) GF_H5(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()));
  describe(d, units, description);
  makeDimensionScale(d, name);
  return d;
}

H5Dataset writeDescribedColumn(hid_t parent, const std::string& name, const std::vector<double>& values,
                               const std::string& units, const std::string& description, hid_t scale) {
  const hsize_t n = values.size();
  H5Space space(GF_H5(H5Screate_simple(1, &n, nullptr)));
  H5Dataset d(GF_H5(H5Dcreate2(parent, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)));
  if (n) GF_H5(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()));
  describe(d, units, description);
  attachScale(d, scale, 0);
  return d;
}

}  // namespace gradfric::io
