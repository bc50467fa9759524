#include "gradfric/io/hdf5_attributes.hpp"

#include "gradfric/core/options.hpp"

#include <hdf5_hl.h>

#include <cstring>

namespace gradfric::io {

H5Group createGroup(hid_t parent, const char* name) {
  H5PropertyList gcpl(GF_H5(H5Pcreate(H5P_GROUP_CREATE)));
  GF_H5(H5Pset_obj_track_times(gcpl, false));
  // Dense attribute storage: no 64 KiB limit on an attribute (options files are stored as text).
  GF_H5(H5Pset_attr_phase_change(gcpl, 0, 0));
  return H5Group(GF_H5(H5Gcreate2(parent, name, H5P_DEFAULT, gcpl, H5P_DEFAULT)));
}

std::vector<std::string> linkNames(hid_t group) {
  H5G_info_t info;
  GF_H5(H5Gget_info(group, &info));
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length = GF_H5(H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT));
    std::string name(static_cast<size_t>(length) + 1, '\0');
    GF_H5(H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT));
    name.resize(static_cast<size_t>(length));
    names.push_back(name);
  }
  return names;
}

void writeStringAttribute(hid_t object, const std::string& name, const std::string& value) {
  if (GF_H5(H5Aexists(object, name.c_str())) > 0) GF_H5(H5Adelete(object, name.c_str()));
  H5Type type(GF_H5(H5Tcopy(H5T_C_S1)));
  GF_H5(H5Tset_size(type, H5T_VARIABLE));
  GF_H5(H5Tset_cset(type, H5T_CSET_UTF8));
  H5Space space(GF_H5(H5Screate(H5S_SCALAR)));
  H5Attribute attribute(GF_H5(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT)));
  const char* text = value.c_str();
  GF_H5(H5Awrite(attribute, type, &text));
}

namespace {
template <typename T>
void writeScalar(hid_t object, const std::string& name, hid_t fileType, hid_t memType, T value) {
  if (GF_H5(H5Aexists(object, name.c_str())) > 0) {
    H5Attribute attribute(GF_H5(H5Aopen(object, name.c_str(), H5P_DEFAULT)));
    GF_H5(H5Awrite(attribute, memType, &value));
    return;
  }
  H5Space space(GF_H5(H5Screate(H5S_SCALAR)));
  H5Attribute attribute(GF_H5(H5Acreate2(object, name.c_str(), fileType, space, H5P_DEFAULT, H5P_DEFAULT)));
  GF_H5(H5Awrite(attribute, memType, &value));
}
}  // namespace

void writeIntAttribute(hid_t object, const std::string& name, int value) {
  writeScalar(object, name, H5T_STD_I32LE, H5T_NATIVE_INT, value);
}

void writeRealAttribute(hid_t object, const std::string& name, double value) {
  writeScalar(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, value);
}

std::string readStringAttribute(hid_t attribute) {
  H5Type type(GF_H5(H5Aget_type(attribute)));
  if (H5Tget_class(type) != H5T_STRING) return "";
  if (H5Tis_variable_str(type) > 0) {
    char* text = nullptr;
    H5Type memType(GF_H5(H5Tcopy(H5T_C_S1)));
    GF_H5(H5Tset_size(memType, H5T_VARIABLE));
    GF_H5(H5Tset_cset(memType, H5Tget_cset(type)));
    GF_H5(H5Aread(attribute, memType, &text));
    std::string out = text ? text : "";
    H5free_memory(text);
    return out;
  }
  const size_t width = H5Tget_size(type);
  std::vector<char> buffer(width + 1, '\0');
  GF_H5(H5Aread(attribute, type, buffer.data()));
  return std::string(buffer.data(), strnlen(buffer.data(), width));
}

std::vector<std::pair<std::string, std::string>> readStringAttributes(hid_t object) {
  std::vector<std::pair<std::string, std::string>> out;
  H5O_info_t info;
  GF_H5(H5Oget_info2(object, &info, H5O_INFO_NUM_ATTRS));
  for (hsize_t i = 0; i < info.num_attrs; ++i) {
    H5Attribute attribute(GF_H5(H5Aopen_by_idx(object, ".", H5_INDEX_NAME, H5_ITER_INC, i, H5P_DEFAULT, H5P_DEFAULT)));
    const ssize_t length = GF_H5(H5Aget_name(attribute, 0, nullptr));
    std::string name(static_cast<size_t>(length) + 1, '\0');
    GF_H5(H5Aget_name(attribute, name.size(), name.data()));
    name.resize(static_cast<size_t>(length));
    out.emplace_back(name, readStringAttribute(attribute));
  }
  return out;
}

void describe(hid_t dataset, const std::string& units, const std::string& description) {
  writeStringAttribute(dataset, "units", units);
  writeStringAttribute(dataset, "description", description);
}

void makeDimensionScale(hid_t scale, const std::string& name) { GF_H5(H5DSset_scale(scale, name.c_str())); }

void attachScale(hid_t dataset, hid_t scale, unsigned dim) { GF_H5(H5DSattach_scale(dataset, scale, dim)); }

void writeOptionRecord(hid_t parent, const char* name, const std::vector<Attribute>& options) {
  H5Group group = createGroup(parent, name);
  H5Group units = createGroup(group, "units");
  H5Group origins = createGroup(group, "origin");
  for (const auto& a : options) {
    writeStringAttribute(group, a.name, a.value);
    writeStringAttribute(units, a.name, a.unit);
    writeStringAttribute(origins, a.name, a.origin);
  }
}

std::vector<Attribute> readOptionRecord(hid_t parent, const char* name) {
  H5Group group(GF_H5(H5Gopen2(parent, name, H5P_DEFAULT)));
  H5Group units(GF_H5(H5Gopen2(group, "units", H5P_DEFAULT)));
  H5Group origins(GF_H5(H5Gopen2(group, "origin", H5P_DEFAULT)));
  auto values = readStringAttributes(group);
  auto unitValues = readStringAttributes(units);
  auto originValues = readStringAttributes(origins);
  std::vector<Attribute> out;
  for (size_t i = 0; i < values.size(); ++i) {
    Attribute a{values[i].first, values[i].second, "", ""};
    if (i < unitValues.size() && unitValues[i].first == a.name) a.unit = unitValues[i].second;
    if (i < originValues.size() && originValues[i].first == a.name) a.origin = originValues[i].second;
    out.push_back(std::move(a));
  }
  return out;
}

std::vector<Attribute> optionAttributes(const RunParameters& record) {
  std::vector<Attribute> out;
  for (const auto& o : record.all())
    out.push_back({o.name.rfind('-', 0) == 0 ? o.name.substr(1) : o.name, o.value, o.unit, originName(o.origin)});
  return out;
}

}  // namespace gradfric::io
