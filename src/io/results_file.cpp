#include "gradfric/io/results_file.hpp"

#include <H5FDmpio.h>
#include <hdf5_hl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace gradfric::io {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

H5PropertyList accessList(MPI_Comm comm) {
  H5PropertyList fapl(GF_H5(H5Pcreate(H5P_FILE_ACCESS)));
  GF_H5(H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL));
  return fapl;
}

// Contiguous, allocated and filled at creation (collective), so that later raw writes by one
// rank touch no metadata.
template <typename T>
H5Dataset createDataset(hid_t parent, const char* name, hid_t fileType, hid_t memType, const std::vector<hsize_t>& dims,
                        T fill) {
  std::vector<hsize_t> safe(dims);
  for (auto& d : safe) d = std::max<hsize_t>(d, 0);
  H5Space space(GF_H5(H5Screate_simple(static_cast<int>(safe.size()), safe.data(), nullptr)));
  H5PropertyList dcpl(GF_H5(H5Pcreate(H5P_DATASET_CREATE)));
  GF_H5(H5Pset_obj_track_times(dcpl, false));
  GF_H5(H5Pset_layout(dcpl, H5D_CONTIGUOUS));
  GF_H5(H5Pset_alloc_time(dcpl, H5D_ALLOC_TIME_EARLY));
  GF_H5(H5Pset_fill_time(dcpl, H5D_FILL_TIME_ALLOC));
  GF_H5(H5Pset_fill_value(dcpl, memType, &fill));
  return H5Dataset(GF_H5(H5Dcreate2(parent, name, fileType, space, H5P_DEFAULT, dcpl, H5P_DEFAULT)));
}

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

// Writes a hyperslab [offset, offset + count) of a dataset from contiguous memory.
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
  if (what == "relative_error") return "propagated error of " + of + "_relative";
  if (what == "discretisation_error")  // FEM sweeps
    return "relative discretisation error bound of " + of + " at the point's settings (NaN: not measured)";
  return name;
}

}  // namespace

bool isHdf5File(const std::string& path) {
  htri_t result = -1;
  H5E_BEGIN_TRY { result = H5Fis_hdf5(path.c_str()); }
  H5E_END_TRY;
  return result > 0;
}

ResultsFile::~ResultsFile() {
  // A file not closed explicitly (an exception unwinding) is closed here; every rank unwinds
  // through the same path when the error is collective, which is the case for input errors.
}

ResultsFile ResultsFile::create(MPI_Comm comm, const std::string& path, const EnsembleLayout& layout,
                                const SweepTable& sweep, const std::vector<Attribute>& scene) {
  ResultsFile f;
  f.comm_ = comm;
  MPI_Comm_rank(comm, &f.rank_);
  f.layout_ = layout;
  f.sweep_ = sweep;
  H5PropertyList fapl = accessList(comm);
  H5PropertyList fcpl(GF_H5(H5Pcreate(H5P_FILE_CREATE)));
  f.file_ = H5File(GF_H5(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl, fapl)));
  f.independent_ = H5PropertyList(GF_H5(H5Pcreate(H5P_DATASET_XFER)));
  GF_H5(H5Pset_dxpl_mpio(f.independent_, H5FD_MPIO_INDEPENDENT));

  const hid_t root = f.file_.get();
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
    if (f.rank_ == 0) writeSlab(d, H5T_NATIVE_INT, {0}, {size}, index.data(), f.independent_);
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
      if (f.rank_ == 0) writeSlab(d, H5T_NATIVE_DOUBLE, {0}, {P}, v.data(), f.independent_);
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
      if (f.rank_ == 0) writeStrings(d, values, f.independent_);
    };
    strings("property", "graded property: E, friction or both", sweep.property);
    strings("profile", "grading profile: none, linear or triangular", sweep.profile);
    H5Dataset ref = make(group, "reference_point", H5T_STD_I32LE, H5T_NATIVE_INT, {point}, -1, "1",
                         "index of the non-graded point the relative variation uses; -1: none");
    if (f.rank_ == 0) writeSlab(ref, H5T_NATIVE_INT, {0}, {P}, sweep.referencePoint.data(), f.independent_);
  }
  {  // The property fields each point used (before the random dispersion of the friction).
    H5Group group = createGroup(root, "properties");
    auto field = [&](const char* name, const char* units, const char* description, const std::vector<double>& v) {
      H5Dataset d = real(group, name, {point, column}, units, description);
      if (f.rank_ == 0 && v.size() == P * N) writeSlab(d, H5T_NATIVE_DOUBLE, {0, 0}, {P, N}, v.data(), f.independent_);
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
      if (f.rank_ == 0) writeSlab(d, H5T_NATIVE_DOUBLE, {0, 0, 0}, {P, N, N}, v.data(), f.independent_);
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
      if (f.rank_ == 0) writeSlab(requested, H5T_NATIVE_DOUBLE, {0}, {S}, layout.snapshotTimes.data(), f.independent_);
      real(group, "snapshot_time", {point, realisation, snapshot}, "s",
           "the time each snapshot was taken; NaN if the run ended before");
      real(group, "sigma_x_over_p", {point, realisation, snapshot, row, column}, "1",
           "longitudinal stress sigma_x / p of each block at each snapshot");
    }
  }
  {
    H5Group group = createGroup(root, "statistics");
    for (const auto& name : layout.statisticsReal)
      real(group, name.c_str(), {point}, "1", statisticDescription(name).c_str());
    for (const auto& name : layout.statisticsInteger)
      make(group, name.c_str(), H5T_STD_I32LE, H5T_NATIVE_INT, {point}, 0, "1", statisticDescription(name).c_str());
  }
  f.openDatasets();
  f.flush();
  return f;
}

ResultsFile ResultsFile::open(MPI_Comm comm, const std::string& path) {
  ResultsFile f;
  f.comm_ = comm;
  MPI_Comm_rank(comm, &f.rank_);
  H5PropertyList fapl = accessList(comm);
  f.file_ = H5File(GF_H5(H5Fopen(path.c_str(), H5F_ACC_RDWR, fapl)));
  f.independent_ = H5PropertyList(GF_H5(H5Pcreate(H5P_DATASET_XFER)));
  GF_H5(H5Pset_dxpl_mpio(f.independent_, H5FD_MPIO_INDEPENDENT));
  f.readLayout();
  f.openDatasets();
  return f;
}

ResultsFile ResultsFile::openReadOnly(MPI_Comm comm, const std::string& path) {
  ResultsFile f;
  f.comm_ = comm;
  MPI_Comm_rank(comm, &f.rank_);
  H5PropertyList fapl = accessList(comm);
  f.file_ = H5File(GF_H5(H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl)));
  f.independent_ = H5PropertyList(GF_H5(H5Pcreate(H5P_DATASET_XFER)));
  GF_H5(H5Pset_dxpl_mpio(f.independent_, H5FD_MPIO_INDEPENDENT));
  f.readLayout();
  f.openDatasets();
  return f;
}

void ResultsFile::readLayout() {
  const hid_t root = file_.get();
  H5Attribute format(GF_H5(H5Aopen(root, "format", H5P_DEFAULT)));
  layout_.format = readStringAttribute(format);
  if (layout_.format != kFormatName && layout_.format != kFemSweepFormatName)
    throw Hdf5Error("not a gradfric ensemble results file (attribute format is not " + std::string(kFormatName) +
                    " or " + kFemSweepFormatName + ")");
  const int version = readScalarAttribute<int>(root, "format_version", H5T_NATIVE_INT, 0);
  if (version != kFormatVersion)
    throw Hdf5Error("results file format version " + std::to_string(version) + ", this build writes " +
                    std::to_string(kFormatVersion));
  layout_.points = readScalarAttribute<int>(root, "points", H5T_NATIVE_INT, 0);
  layout_.realisations = readScalarAttribute<int>(root, "realisations", H5T_NATIVE_INT, 0);
  layout_.historyCapacity = readScalarAttribute<int>(root, "history_capacity", H5T_NATIVE_INT, 0);
  layout_.mapSide = readScalarAttribute<int>(root, "map_side", H5T_NATIVE_INT, 0);
  layout_.firstSlipMap = readScalarAttribute<int>(root, "first_slip_map", H5T_NATIVE_INT, 0) != 0;
  layout_.frictionFields = readScalarAttribute<int>(root, "friction_fields", H5T_NATIVE_INT, 0) != 0;
  if (H5Lexists(root, "maps/snapshot_times", H5P_DEFAULT) > 0) {
    H5Dataset d(GF_H5(H5Dopen2(root, "maps/snapshot_times", H5P_DEFAULT)));
    layout_.snapshotTimes = readAll<double>(d, H5T_NATIVE_DOUBLE);
  }
  {
    H5Group stats(GF_H5(H5Gopen2(root, "statistics", H5P_DEFAULT)));
    for (const std::string& name : linkNames(stats)) {
      H5Dataset d(GF_H5(H5Dopen2(stats, name.c_str(), H5P_DEFAULT)));
      H5Type type(GF_H5(H5Dget_type(d)));
      (H5Tget_class(type) == H5T_FLOAT ? layout_.statisticsReal : layout_.statisticsInteger).push_back(name);
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
      sweep_.axes.push_back(text.substr(start, end - start));
      start = end + 1;
    }
    auto real = [&](const char* name) {
      H5Dataset d(GF_H5(H5Dopen2(group, name, H5P_DEFAULT)));
      return readAll<double>(d, H5T_NATIVE_DOUBLE);
    };
    sweep_.delta = real("delta");
    sweep_.theta = real("theta");
    sweep_.sigma = real("sigma");
    sweep_.sigmaKinetic = real("sigma_kinetic");
    H5Dataset property(GF_H5(H5Dopen2(group, "property", H5P_DEFAULT)));
    sweep_.property = readStrings(property);
    H5Dataset profile(GF_H5(H5Dopen2(group, "profile", H5P_DEFAULT)));
    sweep_.profile = readStrings(profile);
    H5Dataset ref(GF_H5(H5Dopen2(group, "reference_point", H5P_DEFAULT)));
    sweep_.referencePoint = readAll<int>(ref, H5T_NATIVE_INT);
  }
}

void ResultsFile::openDatasets() {
  const hid_t root = file_.get();
  auto open = [&](const char* name) { return H5Dataset(GF_H5(H5Dopen2(root, name, H5P_DEFAULT))); };
  muStatic_ = open("realisations/mu_s");
  muKinetic_ = open("realisations/mu_k");
  peakTime_ = open("realisations/peak_time");
  endTime_ = open("realisations/end_time");
  peakConfirmed_ = open("realisations/peak_confirmed");
  steps_ = open("realisations/steps");
  redrawn_ = open("realisations/redrawn_blocks");
  done_ = open("realisations/done");
  wallSeconds_ = open("run/wall_seconds");
  taskRank_ = open("run/rank");
  if (layout_.historyCapacity > 0) {
    historyTime_ = open("history/time");
    historyMu_ = open("history/mu");
    historyForceX_ = open("history/force_x");
    historyForceY_ = open("history/force_y");
    historyLength_ = open("history/length");
  }
  if (layout_.firstSlipMap) firstSlip_ = open("maps/first_slip_time");
  if (layout_.frictionFields) {
    localStatic_ = open("maps/mu_s_local");
    localKinetic_ = open("maps/mu_k_local");
  }
  if (!layout_.snapshotTimes.empty()) {
    snapshotTime_ = open("maps/snapshot_time");
    snapshots_ = open("maps/sigma_x_over_p");
  }
}

std::vector<Attribute> ResultsFile::sceneAttributes() const { return readOptionRecord(file_, "scene"); }

bool ResultsFile::complete() const { return readScalarAttribute<int>(file_, "complete", H5T_NATIVE_INT, 0) != 0; }

void ResultsFile::writeTask(const TaskOutput& t) {
  if (t.point < 0 || t.point >= layout_.points || t.realisation < 0 || t.realisation >= layout_.realisations)
    throw Hdf5Error("task (" + std::to_string(t.point) + ", " + std::to_string(t.realisation) + ") outside the file");
  const hsize_t p = static_cast<hsize_t>(t.point), r = static_cast<hsize_t>(t.realisation);
  const std::vector<hsize_t> at{p, r}, one{1, 1};
  const hid_t x = independent_;
  if (layout_.historyCapacity > 0) {
    const size_t n = std::min(t.friction.time.size(), t.friction.mu.size());
    if (n > static_cast<size_t>(layout_.historyCapacity))
      throw Hdf5Error("mu(t) history of task (" + std::to_string(t.point) + ", " + std::to_string(t.realisation) +
                      ") has " + std::to_string(n) + " samples, more than the file's capacity " +
                      std::to_string(layout_.historyCapacity));
    // The whole row, padding included, so that a task redone after an interruption overwrites
    // whatever a torn earlier write left.
    const hsize_t C = static_cast<hsize_t>(layout_.historyCapacity);
    std::vector<double> row(C, kNaN);
    std::copy(t.friction.time.begin(), t.friction.time.begin() + n, row.begin());
    writeSlab(historyTime_, H5T_NATIVE_DOUBLE, {p, r, 0}, {1, 1, C}, row.data(), x);
    auto writeRow = [&](hid_t dataset, const std::vector<double>& values) {
      std::fill(row.begin(), row.end(), kNaN);
      std::copy(values.begin(), values.begin() + std::min(n, values.size()), row.begin());
      writeSlab(dataset, H5T_NATIVE_DOUBLE, {p, r, 0}, {1, 1, C}, row.data(), x);
    };
    writeRow(historyMu_, t.friction.mu);
    writeRow(historyForceX_, t.friction.forceX);
    writeRow(historyForceY_, t.friction.forceY);
    const int length = static_cast<int>(n);
    writeSlab(historyLength_, H5T_NATIVE_INT, at, one, &length, x);
  }
  const hsize_t N = static_cast<hsize_t>(layout_.mapSide);
  if (layout_.firstSlipMap) {
    std::vector<double> map(N * N, kNaN);
    if (t.firstSlipTime.size() == map.size()) map = t.firstSlipTime;
    writeSlab(firstSlip_, H5T_NATIVE_DOUBLE, {p, r, 0, 0}, {1, 1, N, N}, map.data(), x);
  }
  if (layout_.frictionFields) {
    for (auto [dataset, values] : {std::pair{localStatic_.get(), &t.localStatic}, std::pair{localKinetic_.get(), &t.localKinetic}}) {
      std::vector<double> map(N * N, kNaN);
      if (values->size() == map.size()) map = *values;
      writeSlab(dataset, H5T_NATIVE_DOUBLE, {p, r, 0, 0}, {1, 1, N, N}, map.data(), x);
    }
  }
  const hsize_t S = layout_.snapshotTimes.size();
  if (S > 0) {
    std::vector<double> times(S, kNaN);
    std::vector<double> maps(S * N * N, kNaN);
    for (size_t s = 0; s < S && s < t.snapshots.size(); ++s) {
      if (s < t.snapshotTime.size()) times[s] = t.snapshotTime[s];
      if (t.snapshots[s].size() == N * N) std::copy(t.snapshots[s].begin(), t.snapshots[s].end(), maps.begin() + s * N * N);
    }
    writeSlab(snapshotTime_, H5T_NATIVE_DOUBLE, {p, r, 0}, {1, 1, S}, times.data(), x);
    writeSlab(snapshots_, H5T_NATIVE_DOUBLE, {p, r, 0, 0, 0}, {1, 1, S, N, N}, maps.data(), x);
  }
  writeSlab(muStatic_, H5T_NATIVE_DOUBLE, at, one, &t.friction.muStatic, x);
  writeSlab(muKinetic_, H5T_NATIVE_DOUBLE, at, one, &t.friction.muKinetic, x);
  writeSlab(peakTime_, H5T_NATIVE_DOUBLE, at, one, &t.friction.peakTime, x);
  writeSlab(endTime_, H5T_NATIVE_DOUBLE, at, one, &t.endTime, x);
  const std::int8_t confirmed = t.friction.peakConfirmed ? 1 : 0;
  writeSlab(peakConfirmed_, H5T_NATIVE_INT8, at, one, &confirmed, x);
  writeSlab(steps_, H5T_NATIVE_INT64, at, one, &t.steps, x);
  writeSlab(redrawn_, H5T_NATIVE_INT, at, one, &t.redrawnBlocks, x);
  writeSlab(wallSeconds_, H5T_NATIVE_DOUBLE, at, one, &t.wallSeconds, x);
  writeSlab(taskRank_, H5T_NATIVE_INT, at, one, &t.rank, x);
  // Last: the flag that says the task above is complete.
  const std::int8_t done = 1;
  writeSlab(done_, H5T_NATIVE_INT8, at, one, &done, x);
}

void ResultsFile::flush() { GF_H5(H5Fflush(file_, H5F_SCOPE_GLOBAL)); }

void ResultsFile::copyTasksFrom(const std::string& path) {
  if (rank_ == 0) {
    H5File old(GF_H5(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)));
    const hsize_t P = static_cast<hsize_t>(readScalarAttribute<int>(old, "points", H5T_NATIVE_INT, 0));
    const hsize_t R = static_cast<hsize_t>(readScalarAttribute<int>(old, "realisations", H5T_NATIVE_INT, 0));
    if (P > static_cast<hsize_t>(layout_.points) || R > static_cast<hsize_t>(layout_.realisations))
      throw Hdf5Error("cannot extend " + path + ": it has more points or realisations than the new file");
    // One point row of one dataset at a time: [p, 0..R, rest...].
    auto copy = [&](const std::string& name) {
      H5Dataset from(GF_H5(H5Dopen2(old, name.c_str(), H5P_DEFAULT)));
      H5Space space(GF_H5(H5Dget_space(from)));
      const int rankOf = H5Sget_simple_extent_ndims(space);
      std::vector<hsize_t> dims(static_cast<size_t>(std::max(rankOf, 0)));
      GF_H5(H5Sget_simple_extent_dims(space, dims.data(), nullptr));
      if (rankOf < 2 || dims[0] != P || dims[1] != R) return;  // not a per-task table
      H5Dataset to(GF_H5(H5Dopen2(file_, name.c_str(), H5P_DEFAULT)));
      H5Type type(GF_H5(H5Dget_type(from)));
      const size_t size = H5Tget_size(type);
      std::vector<hsize_t> count(dims), offset(dims.size(), 0);
      count[0] = 1;
      hsize_t items = 1;
      for (auto c : count) items *= c;
      std::vector<unsigned char> row(items * size);
      H5Space memory(GF_H5(H5Screate_simple(1, &items, nullptr)));
      for (hsize_t p = 0; p < P; ++p) {
        offset[0] = p;
        H5Space source(GF_H5(H5Dget_space(from)));
        GF_H5(H5Sselect_hyperslab(source, H5S_SELECT_SET, offset.data(), nullptr, count.data(), nullptr));
        GF_H5(H5Dread(from, type, memory, source, H5P_DEFAULT, row.data()));
        H5Space target(GF_H5(H5Dget_space(to)));
        GF_H5(H5Sselect_hyperslab(target, H5S_SELECT_SET, offset.data(), nullptr, count.data(), nullptr));
        GF_H5(H5Dwrite(to, type, memory, target, independent_, row.data()));
      }
    };
    for (const char* group : {"realisations", "run", "history", "maps"}) {
      if (H5Lexists(old, group, H5P_DEFAULT) <= 0) continue;
      H5Group g(GF_H5(H5Gopen2(old, group, H5P_DEFAULT)));
      for (const std::string& name : linkNames(g)) {
        H5O_info_t info;
        GF_H5(H5Oget_info_by_name2(g, name.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT));
        if (info.type != H5O_TYPE_DATASET) continue;  // the option record's groups of /run
        if (std::string(group) + "/" + name != "realisations/done") copy(std::string(group) + "/" + name);
      }
    }
    copy("realisations/done");  // last: a task is done once all its data is there
  }
  flush();
  flush();  // sync, barrier, sync: every rank reads what rank 0 copied
}

std::vector<std::uint8_t> ResultsFile::finishedTasks() const {
  auto flags = readAll<std::int8_t>(done_, H5T_NATIVE_INT8);
  return std::vector<std::uint8_t>(flags.begin(), flags.end());
}

std::vector<double> ResultsFile::readRealisationReal(const std::string& name) const {
  H5Dataset d(GF_H5(H5Dopen2(file_, ("realisations/" + name).c_str(), H5P_DEFAULT)));
  return readAll<double>(d, H5T_NATIVE_DOUBLE);
}

std::vector<std::int8_t> ResultsFile::readPeakConfirmed() const {
  return readAll<std::int8_t>(peakConfirmed_, H5T_NATIVE_INT8);
}

std::vector<double> ResultsFile::readStatistic(const std::string& name) const {
  H5Dataset d(GF_H5(H5Dopen2(file_, ("statistics/" + name).c_str(), H5P_DEFAULT)));
  return readAll<double>(d, H5T_NATIVE_DOUBLE);
}

void ResultsFile::writeStatistics(const std::vector<std::pair<std::string, std::vector<double>>>& real,
                                  const std::vector<std::pair<std::string, std::vector<int>>>& integer) {
  const hsize_t P = static_cast<hsize_t>(layout_.points);
  if (rank_ == 0) {
    for (const auto& [name, values] : real) {
      if (values.size() != P) throw Hdf5Error("statistics column " + name + " has the wrong length");
      H5Dataset d(GF_H5(H5Dopen2(file_, ("statistics/" + name).c_str(), H5P_DEFAULT)));
      writeSlab(d, H5T_NATIVE_DOUBLE, {0}, {P}, values.data(), independent_);
    }
    for (const auto& [name, values] : integer) {
      if (values.size() != P) throw Hdf5Error("statistics column " + name + " has the wrong length");
      H5Dataset d(GF_H5(H5Dopen2(file_, ("statistics/" + name).c_str(), H5P_DEFAULT)));
      writeSlab(d, H5T_NATIVE_INT, {0}, {P}, values.data(), independent_);
    }
  }
  flush();
}

void ResultsFile::setRunAttributes(const std::vector<Attribute>& attributes) {
  H5Group run(GF_H5(H5Gopen2(file_, "run", H5P_DEFAULT)));
  for (const auto& a : attributes) writeStringAttribute(run, a.name, a.value);
  flush();
}

void ResultsFile::setProvenance(const Provenance& provenance) {
  H5Group run(GF_H5(H5Gopen2(file_, "run", H5P_DEFAULT)));
  writeProvenance(run, provenance);
  flush();
}

void ResultsFile::markComplete() {
  writeIntAttribute(file_, "complete", 1);
  flush();
}

void ResultsFile::close() {
  muStatic_.reset();
  muKinetic_.reset();
  peakTime_.reset();
  endTime_.reset();
  peakConfirmed_.reset();
  steps_.reset();
  redrawn_.reset();
  done_.reset();
  wallSeconds_.reset();
  taskRank_.reset();
  historyTime_.reset();
  historyMu_.reset();
  historyForceX_.reset();
  historyForceY_.reset();
  historyLength_.reset();
  firstSlip_.reset();
  localStatic_.reset();
  localKinetic_.reset();
  snapshotTime_.reset();
  snapshots_.reset();
  independent_.reset();
  file_.reset();
}

}  // namespace gradfric::io
