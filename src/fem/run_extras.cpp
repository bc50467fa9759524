// The FEM extras of a single run's results file (include/gradfric/fem/run_extras.hpp).
#include "gradfric/fem/run_extras.hpp"

#include "gradfric/io/file_room.hpp"
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/io/hdf5_datasets.hpp"
#include "gradfric/fem/mesh_sites.hpp"
#include "gradfric/fem/plate_model.hpp"

#include <algorithm>
#include <limits>

namespace gradfric::fem {

namespace {

void writeRealsAttribute(hid_t object, const char* name, const double* values, hsize_t n) {
  using namespace io;
  H5Space space(GF_H5(H5Screate_simple(1, &n, nullptr)));
  H5Attribute a(GF_H5(H5Acreate2(object, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT)));
  GF_H5(H5Awrite(a, H5T_NATIVE_DOUBLE, values));
}

// A map on the bottom node grid, [ny][nx] (rows along y), written as `name` in `group` with the
// node positions as its axes (dimension scales node_y, node_x: named, with units, in h5py and xarray).
io::H5Dataset writeNodeGridMap(hid_t group, const char* name, const std::vector<double>& values, int nx, int ny,
                               const std::vector<double>& nodeX, const std::vector<double>& nodeY, const char* unit,
                               const std::string& description) {
  using namespace io;
  const hsize_t dims[2] = {hsize_t(ny), hsize_t(nx)};
  H5Space space(GF_H5(H5Screate_simple(2, dims, nullptr)));
  H5Dataset map(GF_H5(H5Dcreate2(group, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)));
  GF_H5(H5Dwrite(map, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()));
  describe(map, unit, description);
  const H5Dataset y = createCoordinateScale(group, "node_y", nodeY, "m", "bottom node position along y");
  const H5Dataset x = createCoordinateScale(group, "node_x", nodeX, "m", "bottom node position along x");
  attachScale(map, y, 0);
  attachScale(map, x, 1);
  return map;
}

// /fem/pressure_response/g [ny+1][nx+1] with the extent of a property-field map (docs/fields.md).
void writePressureResponse(hid_t fem, const PressureResponseMap& m) {
  using namespace io;
  H5Group group = createGroup(fem, "pressure_response");
  const H5Dataset map = writeNodeGridMap(
      group, "g", m.g, m.nx, m.ny, m.nodeX, m.nodeY, "1",
      "change of the bottom contact pressure per unit of mu(t), (1/p) dp_c/dmu, at every bottom node [ny+1][nx+1] "
      "(rows along y); least squares over the loading phase; -pressure_response fem reads it");
  writeRealsAttribute(map, "extent", m.extent, 4);
  writeRealsAttribute(map, "mu_window", m.window, 2);
  writeIntAttribute(map, "samples", static_cast<int>(m.samples));
  writeRealAttribute(map, "mean", m.mean);
  writeRealAttribute(map, "moment_over_H", m.momentOverThickness);
}

// /fem/first_slip/time [ny+1][nx+1] on the bottom node grid (first_slip_map.hpp).
void writeFirstSlipMap(hid_t fem, const FirstSlipMap& m) {
  io::H5Group group = io::createGroup(fem, "first_slip");
  writeNodeGridMap(group, "time", m.time, m.nx, m.ny, m.nodeX, m.nodeY, "s",
                   "time since the start of sliding at which each bottom node first slid, [ny+1][nx+1] (rows along "
                   "y); NaN: it never slid");
}

// /fem/results: the run's scalars the campaign layout has no place for, with their units.
void writeResults(hid_t fem, const PlateModel& model, const FemRunResult& r, const std::string (&errorBasis)[2]) {
  using namespace io;
  H5Group results = createGroup(fem, "results");
  const FemParameters& q = model.params();
  const FrictionSummary& f = r.friction;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool filterMeasured = r.resolution.memoryTime > 0;  // the filter's rule applied (nodes slid at mu > 1)
  // The bars' fields are /statistics/mu_*_discretisation_* (as in a sweep); their text here.
  writeStringAttribute(results, "mu_s_error_basis", errorBasis[0]);
  writeStringAttribute(results, "mu_k_error_basis", errorBasis[1]);
  const std::pair<const char*, double> seconds[] = {
      {"eq2_peak_time", q.eq2PeakTime()}, {"first_slip_time", f.firstSlipTime}, {"slide_start", r.slideStart},
      {"mu_k_window_start", f.kineticFrom}, {"mu_k_window_end", f.kineticTo}, {"dt", r.dt}, {"stable_dt", r.stableDt},
      {"memory_relaxation_time", filterMeasured ? r.resolution.memoryTime : nan}};
  const std::pair<const char*, double> metres[] = {
      {"memory_cutoff_wavelength", filterMeasured ? r.resolution.cutoffWavelength : nan},
      {"largest_element_slid_above_one", r.resolution.aboveOne.nodes > 0 ? r.resolution.aboveOne.largestElement : nan}};
  const std::pair<const char*, double> numbers[] = {{"settled_normal_force", r.settledNormalForce},
                                                    {"mu_k_window_spread", f.kineticSpread},
                                                    {"mu_k_steady_tolerance", q.measurement.kineticSteadyTolerance},
                                                    {"area_slid_above_one", r.resolution.aboveOne.areaFraction}};
  const std::pair<const char*, int> flags[] = {
      {"kinetic_window_complete", f.kineticComplete ? 1 : 0},
      {"mu_k_window_steady", !f.kineticSteadyTested ? -1 : f.kineticSteady ? 1 : 0},
      {"nodes_slid_above_one", r.resolution.applies ? static_cast<int>(r.resolution.aboveOne.nodes) : -1}};
  H5Group units = createGroup(results, "units");
  for (const auto& [name, value] : seconds) {
    writeRealAttribute(results, name, value);
    writeStringAttribute(units, name, "s");
  }
  for (const auto& [name, value] : numbers) {
    writeRealAttribute(results, name, value);
    writeStringAttribute(units, name, "1");
  }
  for (const auto& [name, value] : metres) {
    writeRealAttribute(results, name, value);
    writeStringAttribute(units, name, "m");
  }
  for (const auto& [name, value] : flags) {
    writeIntAttribute(results, name, value);
    writeStringAttribute(units, name, "1");
  }
}

// /fem/history/normal_force [point, realisation, sample]: at the samples of /history/time.
void writeNormalForce(hid_t file, hid_t fem, const FemRunResult& r) {
  using namespace io;
  H5Group history = createGroup(fem, "history");
  H5Dataset sample(GF_H5(H5Dopen2(file, "sample", H5P_DEFAULT)));
  H5Dataset point(GF_H5(H5Dopen2(file, "point", H5P_DEFAULT)));
  H5Dataset realisation(GF_H5(H5Dopen2(file, "realisation", H5P_DEFAULT)));
  H5Space space(GF_H5(H5Dget_space(sample)));
  hsize_t capacity = 0;
  H5Sget_simple_extent_dims(space, &capacity, nullptr);
  std::vector<double> row = normalForceAtSamples(r);
  row.resize(capacity, std::numeric_limits<double>::quiet_NaN());
  H5Dataset d = createDescribedDataset(history, "normal_force", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {1, 1, capacity},
                                       std::numeric_limits<double>::quiet_NaN(), "1",
                                       "total normal contact force / (p L^2) at each sample of /history/time; NaN "
                                       "after the last sample",
                                       {point.get(), realisation.get(), sample.get()});
  writeSlab(d, H5T_NATIVE_DOUBLE, {0, 0, 0}, {1, 1, capacity}, row.data(), H5P_DEFAULT);
}

}  // namespace

std::vector<double> normalForceAtSamples(const FemRunResult& r) {
  std::vector<double> out;
  std::size_t step = 0;
  for (const double t : r.friction.time) {  // both in increasing time: one walk
    while (step < r.time.size() && r.time[step] < t) ++step;
    out.push_back(step < r.time.size() && r.time[step] == t ? r.normalForce[step]
                                                             : std::numeric_limits<double>::quiet_NaN());
  }
  return out;
}

std::uint64_t runExtrasBytes(const RunExtras& c) {
  const FemParameters& q = c.model.params();
  std::uint64_t bytes = 8 * (c.result.friction.time.size() + 4 * std::uint64_t(q.slideTime / q.measurement.historyInterval) + 16);
  bytes += 8 * 8 * static_cast<std::uint64_t>(q.nx + 1) * (q.ny + 1);  // properties, fields
  for (const PropertyProfile& p : c.properties) bytes += 8 * p.values.size() + p.description.size() + 256;
  if (c.response) bytes += 8 * (c.response->g.size() + c.response->nodeX.size() + c.response->nodeY.size());
  if (c.firstSlips) bytes += 8 * (c.firstSlips->time.size() + c.firstSlips->nodeX.size() + c.firstSlips->nodeY.size());
  for (const auto& a : c.derived) bytes += 3 * (a.name.size() + 128) + a.value.size() + a.unit.size() + a.origin.size();
  return bytes + 64 * 1024 + c.fieldsXdmf.size();
}

void writeRunExtras(hid_t file, const RunExtras& c) {
  using namespace io;
  const PlateModel& model = c.model;
  H5Group fem = createGroup(file, "fem");
  writeIntAttribute(fem, "format_version", kFemExtrasVersion);
  writeStringAttribute(fem, "description", "what a single gradfric-fem run stores beside the campaign layout (docs/fem.md)");
  if (!c.fieldsXdmf.empty()) writeStringAttribute(fem, "fields_xdmf", c.fieldsXdmf);
  writeResults(fem, model, c.result, c.errorBasis);
  writeOptionRecord(fem, "derived", c.derived);
  writeNormalForce(file, fem, c.result);
  {  // The property fields as given (-field_*), sampled at the bottom cells' centres: the input maps.
    const FemParameters& q = model.params();
    const Grading& g = model.grading();
    const MeshAxis columns = meshAxisX(q), rows = meshAxisY(q);  // mapped on a graded mesh
    if (g.fields) {  // fields may vary along y: every bottom cell, [ny][nx] row-major
      const PropertySampler sampler = meshSampler(g, columns, rows);
      std::vector<double> maps[4];
      for (int j = 0; j < q.ny; ++j)
        for (int i = 0; i < q.nx; ++i) {
          const double u = columns.unitCentre(i), v = rows.unitCentre(j);
          maps[0].push_back(q.plate.youngsModulus * sampler.modulus(u, v));
          maps[1].push_back(q.plate.muStatic * sampler.muStatic(u, v));
          maps[2].push_back(q.plate.muKinetic * sampler.muKinetic(u, v));
          maps[3].push_back(q.plate.pressure * sampler.pressure(u, v));
        }
      H5Group fieldGroup = createGroup(fem, "fields");
      std::vector<double> cx, cy;  // the bottom cells' centres: the maps' axes
      for (int i = 0; i < q.nx; ++i) cx.push_back(columns.unitCentre(i) * q.plate.length);
      for (int j = 0; j < q.ny; ++j) cy.push_back(rows.unitCentre(j) * q.plate.length);
      const H5Dataset y = createCoordinateScale(fieldGroup, "cell_y", cy, "m", "centre of each bottom cell row along y");
      const H5Dataset x = createCoordinateScale(fieldGroup, "cell_x", cx, "m", "centre of each bottom cell column along x");
      const char* names[4] = {"E_map", "mu_s_map", "mu_k_map", "p_map"};
      const char* units[4] = {"Pa", "1", "1", "Pa"};
      const hsize_t dims[2] = {hsize_t(q.ny), hsize_t(q.nx)};
      for (int k = 0; k < 4; ++k) {
        H5Space space(GF_H5(H5Screate_simple(2, dims, nullptr)));
        H5Dataset d(GF_H5(H5Dcreate2(fieldGroup, names[k], H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)));
        GF_H5(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, maps[k].data()));
        describe(d, units[k], "property field at the centre of every bottom cell, [fem_ny][fem_nx] (docs/fields.md)");
        attachScale(d, y, 0);
        attachScale(d, x, 1);
      }
    }
    // /fem/properties: the values the physics used, from the layers (property_profiles.hpp): per
    // cell on the column centres cell_x, per node on the node positions node_x (the contact uses each
    // node's area-weighted mean). /properties holds the fields at the column centres, as a sweep's.
    H5Group properties = createGroup(fem, "properties");
    std::vector<double> x, nodeX = model.mesh().axisX().nodes;
    for (int i = 0; i < q.nx; ++i) x.push_back(columns.unitCentre(i) * q.plate.length);
    // cell_x, cell_y: not x, y, which a campaign file's readers give the block centres
    const H5Dataset column =
        createCoordinateScale(properties, "cell_x", x, "m", "centre of each cell column along the grading axis x");
    const H5Dataset node = createCoordinateScale(properties, "node_x", nodeX, "m", "position of each node column along x");
    for (const PropertyProfile& p : c.properties)
      writeDescribedColumn(properties, p.name, p.values, p.unit, p.description, p.perNode ? node : column);
  }
  if (c.response) writePressureResponse(fem, *c.response);
  if (c.firstSlips) writeFirstSlipMap(fem, *c.firstSlips);
}

}  // namespace gradfric::fem
