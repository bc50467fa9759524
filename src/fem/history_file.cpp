// The FEM history file's content (include/gradfric/fem/history_file.hpp).
#include "gradfric/fem/history_file.hpp"

#include "gradfric/fem/error_estimate.hpp"
#include "gradfric/io/file_room.hpp"
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/io/hdf5_datasets.hpp"
#include "gradfric/fem/mesh_sites.hpp"
#include "gradfric/fem/plate_model.hpp"

#include <algorithm>
#include <limits>

namespace gradfric::fem {

namespace {

const char* originText(OptionOrigin o) {
  return o == OptionOrigin::Default ? "default" : o == OptionOrigin::User ? "set" : "derived";
}

void writeRealsAttribute(hid_t object, const char* name, const double* values, hsize_t n) {
  using namespace io;
  H5Space space(GF_H5(H5Screate_simple(1, &n, nullptr)));
  H5Attribute a(GF_H5(H5Acreate2(object, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT)));
  GF_H5(H5Awrite(a, H5T_NATIVE_DOUBLE, values));
}

// /pressure_response/g [ny+1][nx+1] with the extent of a property-field map (docs/fields.md).
void writePressureResponse(hid_t file, const PressureResponseMap& m) {
  using namespace io;
  H5Group group = createGroup(file, "pressure_response");
  const hsize_t dims[2] = {hsize_t(m.ny), hsize_t(m.nx)};
  H5Space space(GF_H5(H5Screate_simple(2, dims, nullptr)));
  H5Dataset map(GF_H5(H5Dcreate2(group, "g", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)));
  GF_H5(H5Dwrite(map, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, m.g.data()));
  describe(map, "1",
           "change of the bottom contact pressure per unit of mu(t), (1/p) dp_c/dmu, at every bottom node [ny+1][nx+1] "
           "(rows along y); least squares over the loading phase; -pressure_response fem reads it");
  // The node positions as the map's axes (dimension scales: named, with units, in h5py and xarray).
  const H5Dataset nodeY = createCoordinateScale(group, "node_y", m.nodeY, "m", "bottom node position along y");
  const H5Dataset nodeX = createCoordinateScale(group, "node_x", m.nodeX, "m", "bottom node position along x");
  attachScale(map, nodeY, 0);
  attachScale(map, nodeX, 1);
  writeRealsAttribute(map, "extent", m.extent, 4);
  writeRealsAttribute(map, "mu_window", m.window, 2);
  writeIntAttribute(map, "samples", static_cast<int>(m.samples));
  writeRealAttribute(map, "mean", m.mean);
  writeRealAttribute(map, "moment_over_H", m.momentOverThickness);
}

}  // namespace

std::uint64_t historyFileBytes(const HistoryContent& c) {
  const FemParameters& q = c.model.params();
  std::uint64_t bytes = 5 * 8 * (c.result.time.size() / std::max(1, c.historyEvery) + 1);  // the history
  bytes += 8 * 8 * static_cast<std::uint64_t>(q.nx) * (q.ny + 1);                         // properties, fields
  if (c.response) bytes += 8 * c.response->g.size();
  for (const auto& o : c.record.all()) bytes += 3 * (o.name.size() + 128) + o.value.size() + o.unit.size();
  for (const auto& [name, text] : c.provenance.optionsFiles) bytes += name.size() + text.size() + 128;
  return io::withMetadataRoom(bytes + c.provenance.commandLine.size() + 64 * 1024);
}

void writeHistoryFile(hid_t file, const HistoryContent& c) {
  using namespace io;
  const PlateModel& model = c.model;
  const FemRunResult& r = c.result;
  const RunParameters& record = c.record;
  const int historyEvery = c.historyEvery;
  const std::optional<PressureResponseMap>& response = c.response;
  writeStringAttribute(file, "format", "gradfric-fem-history");
  // 2: conventions of the ensemble file; 3: /fields maps 2D and /pressure_response/g on named
  // axes holding the positions; 4: /properties the values the physics used (the layers'), mu_s
  // and mu_k per bottom node on node_x (docs/fem.md)
  writeIntAttribute(file, "format_version", 4);
  writeIntAttribute(file, "complete", 0);
  auto vector = [](hid_t group, const char* name, const std::vector<double>& data, const char* units,
                   const char* description) {
    const hsize_t n = data.size();
    H5Space space(GF_H5(H5Screate_simple(1, &n, nullptr)));
    H5Dataset set(GF_H5(H5Dcreate2(group, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)));
    if (n) GF_H5(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()));
    describe(set, units, description);
    return set;
  };
  {
    H5Group history = createGroup(file, "history");
    const int every = std::max(1, historyEvery);
    std::vector<double> t, mu, fn, fx, fy;
    for (std::size_t i = 0; i < r.time.size(); i += every) {
      t.push_back(r.time[i]);
      mu.push_back(r.mu[i]);
      fn.push_back(r.normalForce[i]);
      fx.push_back(i < r.forceX.size() ? r.forceX[i] : std::numeric_limits<double>::quiet_NaN());
      fy.push_back(i < r.forceY.size() ? r.forceY[i] : std::numeric_limits<double>::quiet_NaN());
    }
    H5Dataset time = vector(history, "time", t, "s", "time since the start of sliding (step 2)");
    makeDimensionScale(time, "time");
    const H5Dataset series[] = {
        vector(history, "mu", mu, "1", "mu(t) = |total tangential contact force| / (p L^2)"),
        vector(history, "normal_force", fn, "1", "total normal contact force / (p L^2)"),
        vector(history, "force_x", fx, "N", "x component (grading axis) of the total tangential contact force"),
        vector(history, "force_y", fy, "N", "y component of the total tangential contact force")};
    for (const auto& d : series) attachScale(d, time, 0);
  }
  {
    H5Group results = createGroup(file, "results");
    writeRealAttribute(results, "mu_s", r.friction.muStatic);
    writeRealAttribute(results, "mu_k", r.friction.muKinetic);
    {  // the error bar (error_estimate.hpp): relative bound, NaN when not measured, and its basis
      const DiscretisationError e = discretisationError(model.params(), model.grading(), r.dt / r.stableDt);
      writeRealAttribute(results, "mu_s_discretisation_error",
                         e.measured ? e.relative : std::numeric_limits<double>::quiet_NaN());
      writeStringAttribute(results, "mu_s_error_basis", e.measured ? e.basis : "not measured: " + e.basis);
      writeRealAttribute(results, "mu_k_discretisation_error", std::numeric_limits<double>::quiet_NaN());
      writeStringAttribute(results, "mu_k_error_basis", "not measured: " + e.kineticBasis);
    }
    writeRealAttribute(results, "peak_time", r.friction.peakTime);
    writeRealAttribute(results, "eq2_peak_time", model.params().eq2PeakTime());
    writeRealAttribute(results, "first_slip_time", r.friction.firstSlipTime);
    writeRealAttribute(results, "slide_start", r.slideStart);
    writeRealAttribute(results, "settled_normal_force", r.settledNormalForce);
    writeIntAttribute(results, "peak_confirmed", r.friction.peakConfirmed ? 1 : 0);
    writeIntAttribute(results, "kinetic_window_complete", r.friction.kineticComplete ? 1 : 0);
    {  // the mu_k window used and its steadiness (docs/accuracy_fem_history.md, "The steady kinetic window")
      const FrictionSummary& f = r.friction;
      writeRealAttribute(results, "mu_k_window_start", f.kineticFrom);
      writeRealAttribute(results, "mu_k_window_end", f.kineticTo);
      writeRealAttribute(results, "mu_k_window_spread", f.kineticSpread);
      writeIntAttribute(results, "mu_k_window_steady", !f.kineticSteadyTested ? -1 : f.kineticSteady ? 1 : 0);
      writeRealAttribute(results, "mu_k_steady_tolerance", model.params().measurement.kineticSteadyTolerance);
    }
    writeRealAttribute(results, "dt", r.dt);
    writeRealAttribute(results, "stable_dt", r.stableDt);
    writeIntAttribute(results, "steps", static_cast<int>(r.steps));
    writeRealAttribute(results, "wall_seconds", r.wallPressure + r.wallSliding);
    H5Group units = createGroup(results, "units");
    for (const char* name : {"peak_time", "eq2_peak_time", "first_slip_time", "slide_start", "dt", "stable_dt",
                             "wall_seconds"})
      writeStringAttribute(units, name, "s");
    for (const char* name : {"mu_k_window_start", "mu_k_window_end"}) writeStringAttribute(units, name, "s");
    for (const char* name : {"mu_k_window_spread", "mu_k_window_steady", "mu_k_steady_tolerance"})
      writeStringAttribute(units, name, "1");
    for (const char* name : {"mu_s", "mu_k", "mu_s_discretisation_error", "mu_k_discretisation_error", "settled_normal_force", "peak_confirmed", "kinetic_window_complete",
                             "steps"})
      writeStringAttribute(units, name, "1");
  }
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
      H5Group fieldGroup = createGroup(file, "fields");
      std::vector<double> cx, cy;  // the bottom cells' centres: the maps' axes
      for (int i = 0; i < q.nx; ++i) cx.push_back(columns.unitCentre(i) * q.plate.length);
      for (int j = 0; j < q.ny; ++j) cy.push_back(rows.unitCentre(j) * q.plate.length);
      const H5Dataset y = createCoordinateScale(fieldGroup, "y", cy, "m", "centre of each bottom cell row along y");
      const H5Dataset x = createCoordinateScale(fieldGroup, "x", cx, "m", "centre of each bottom cell column along x");
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
        writeIntAttribute(d, "rows", q.ny);  // as before the maps were 2D: readers of format 2 files
        writeIntAttribute(d, "columns", q.nx);
      }
    }
    // /properties: the values the physics used, from the layers (property_profiles.hpp): per cell
    // on the column centres x, per node on the node positions node_x. Before format 4 mu_s and mu_k
    // were the fields at the column centres; the contact uses each node's area-weighted mean.
    H5Group properties = createGroup(file, "properties");
    std::vector<double> x, nodeX = model.mesh().axisX().nodes;
    for (int i = 0; i < q.nx; ++i) x.push_back(columns.unitCentre(i) * q.plate.length);
    H5Dataset column = vector(properties, "x", x, "m", "centre of each cell column along the grading axis x");
    makeDimensionScale(column, "x");
    H5Dataset node = vector(properties, "node_x", nodeX, "m", "position of each node column along x");
    makeDimensionScale(node, "node_x");
    for (const PropertyProfile& p : c.properties) {
      const H5Dataset d = vector(properties, p.name.c_str(), p.values, p.unit.c_str(), p.description.c_str());
      attachScale(d, p.perNode ? node : column, 0);
    }
  }
  if (response) writePressureResponse(file, *response);
  {
    std::vector<Attribute> options;
    for (const auto& o : record.all()) {
      std::string name = o.name;
      while (!name.empty() && name[0] == '-') name.erase(0, 1);
      options.push_back({name, o.value, o.unit, originText(o.origin)});
    }
    writeOptionRecord(file, "scene", options);
    H5Group group = createGroup(file, "provenance");
    writeProvenance(group, c.provenance);
  }
  writeIntAttribute(file, "complete", 1);
}

}  // namespace gradfric::fem
