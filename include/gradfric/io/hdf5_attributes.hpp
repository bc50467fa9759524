#pragma once
// The conventions every gradfric HDF5 file follows (ensemble, FEM history, studies):
//  - string attributes are variable-length UTF-8 strings (h5py reads str, h5dump prints text);
//  - flags and counts are 32-bit integers, never doubles;
//  - every dataset carries `units` (UCUM-like text, "1" for a pure number) and `description`;
//  - axes are HDF5 dimension scales, so h5py (`dset.dims`) and xarray (h5netcdf) see names;
//  - the resolved options are one record: a group whose attributes are the values (text), with
//    subgroups units/ and origin/ holding each option's unit and where it came from.
#include "gradfric/io/hdf5_handle.hpp"

#include <string>
#include <utility>
#include <vector>

namespace gradfric {
class RunParameters;  // core/options.hpp
}  // namespace gradfric

namespace gradfric::io {

// One resolved option of a scene.
struct Attribute {
  std::string name;  // without the leading dash: "sbm_E"
  std::string value;
  std::string unit;
  std::string origin;  // default, set, derived
};

// A group without access/modification times (the file depends on the results only).
H5Group createGroup(hid_t parent, const char* name);
// The names of the links (datasets, groups) of a group, in name order.
std::vector<std::string> linkNames(hid_t group);

void writeStringAttribute(hid_t object, const std::string& name, const std::string& value);
void writeIntAttribute(hid_t object, const std::string& name, int value);
void writeRealAttribute(hid_t object, const std::string& name, double value);
// "" if the attribute is not a string.
std::string readStringAttribute(hid_t attribute);
// All attributes of an object as (name, text), sorted by name.
std::vector<std::pair<std::string, std::string>> readStringAttributes(hid_t object);

// Sets the units and description attributes of a dataset.
void describe(hid_t dataset, const std::string& units, const std::string& description);

// Makes dataset a dimension scale named name and attaches it to dimension dim of each target.
void makeDimensionScale(hid_t scale, const std::string& name);
void attachScale(hid_t dataset, hid_t scale, unsigned dim);

// The option record (see above) as group `name` of parent. Collective in a parallel file.
void writeOptionRecord(hid_t parent, const char* name, const std::vector<Attribute>& options);
std::vector<Attribute> readOptionRecord(hid_t parent, const char* name);
// Every option a run resolved, as the record stores it: the name without its leading dash, the
// value and unit as printed, the origin as text (default, set, derived).
std::vector<Attribute> optionAttributes(const RunParameters& record);

}  // namespace gradfric::io
