#include "gradfric/study/study_file.hpp"

#include "gradfric/io/hdf5_handle.hpp"

#include <algorithm>

namespace gradfric::study {

void writeVector(hid_t group, const std::string& name, const std::vector<double>& values) {
  const hsize_t n = values.size();
  io::H5Space space(GF_H5(H5Screate_simple(1, &n, nullptr)));
  io::H5Dataset set(GF_H5(H5Dcreate2(group, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)));
  if (n) GF_H5(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()));
}

void writeText(hid_t object, const std::string& name, const std::string& value) {
  io::H5Type type(GF_H5(H5Tcopy(H5T_C_S1)));
  GF_H5(H5Tset_size(type, std::max<size_t>(value.size(), 1)));
  io::H5Space space(GF_H5(H5Screate(H5S_SCALAR)));
  io::H5Attribute a(GF_H5(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT)));
  GF_H5(H5Awrite(a, type, value.c_str()));
}

}  // namespace gradfric::study
