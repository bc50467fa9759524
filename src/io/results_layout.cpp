// The layout of a results file (src/io/results_layout.hpp).
#include "results_layout.hpp"

#include "gradfric/io/file_room.hpp"
#include "gradfric/io/hdf5_datasets.hpp"

#include <hdf5_hl.h>

#include <algorithm>
#include <cstdint>
#include <limits>

namespace gradfric::io::detail {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The lengths of the axes of /properties: the lattice's N_b x N_b blocks, or the FEM's bottom cells
// (rows: 0 without property-field maps).
hsize_t mapColumns(const EnsembleLayout& l) { return l.springBlock() ? hsize_t(l.mapSide) : l.cellX.size(); }
hsize_t mapRows(const EnsembleLayout& l) { return l.springBlock() ? hsize_t(l.mapSide) : l.cellY.size(); }

}  // namespace

std::uint64_t layoutBytes(const EnsembleLayout& l, const SweepTable& sweep, const std::vector<Attribute>& scene) {
  const std::uint64_t P = l.points, R = l.realisations, C = l.historyCapacity, N = std::max(mapColumns(l), mapRows(l)),
                      S = l.snapshotTimes.size(), tasks = P * R;
  std::uint64_t bytes = 4 * (P + R + 2 * N + C + S) + 8 * (l.cellX.size() + l.cellY.size()) + P * 64;  // axes, sweep table
  for (const auto* v : {&sweep.modulus, &sweep.muStatic, &sweep.muKinetic, &sweep.blockModulus, &sweep.blockMuStatic,
                        &sweep.blockMuKinetic, &sweep.blockPressure})
    bytes += 8 * std::max<std::uint64_t>(v->size(), P * N);
  for (const auto* v : {&sweep.property, &sweep.profile})
    for (const auto& text : *v) bytes += text.size() + 8;
  for (const TaskDataset& d : taskDatasets(l)) {  // 8 bytes an element at most
    std::uint64_t extent = 1;
    for (const auto& axis : d.axes) extent *= axisSize(l, axis);
    bytes += tasks * 8 * extent;
  }
  bytes += 8 * S;  // /maps/snapshot_times
  for (const auto& c : l.statistics) {
    bytes += 8 * P + 256 + c.description.size();
    for (const auto& [name, value] : c.attributes) bytes += name.size() + value.size() + 128;
  }
  for (const auto& a : scene) bytes += 3 * (a.name.size() + 128) + a.value.size() + a.unit.size() + a.origin.size();
  return withMetadataRoom(bytes + 64 * 2048);  // ~64 datasets and groups with their attributes
}

void writeLayout(hid_t root, const EnsembleLayout& layout, const SweepTable& sweep, const std::vector<Attribute>& scene) {
  const bool sbm = layout.springBlock();
  writeStringAttribute(root, "format", layout.format);
  writeIntAttribute(root, "format_version", formatVersion(layout.format));
  writeIntAttribute(root, "complete", 0);
  writeIntAttribute(root, "points", layout.points);
  writeIntAttribute(root, "realisations", layout.realisations);
  writeIntAttribute(root, "history_capacity", layout.historyCapacity);
  if (sbm) {  // the lattice and its /maps; a FEM file has neither (its axes carry their lengths)
    writeIntAttribute(root, "map_side", layout.mapSide);
    writeIntAttribute(root, "first_slip_map", layout.firstSlipMap ? 1 : 0);
    writeIntAttribute(root, "friction_fields", layout.frictionFields ? 1 : 0);
  }

  // The scene: every resolved option as attributes; units and origins in subgroups.
  writeOptionRecord(root, "scene", scene);

  const hsize_t P = static_cast<hsize_t>(layout.points);
  const hsize_t R = static_cast<hsize_t>(layout.realisations);
  const hsize_t C = static_cast<hsize_t>(layout.historyCapacity);
  const hsize_t S = layout.snapshotTimes.size();

  // The axes: dimension scales at the root holding 0, 1, 2, ... (the index along each axis), but a
  // FEM file's bottom cells, which hold their centres.
  struct Axis {
    hid_t scale;
    hsize_t size;
  };
  std::vector<H5Dataset> scales;
  auto axis = [&](const char* name, hsize_t size, const char* description) {
    scales.push_back(createIndexScale(root, name, size, description));
    return Axis{scales.back().get(), size};
  };
  // A FEM file's bottom cells: their centres [m] (unequal on a graded mesh) along the axis.
  auto cells = [&](const char* name, const std::vector<double>& centres, const char* description) {
    scales.push_back(createCoordinateScale(root, name, centres, "m", description));
    return Axis{scales.back().get(), centres.size()};
  };
  const Axis point = axis("point", P, "sweep point index (row of /sweep)");
  const Axis realisation = axis("realisation", R, "realisation index within a sweep point");
  const hsize_t N = static_cast<hsize_t>(layout.mapSide);
  const Axis row = sbm ? axis("block_row", N, "block row (y) of the N_b x N_b lattice")
                   : !layout.cellY.empty() ? cells("cell_y", layout.cellY, "centre of each bottom cell row along y")
                                           : Axis{};
  const Axis column = sbm ? axis("block_column", N, "block column (x, the grading axis) of the lattice")
                          : cells("cell_x", layout.cellX, "centre of each bottom cell column along x (the grading axis)");
  const Axis sample = C > 0 ? axis("sample", C, "mu(t) history sample index") : Axis{};
  const Axis snapshot = S > 0 ? axis("snapshot", S, "index of the requested snapshot time") : Axis{};

  // A dataset with its axes attached and its units and description set.
  auto make = [&](hid_t group, const char* name, hid_t fileType, hid_t memType, const std::vector<Axis>& axes,
                  auto fill, const char* units, const char* description) {
    std::vector<hsize_t> dims;
    std::vector<hid_t> attached;
    for (const auto& a : axes) {
      dims.push_back(a.size);
      attached.push_back(a.scale);
    }
    return createDescribedDataset(group, name, fileType, memType, dims, fill, units, description, attached);
  };
  auto real = [&](hid_t group, const char* name, const std::vector<Axis>& axes, const char* units,
                  const char* description) {
    return make(group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, axes, kNaN, units, description);
  };

  {  // The sweep table, one row per point.
    H5Group group = createGroup(root, "sweep");
    std::string axes;
    for (const auto& a : sweep.axes) axes += (axes.empty() ? "" : ",") + a;
    writeStringAttribute(group, "axes", axes);
    auto column1 = [&](const char* name, const char* units, const char* description, const std::vector<double>& v) {
      H5Dataset d = real(group, name, {point}, units, description);
      writeSlab(d, H5T_NATIVE_DOUBLE, {0}, {P}, v.data(), H5P_DEFAULT);
    };
    column1("delta", "1", "grading amplitude Delta", sweep.delta);
    column1("theta", "degree", "sliding angle between the slider velocity and the grading axis x", sweep.theta);
    if (sbm) {  // the FEM's coefficients have no random dispersion
      column1("sigma", "1", "relative standard deviation of the local mu_s,i", sweep.sigma);
      column1("sigma_kinetic", "1", "relative standard deviation of the local mu_k,i", sweep.sigmaKinetic);
    }
    if (sweep.fieldValue.size() == P)  // the axis field_<parameter> names it (-ensemble_field)
      column1("field_value", "", "value of the swept property-field parameter (the axis field_<name>)", sweep.fieldValue);
    auto strings = [&](const char* name, const char* description, const std::vector<std::string>& values) {
      size_t width = 1;
      for (const auto& v : values) width = std::max(width, v.size());
      H5Dataset d = createStringDataset(group, name, P, width);
      describe(d, "", description);
      attachScale(d, point.scale, 0);
      writeStrings(d, values, H5P_DEFAULT);
    };
    strings("property", "graded property: E, friction or both", sweep.property);
    strings("profile", "grading profile: none, linear or triangular", sweep.profile);
    if (!layout.singleRun()) {  // one run is compared with nothing
      H5Dataset ref = make(group, "reference_point", H5T_STD_I32LE, H5T_NATIVE_INT, {point}, -1, "1",
                           "index of the non-graded point the relative variation uses; -1: none");
      writeSlab(ref, H5T_NATIVE_INT, {0}, {P}, sweep.referencePoint.data(), H5P_DEFAULT);
    }
  }
  {  // The property fields each point used (before the random dispersion of the friction).
    H5Group group = createGroup(root, "properties");
    const hsize_t columns = column.size, rows = row.size;
    auto field = [&](const char* name, const char* units, const char* description, const std::vector<double>& v) {
      H5Dataset d = real(group, name, {point, column}, units, description);
      if (v.size() == P * columns) writeSlab(d, H5T_NATIVE_DOUBLE, {0, 0}, {P, columns}, v.data(), H5P_DEFAULT);
    };
    // With property fields (-field_*), which may vary along y: every block's (bottom cell's) value, per point.
    auto map = [&](const char* name, const char* units, const char* description, const std::vector<double>& v) {
      if (v.empty() || rows == 0 || v.size() != P * rows * columns) return;
      H5Dataset d = real(group, name, {point, row, column}, units, description);
      writeSlab(d, H5T_NATIVE_DOUBLE, {0, 0, 0}, {P, rows, columns}, v.data(), H5P_DEFAULT);
    };
    if (sbm) {
      field("E", "Pa", "Young's modulus of each block column (the same in every row)", sweep.modulus);
      field("mu_s", "1",
            "mean local static coefficient of each block column; realisation r draws "
            "mu_s,i = mu_s * (1 + sigma * z) per block (docs/ensemble.md)",
            sweep.muStatic);
      field("mu_k", "1",
            "mean local kinetic coefficient of each block column; realisation r draws "
            "mu_k,i = mu_k * (1 + sigma_kinetic * z) per block (docs/ensemble.md)",
            sweep.muKinetic);
      map("E_map", "Pa", "Young's modulus of every block (property fields, docs/fields.md)", sweep.blockModulus);
      map("mu_s_map", "1", "mean local static coefficient of every block, before dispersion", sweep.blockMuStatic);
      map("mu_k_map", "1", "mean local kinetic coefficient of every block, before dispersion", sweep.blockMuKinetic);
      map("p_map", "Pa", "normal pressure of every block (its normal force is p l^2)", sweep.blockPressure);
    } else {  // the FEM: the fields at the bottom cells' centres, no dispersion
      field("E", "Pa", "Young's modulus at the centre of each bottom cell column, on the middle row y = L/2", sweep.modulus);
      field("mu_s", "1", "local static coefficient at the centre of each bottom cell column, on the middle row y = L/2",
            sweep.muStatic);
      field("mu_k", "1", "local kinetic coefficient at the centre of each bottom cell column, on the middle row y = L/2",
            sweep.muKinetic);
      map("E_map", "Pa", "Young's modulus at the centre of every bottom cell (property fields, docs/fields.md)",
          sweep.blockModulus);
      map("mu_s_map", "1", "local static coefficient at the centre of every bottom cell", sweep.blockMuStatic);
      map("mu_k_map", "1", "local kinetic coefficient at the centre of every bottom cell", sweep.blockMuKinetic);
      map("p_map", "Pa", "normal pressure field at the centre of every bottom cell (docs/fields.md)", sweep.blockPressure);
    }
  }
  {  // What every task writes (results_schema.hpp), each group made where its first dataset is.
    const std::vector<std::pair<std::string, Axis>> named = {
        {"sample", sample}, {"snapshot", snapshot}, {"block_row", row}, {"block_column", column},
        {"cell_y", row},    {"cell_x", column}};
    std::vector<std::pair<std::string, H5Group>> groups;
    for (const TaskDataset& spec : taskDatasets(layout)) {
      const std::string groupName = spec.path.substr(0, spec.path.find('/'));
      if (groups.empty() || groups.back().first != groupName) {
        groups.emplace_back(groupName, createGroup(root, groupName.c_str()));
        if (groupName == "maps" && S > 0) {  // the requested times, beside the maps taken at them
          H5Dataset requested = real(groups.back().second, "snapshot_times", {snapshot}, "s", "the requested snapshot times");
          writeSlab(requested, H5T_NATIVE_DOUBLE, {0}, {S}, layout.snapshotTimes.data(), H5P_DEFAULT);
        }
      }
      std::vector<Axis> axes{point, realisation};
      for (const auto& name : spec.axes)
        axes.push_back(std::find_if(named.begin(), named.end(), [&](const auto& a) { return a.first == name; })->second);
      const hid_t group = groups.back().second;
      const std::string name = spec.path.substr(groupName.size() + 1);
      // Under /run no scales: a scale's REFERENCE_LIST would name /run's datasets, and h5diff
      // --exclude-path /run would still compare them through it.
      std::vector<hsize_t> dims;
      std::vector<hid_t> attached;
      for (const auto& a : axes) {
        dims.push_back(a.size);
        if (spec.scales) attached.push_back(a.scale);
      }
      createTaskDataset(group, name, spec, dims, attached);
    }
  }
  {  // The statistics: the real columns, then the integer ones.
    H5Group group = createGroup(root, "statistics");
    for (const bool integer : {false, true})
      for (const StatisticColumn& c : layout.statistics) {
        if (c.integer != integer) continue;
        H5Dataset d = integer ? make(group, c.name.c_str(), H5T_STD_I32LE, H5T_NATIVE_INT, {point}, 0,
                                     c.units.c_str(), c.description.c_str())
                              : real(group, c.name.c_str(), {point}, c.units.c_str(), c.description.c_str());
        for (const auto& [attribute, value] : c.attributes) writeStringAttribute(d, attribute, value);
      }
  }
}

void readLayout(hid_t root, EnsembleLayout* layout, SweepTable* sweep) {
  H5Attribute format(GF_H5(H5Aopen(root, "format", H5P_DEFAULT)));
  layout->format = readStringAttribute(format);
  if (layout->format != kFormatName && layout->format != kFemSweepFormatName && layout->format != kFemRunFormatName)
    throw Hdf5Error("not a gradfric ensemble results file (attribute format is not " + std::string(kFormatName) +
                    ", " + kFemSweepFormatName + " or " + kFemRunFormatName + ")");
  const int version = readScalarAttribute<int>(root, "format_version", H5T_NATIVE_INT, 0);
  if (version != formatVersion(layout->format))
    throw Hdf5Error("results file format version " + std::to_string(version) + ", this build writes " +
                    std::to_string(formatVersion(layout->format)) + " (" + layout->format + ")");
  layout->points = readScalarAttribute<int>(root, "points", H5T_NATIVE_INT, 0);
  layout->realisations = readScalarAttribute<int>(root, "realisations", H5T_NATIVE_INT, 0);
  layout->historyCapacity = readScalarAttribute<int>(root, "history_capacity", H5T_NATIVE_INT, 0);
  layout->mapSide = readScalarAttribute<int>(root, "map_side", H5T_NATIVE_INT, 0);
  layout->firstSlipMap = readScalarAttribute<int>(root, "first_slip_map", H5T_NATIVE_INT, 0) != 0;
  layout->frictionFields = readScalarAttribute<int>(root, "friction_fields", H5T_NATIVE_INT, 0) != 0;
  for (auto [name, centres] : {std::pair{"cell_x", &layout->cellX}, std::pair{"cell_y", &layout->cellY}})
    if (H5Lexists(root, name, H5P_DEFAULT) > 0) {  // a FEM file's axes
      H5Dataset d(GF_H5(H5Dopen2(root, name, H5P_DEFAULT)));
      *centres = readAll<double>(d, H5T_NATIVE_DOUBLE);
    }
  // One level at a time: HDF5 1.10 fails (and prints) on a path through a missing group.
  if (H5Lexists(root, "maps", H5P_DEFAULT) > 0 && H5Lexists(root, "maps/snapshot_times", H5P_DEFAULT) > 0) {
    H5Dataset d(GF_H5(H5Dopen2(root, "maps/snapshot_times", H5P_DEFAULT)));
    layout->snapshotTimes = readAll<double>(d, H5T_NATIVE_DOUBLE);
  }
  {
    H5Group stats(GF_H5(H5Gopen2(root, "statistics", H5P_DEFAULT)));
    for (const std::string& name : linkNames(stats)) {
      H5Dataset d(GF_H5(H5Dopen2(stats, name.c_str(), H5P_DEFAULT)));
      H5Type type(GF_H5(H5Dget_type(d)));
      StatisticColumn column;
      column.name = name;
      column.integer = H5Tget_class(type) != H5T_FLOAT;
      for (const auto& [attribute, text] : readStringAttributes(d))
        if (attribute == "units") column.units = text;
        else if (attribute == "description") column.description = text;
      layout->statistics.push_back(column);
    }
  }
  {
    H5Group group(GF_H5(H5Gopen2(root, "sweep", H5P_DEFAULT)));
    H5Attribute axes(GF_H5(H5Aopen(group, "axes", H5P_DEFAULT)));
    std::string text = readStringAttribute(axes);
    size_t start = 0;
    while (start < text.size()) {
      size_t end = text.find(',', start);
      if (end == std::string::npos) end = text.size();
      sweep->axes.push_back(text.substr(start, end - start));
      start = end + 1;
    }
    auto real = [&](const char* name) {
      H5Dataset d(GF_H5(H5Dopen2(group, name, H5P_DEFAULT)));
      return readAll<double>(d, H5T_NATIVE_DOUBLE);
    };
    sweep->delta = real("delta");
    sweep->theta = real("theta");
    // A FEM file has no sigma columns (its one surface is in /scene): left empty.
    if (H5Lexists(group, "sigma", H5P_DEFAULT) > 0) {
      sweep->sigma = real("sigma");
      sweep->sigmaKinetic = real("sigma_kinetic");
    }
    H5Dataset property(GF_H5(H5Dopen2(group, "property", H5P_DEFAULT)));
    sweep->property = readStrings(property);
    H5Dataset profile(GF_H5(H5Dopen2(group, "profile", H5P_DEFAULT)));
    sweep->profile = readStrings(profile);
    if (H5Lexists(group, "reference_point", H5P_DEFAULT) > 0) {
      H5Dataset ref(GF_H5(H5Dopen2(group, "reference_point", H5P_DEFAULT)));
      sweep->referencePoint = readAll<int>(ref, H5T_NATIVE_INT);
    } else {  // a single FEM run: no reference
      sweep->referencePoint.assign(sweep->delta.size(), -1);
    }
  }
}

}  // namespace gradfric::io::detail
