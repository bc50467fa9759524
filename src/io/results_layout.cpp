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

// One line on each statistics column (docs/ensemble.md has the formulas).
std::string statisticDescription(const std::string& name) {
  if (name == "finished") return "realisations finished";
  if (name == "target_half_width")
    return "95 % CI half-width reached of the quantity -ensemble_target bounds (-ensemble_target_type)";
  if (name == "target_met") return "1 if the point met -ensemble_target, 0 if it stopped at -ensemble_target_max";
  if (name == "peaks_unconfirmed") return "realisations whose peak was not confirmed before -sbm_t_max";
  const std::string of = name.substr(0, 4);  // mu_s or mu_k
  const std::string what = name.size() > 5 ? name.substr(5) : "";
  if (what == "count") return "finite values of " + of + " used for the statistics";
  if (what == "mean") return "mean of " + of + " over the finished realisations";
  if (what == "std") return "sample standard deviation (n - 1) of " + of;
  if (what == "stderr") return "standard error of the mean of " + of;
  if (what == "ci95_low") return "lower end of the 95 % confidence interval of the mean of " + of;
  if (what == "ci95_high") return "upper end of the 95 % confidence interval of the mean of " + of;
  if (what == "relative") return "(" + of + " - " + of + "_0) / " + of + "_0 against /sweep/reference_point";
  if (what == "relative_ci95") return "95 % confidence half-width of " + of + "_relative";
  if (what == "discretisation_error")  // FEM sweeps and spring-block ensembles
    return "relative discretisation error bound of " + of + " at the point's settings (NaN: not measured)";
  if (what == "discretisation_lattice") return "its lattice term (N_b ladder), relative (NaN: not measured)";
  if (what == "discretisation_dt") return "its time-step term, relative (NaN: not measured)";
  return name;
}

// What kind of interval a column is (its `interval` attribute; docs/ensemble.md, section 3), or "".
std::string statisticInterval(const std::string& name) {
  if (name.find("ci95") != std::string::npos || name == "target_half_width") {
    if (name.find("relative") != std::string::npos)
      return "95 % Student t half-width: the propagated standard error x t(0.975, min(n, n_0) - 1), or with "
             "common random numbers the paired differences' x t(0.975, pairs - 1)";
    return name == "target_half_width" ? "95 % Student t half-width (as mu_s_ci95_* and mu_s_relative_ci95)"
                                       : "95 % Student t, n - 1 degrees of freedom";
  }
  if (name.find("discretisation") != std::string::npos)
    return "bound from the convergence study (GCI with safety factor 1.25 and time-step term), not a statistical "
           "interval";
  return "";
}


}  // namespace

std::uint64_t layoutBytes(const EnsembleLayout& l, const SweepTable& sweep, const std::vector<Attribute>& scene) {
  const std::uint64_t P = l.points, R = l.realisations, C = l.historyCapacity, N = l.mapSide,
                      S = l.snapshotTimes.size(), tasks = P * R;
  std::uint64_t bytes = 4 * (P + R + 2 * N + C + S) + P * 64;  // axes, sweep table
  for (const auto* v : {&sweep.modulus, &sweep.muStatic, &sweep.muKinetic, &sweep.blockModulus, &sweep.blockMuStatic,
                        &sweep.blockMuKinetic, &sweep.blockPressure})
    bytes += 8 * std::max<std::uint64_t>(v->size(), P * N);
  for (const auto* v : {&sweep.property, &sweep.profile})
    for (const auto& text : *v) bytes += text.size() + 8;
  bytes += tasks * (46 + 12);                                           // /realisations, /run
  if (C > 0) bytes += tasks * (32 * C + 4);                             // /history
  bytes += tasks * 8 * N * N * ((l.firstSlipMap ? 1 : 0) + (l.frictionFields ? 2 : 0) + S) + 8 * S * (tasks + 1);
  bytes += 8 * P * (l.statisticsReal.size() + l.statisticsInteger.size()) + 256 * l.statisticsReal.size();
  for (const auto& note : l.statisticsNotes) bytes += note[1].size() + note[2].size() + 128;
  for (const auto& a : scene) bytes += 3 * (a.name.size() + 128) + a.value.size() + a.unit.size() + a.origin.size();
  return withMetadataRoom(bytes + 64 * 2048);  // ~64 datasets and groups with their attributes
}

void writeLayout(hid_t root, const EnsembleLayout& layout, const SweepTable& sweep, const std::vector<Attribute>& scene) {
  writeStringAttribute(root, "format", layout.format);
  writeIntAttribute(root, "format_version", kFormatVersion);
  writeIntAttribute(root, "complete", 0);
  writeIntAttribute(root, "points", layout.points);
  writeIntAttribute(root, "realisations", layout.realisations);
  writeIntAttribute(root, "history_capacity", layout.historyCapacity);
  writeIntAttribute(root, "map_side", layout.mapSide);
  writeIntAttribute(root, "first_slip_map", layout.firstSlipMap ? 1 : 0);
  writeIntAttribute(root, "friction_fields", layout.frictionFields ? 1 : 0);

  // The scene: every resolved option as attributes; units and origins in subgroups.
  writeOptionRecord(root, "scene", scene);

  const hsize_t P = static_cast<hsize_t>(layout.points);
  const hsize_t R = static_cast<hsize_t>(layout.realisations);
  const hsize_t C = static_cast<hsize_t>(layout.historyCapacity);
  const hsize_t N = static_cast<hsize_t>(layout.mapSide);
  const hsize_t S = layout.snapshotTimes.size();

  // The axes: dimension scales at the root holding 0, 1, 2, ... (the index along each axis).
  struct Axis {
    hid_t scale;
    hsize_t size;
  };
  std::vector<H5Dataset> scales;
  auto axis = [&](const char* name, hsize_t size, const char* description) {
    H5Dataset d = createDataset<int>(root, name, H5T_STD_I32LE, H5T_NATIVE_INT, {size}, 0);
    std::vector<int> index(size);
    for (hsize_t i = 0; i < size; ++i) index[i] = static_cast<int>(i);
    writeSlab(d, H5T_NATIVE_INT, {0}, {size}, index.data(), H5P_DEFAULT);
    describe(d, "1", description);
    makeDimensionScale(d, name);
    scales.push_back(std::move(d));
    return Axis{scales.back().get(), size};
  };
  const Axis point = axis("point", P, "sweep point index (row of /sweep)");
  const Axis realisation = axis("realisation", R, "realisation index within a sweep point");
  const Axis row = axis("block_row", N, "block row (y) of the N_b x N_b lattice");
  const Axis column = axis("block_column", N, "block column (x, the grading axis) of the lattice");
  const Axis sample = C > 0 ? axis("sample", C, "mu(t) history sample index") : Axis{};
  const Axis snapshot = S > 0 ? axis("snapshot", S, "index of the requested snapshot time") : Axis{};

  // A dataset with its axes attached and its units and description set.
  auto make = [&](hid_t group, const char* name, hid_t fileType, hid_t memType, const std::vector<Axis>& axes,
                  auto fill, const char* units, const char* description) {
    std::vector<hsize_t> dims;
    for (const auto& a : axes) dims.push_back(a.size);
    H5Dataset d = createDataset(group, name, fileType, memType, dims, fill);
    describe(d, units, description);
    for (unsigned i = 0; i < axes.size(); ++i) attachScale(d, axes[i].scale, i);
    return d;
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
    column1("sigma", "1", "relative standard deviation of the local mu_s,i", sweep.sigma);
    column1("sigma_kinetic", "1", "relative standard deviation of the local mu_k,i", sweep.sigmaKinetic);
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
    H5Dataset ref = make(group, "reference_point", H5T_STD_I32LE, H5T_NATIVE_INT, {point}, -1, "1",
                         "index of the non-graded point the relative variation uses; -1: none");
    writeSlab(ref, H5T_NATIVE_INT, {0}, {P}, sweep.referencePoint.data(), H5P_DEFAULT);
  }
  {  // The property fields each point used (before the random dispersion of the friction).
    H5Group group = createGroup(root, "properties");
    auto field = [&](const char* name, const char* units, const char* description, const std::vector<double>& v) {
      H5Dataset d = real(group, name, {point, column}, units, description);
      if (v.size() == P * N) writeSlab(d, H5T_NATIVE_DOUBLE, {0, 0}, {P, N}, v.data(), H5P_DEFAULT);
    };
    field("E", "Pa", "Young's modulus of each block column (the same in every row)", sweep.modulus);
    field("mu_s", "1",
          "mean local static coefficient of each block column; realisation r draws "
          "mu_s,i = mu_s * (1 + sigma * z) per block (docs/ensemble.md)",
          sweep.muStatic);
    field("mu_k", "1",
          "mean local kinetic coefficient of each block column; realisation r draws "
          "mu_k,i = mu_k * (1 + sigma_kinetic * z) per block (docs/ensemble.md)",
          sweep.muKinetic);
    // With property fields (-field_*), which may vary along y: every block's value, per point.
    auto map = [&](const char* name, const char* units, const char* description, const std::vector<double>& v) {
      if (v.size() != P * N * N) return;
      H5Dataset d = real(group, name, {point, row, column}, units, description);
      writeSlab(d, H5T_NATIVE_DOUBLE, {0, 0, 0}, {P, N, N}, v.data(), H5P_DEFAULT);
    };
    map("E_map", "Pa", "Young's modulus of every block (property fields, docs/fields.md)", sweep.blockModulus);
    map("mu_s_map", "1", "mean local static coefficient of every block, before dispersion", sweep.blockMuStatic);
    map("mu_k_map", "1", "mean local kinetic coefficient of every block, before dispersion", sweep.blockMuKinetic);
    map("p_map", "Pa", "normal pressure of every block (its normal force is p l^2)", sweep.blockPressure);
  }
  {
    H5Group group = createGroup(root, "realisations");
    const std::vector<Axis> pr{point, realisation};
    real(group, "mu_s", pr, "1", "global static friction coefficient: the maximum of mu(t) at the transition");
    real(group, "mu_k", pr, "1", "global kinetic coefficient: mean of mu(t) over the window after the peak; NaN: none");
    real(group, "peak_time", pr, "s", "time of the peak of mu(t)");
    real(group, "end_time", pr, "s", "simulated time reached");
    make(group, "peak_confirmed", H5T_STD_I8LE, H5T_NATIVE_INT8, pr, std::int8_t(0), "1",
         "1 if the peak was confirmed, 0 if the run stopped at -sbm_t_max first");
    make(group, "steps", H5T_STD_I64LE, H5T_NATIVE_INT64, pr, std::int64_t(0), "1", "time steps taken");
    make(group, "redrawn_blocks", H5T_STD_I32LE, H5T_NATIVE_INT, pr, 0, "1",
         "local coefficients redrawn to keep 0 < mu_k,i <= mu_s,i");
    make(group, "done", H5T_STD_I8LE, H5T_NATIVE_INT8, pr, std::int8_t(0), "1",
         "1: the task finished and its results are stored; 0: not run (yet)");
  }
  {
    // No dimension scales here: a scale's REFERENCE_LIST would then name /run's datasets, and
    // h5diff --exclude-path /run would still compare them through it.
    H5Group group = createGroup(root, "run");
    H5Dataset wall = createDataset<double>(group, "wall_seconds", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {P, R}, kNaN);
    describe(wall, "s", "wall time of each task [point, realisation]");
    H5Dataset rank = createDataset<int>(group, "rank", H5T_STD_I32LE, H5T_NATIVE_INT, {P, R}, -1);
    describe(rank, "1", "the MPI rank that ran each task [point, realisation]");
  }
  if (C > 0) {
    H5Group group = createGroup(root, "history");
    const std::vector<Axis> prc{point, realisation, sample};
    real(group, "time", prc, "s", "time of each mu(t) sample; NaN after the last sample");
    real(group, "mu", prc, "1", "mu(t) = |sum of the slider forces| / (p L^2); NaN after the last sample");
    real(group, "force_x", prc, "N", "x component (grading axis) of the sum of the slider-spring forces on the plate");
    real(group, "force_y", prc, "N", "y component of the sum of the slider-spring forces on the plate");
    make(group, "length", H5T_STD_I32LE, H5T_NATIVE_INT, {point, realisation}, 0, "1", "number of samples of each task");
  }
  if (layout.firstSlipMap || layout.frictionFields || S > 0) {
    H5Group group = createGroup(root, "maps");
    if (layout.frictionFields) {
      real(group, "mu_s_local", {point, realisation, row, column}, "1",
           "local static coefficient mu_s,i of each block, as drawn for the realisation");
      real(group, "mu_k_local", {point, realisation, row, column}, "1",
           "local kinetic coefficient mu_k,i of each block, as drawn for the realisation");
    }
    if (layout.firstSlipMap)
      real(group, "first_slip_time", {point, realisation, row, column}, "s",
           "time of each block's first slip; NaN: never slipped");
    if (S > 0) {
      H5Dataset requested = real(group, "snapshot_times", {snapshot}, "s", "the requested snapshot times");
      writeSlab(requested, H5T_NATIVE_DOUBLE, {0}, {S}, layout.snapshotTimes.data(), H5P_DEFAULT);
      real(group, "snapshot_time", {point, realisation, snapshot}, "s",
           "the time each snapshot was taken; NaN if the run ended before");
      real(group, "sigma_x_over_p", {point, realisation, snapshot, row, column}, "1",
           "longitudinal stress sigma_x / p of each block at each snapshot");
    }
  }
  {
    H5Group group = createGroup(root, "statistics");
    for (const auto& name : layout.statisticsReal) {
      H5Dataset d = real(group, name.c_str(), {point}, "1", statisticDescription(name).c_str());
      if (const std::string interval = statisticInterval(name); !interval.empty())
        writeStringAttribute(d, "interval", interval);
      for (const auto& [column, attribute, value] : layout.statisticsNotes)
        if (column == name) writeStringAttribute(d, attribute, value);
    }
    for (const auto& name : layout.statisticsInteger)
      make(group, name.c_str(), H5T_STD_I32LE, H5T_NATIVE_INT, {point}, 0, "1", statisticDescription(name).c_str());
  }
}

void readLayout(hid_t root, EnsembleLayout* layout, SweepTable* sweep) {
  H5Attribute format(GF_H5(H5Aopen(root, "format", H5P_DEFAULT)));
  layout->format = readStringAttribute(format);
  if (layout->format != kFormatName && layout->format != kFemSweepFormatName)
    throw Hdf5Error("not a gradfric ensemble results file (attribute format is not " + std::string(kFormatName) +
                    " or " + kFemSweepFormatName + ")");
  const int version = readScalarAttribute<int>(root, "format_version", H5T_NATIVE_INT, 0);
  if (version != kFormatVersion)
    throw Hdf5Error("results file format version " + std::to_string(version) + ", this build writes " +
                    std::to_string(kFormatVersion));
  layout->points = readScalarAttribute<int>(root, "points", H5T_NATIVE_INT, 0);
  layout->realisations = readScalarAttribute<int>(root, "realisations", H5T_NATIVE_INT, 0);
  layout->historyCapacity = readScalarAttribute<int>(root, "history_capacity", H5T_NATIVE_INT, 0);
  layout->mapSide = readScalarAttribute<int>(root, "map_side", H5T_NATIVE_INT, 0);
  layout->firstSlipMap = readScalarAttribute<int>(root, "first_slip_map", H5T_NATIVE_INT, 0) != 0;
  layout->frictionFields = readScalarAttribute<int>(root, "friction_fields", H5T_NATIVE_INT, 0) != 0;
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
      (H5Tget_class(type) == H5T_FLOAT ? layout->statisticsReal : layout->statisticsInteger).push_back(name);
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
    sweep->sigma = real("sigma");
    sweep->sigmaKinetic = real("sigma_kinetic");
    H5Dataset property(GF_H5(H5Dopen2(group, "property", H5P_DEFAULT)));
    sweep->property = readStrings(property);
    H5Dataset profile(GF_H5(H5Dopen2(group, "profile", H5P_DEFAULT)));
    sweep->profile = readStrings(profile);
    H5Dataset ref(GF_H5(H5Dopen2(group, "reference_point", H5P_DEFAULT)));
    sweep->referencePoint = readAll<int>(ref, H5T_NATIVE_INT);
  }
}

}  // namespace gradfric::io::detail
