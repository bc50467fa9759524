#pragma once
// The layout of a results file (include/gradfric/io/results_file.hpp): every group, dataset and
// attribute, written once, serially, when the file is created, and read back when it is opened.
#include "gradfric/io/results_file.hpp"

#include <cstdint>
#include <vector>

namespace gradfric::io::detail {

void writeLayout(hid_t root, const EnsembleLayout& layout, const SweepTable& sweep, const std::vector<Attribute>& scene);
// The size of the file writeLayout makes, generously (the room reserved for it).
std::uint64_t layoutBytes(const EnsembleLayout& layout, const SweepTable& sweep, const std::vector<Attribute>& scene);
void readLayout(hid_t root, EnsembleLayout* layout, SweepTable* sweep);

}  // namespace gradfric::io::detail
