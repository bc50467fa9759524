#pragma once
// Writing the accuracy-study file (layout in docs/accuracy.md): one group per ladder with
// float64 datasets and string attributes. Shared by the SBM and FEM studies.
#include <hdf5.h>

#include <string>
#include <vector>

namespace gradfric::study {

void writeVector(hid_t group, const std::string& name, const std::vector<double>& values);
void writeText(hid_t object, const std::string& name, const std::string& value);

}  // namespace gradfric::study
