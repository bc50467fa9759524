#include "gradfric/fem/output.hpp"

#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/xdmf.hpp"
#include "gradfric/fem/error_estimate.hpp"
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/physics/property_sampler.hpp"

#include <hdf5.h>
#include <petscdmplex.h>
#include <petscfe.h>
#include <petscviewerhdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace gradfric::fem {

namespace {

std::string stem(const std::string& path) {
  const auto dot = path.rfind('.');
  const auto slash = path.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path;
  return path.substr(0, dot);
}

const char* originText(OptionOrigin o) {
  return o == OptionOrigin::Default ? "default" : o == OptionOrigin::User ? "set" : "derived";
}

}  // namespace

OutputFiles::OutputFiles(MPI_Comm comm, const FemParameters& params) : comm_(comm), params_(params) {
  if (params.output.empty()) {
    if (!params.snapshotTimes.empty())
      throw InputError("-fem_snapshot_times", "(given)", "only together with -output <file.h5>");
    return;
  }
  path_ = params.output;
  provenance_ = io::collectProvenance(comm);  // collective: the same record on every rank
  if (!params.snapshotTimes.empty()) {
    fieldsPath_ = stem(path_) + "_fields.h5";
    xmfPath_ = stem(path_) + "_fields.xmf";
    pending_ = params.snapshotTimes;
    std::sort(pending_.begin(), pending_.end());
  }
  // Every file planned before any work, refused on every rank alike (io::OutputPlan).
  auto plan = [&](const std::string& path) {
    io::OutputRequest request;
    request.option = "-output";
    request.path = path;
    request.value = path_;
    request.temporarySuffix = ".tmp";
    request.overwrite = params.overwrite;
    request.overwriteOption = "-output_overwrite";
    return io::OutputPlan::decide(comm, request);
  };
  historyPlan_ = plan(path_);
  if (!fieldsPath_.empty()) {
    fieldsPlan_ = plan(fieldsPath_);
    xmfPlan_ = plan(xmfPath_);
  }
}

OutputFiles::~OutputFiles() {
  if (viewer_) PetscViewerDestroy(&viewer_);
  if (contactDM_) DMDestroy(&contactDM_);
  if (stressDM_) DMDestroy(&stressDM_);
  if (!finished_) {  // failed run: leave nothing half-written, and any earlier result whole
    for (const auto* plan : {&historyPlan_, &fieldsPlan_, &xmfPlan_})
      if (*plan) (*plan)->discard(comm_);
  }
}

StepObserver OutputFiles::snapshotObserver(PlateModel& model) {
  if (path_.empty()) return {};
  pressureResponse_ = std::make_unique<PressureResponseRecorder>(model);
  return [this, &model](double t, Vec state) {
    pressureResponse_->observe(model);
    while (!pending_.empty() && t >= pending_.front() - 0.5 * model.timeStep()) {
      pending_.erase(pending_.begin());
      writeSnapshot(model, state, t);
    }
  };
}

void OutputFiles::createFieldDMs(PlateModel& model) {
  MPI_Comm comm = model.comm();
  PetscFE fe = nullptr;
  GF_CALL(DMClone(model.dm(), &contactDM_));
  GF_CALL(PetscFECreateLagrange(comm, 3, 4, PETSC_FALSE, 1, 1, &fe));
  GF_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(fe), "contact"));
  GF_CALL(DMSetField(contactDM_, 0, nullptr, reinterpret_cast<PetscObject>(fe)));
  GF_CALL(PetscFEDestroy(&fe));
  GF_CALL(DMCreateDS(contactDM_));
  GF_CALL(DMClone(model.dm(), &stressDM_));
  GF_CALL(PetscFECreateLagrange(comm, 3, 6, PETSC_FALSE, 0, 1, &fe));
  GF_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(fe), "stress"));
  GF_CALL(DMSetField(stressDM_, 0, nullptr, reinterpret_cast<PetscObject>(fe)));
  GF_CALL(PetscFEDestroy(&fe));
  GF_CALL(DMCreateDS(stressDM_));
}

namespace {

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
  writeRealsAttribute(map, "extent", m.extent, 4);
  writeRealsAttribute(map, "mu_window", m.window, 2);
  writeIntAttribute(map, "samples", static_cast<int>(m.samples));
  writeRealAttribute(map, "mean", m.mean);
  writeRealAttribute(map, "moment_over_H", m.momentOverThickness);
}

PetscLogEvent outputEvent() {
  static PetscLogEvent event = 0;
  if (!event) {
    PetscClassId id = 0;
    GF_CALL(PetscClassIdRegister("gradfric FEM output", &id));
    GF_CALL(PetscLogEventRegister("GfFemOutput", id, &event));
  }
  return event;
}
}  // namespace

void OutputFiles::writeSnapshot(PlateModel& model, Vec state, double t) {
  if (fieldsPath_.empty()) return;
  struct EventScope {
    PetscLogEvent e;
    explicit EventScope(PetscLogEvent ev) : e(ev) { PetscLogEventBegin(e, 0, 0, 0, 0); }
    ~EventScope() { PetscLogEventEnd(e, 0, 0, 0, 0); }
  } scope(outputEvent());
  try {
    writeFields(model, state, t);
  } catch (const std::exception& e) {
    // A collective write failed, perhaps on this rank only: unwinding would reach the collective
    // close of the viewer and wait there for ever. One line, then every rank ends.
    int rank = 0;
    MPI_Comm_rank(comm_, &rank);
    abortJob(comm_, "writing " + fieldsPlan_->workPath() + " failed on rank " + std::to_string(rank) + ": " + e.what());
  }
}

void OutputFiles::writeFields(PlateModel& model, Vec state, double t) {
  const std::string tmp = fieldsPlan_->workPath();
  if (!viewer_) {
    createFieldDMs(model);
    GF_CALL(PetscViewerHDF5Open(model.comm(), tmp.c_str(), FILE_MODE_WRITE, &viewer_));
    GF_CALL(PetscViewerPushFormat(viewer_, PETSC_VIEWER_HDF5_VIZ));
    GF_CALL(DMView(model.dm(), viewer_));
  }
  GF_CALL(DMSetOutputSequenceNumber(model.dm(), snapshots_, t));
  GF_CALL(DMSetOutputSequenceNumber(contactDM_, snapshots_, t));
  GF_CALL(DMSetOutputSequenceNumber(stressDM_, snapshots_, t));
  GF_CALL(VecView(state, viewer_));
  // Contact fields on the bottom nodes (owned blocks in the same order as the state's).
  Vec contact = nullptr, stress = nullptr;
  GF_CALL(DMGetGlobalVector(contactDM_, &contact));
  GF_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(contact), "bottom"));  // -> bottom_contact
  GF_CALL(VecZeroEntries(contact));
  PetscScalar* c = nullptr;
  GF_CALL(VecGetArray(contact, &c));
  for (const auto& n : model.contact().nodes()) {
    c[4 * n.block + 0] = n.pressure;
    c[4 * n.block + 1] = n.tx;
    c[4 * n.block + 2] = n.ty;
    c[4 * n.block + 3] = static_cast<double>(static_cast<int>(n.state));
  }
  GF_CALL(VecRestoreArray(contact, &c));
  GF_CALL(VecView(contact, viewer_));
  GF_CALL(DMRestoreGlobalVector(contactDM_, &contact));
  std::vector<std::array<double, 6>> cellStress;
  model.elastic().cellStresses(state, &cellStress);
  GF_CALL(DMGetGlobalVector(stressDM_, &stress));
  GF_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(stress), "cell"));  // -> cell_stress
  PetscScalar* s = nullptr;
  PetscInt n = 0;
  GF_CALL(VecGetLocalSize(stress, &n));
  if (n != 6 * static_cast<PetscInt>(cellStress.size())) throw std::runtime_error("stress output: unexpected layout");
  GF_CALL(VecGetArray(stress, &s));
  // cellStresses gives xx, yy, zz, yz, xz, xy; the file holds XDMF's Tensor6 order xx, xy, xz, yy, yz, zz.
  constexpr int kTensor6Order[6] = {0, 5, 4, 1, 3, 2};
  for (std::size_t i = 0; i < cellStress.size(); ++i)
    for (int k = 0; k < 6; ++k) s[6 * i + k] = cellStress[i][kTensor6Order[k]];
  GF_CALL(VecRestoreArray(stress, &s));
  GF_CALL(VecView(stress, viewer_));
  GF_CALL(DMRestoreGlobalVector(stressDM_, &stress));
  ++snapshots_;
}

void OutputFiles::writeHistory(const PlateModel& model, const FemRunResult& r, const RunParameters& record) {
  if (path_.empty()) return;
  // The pressure response's regression, gathered on rank 0 (collective; the same decision on every rank).
  std::optional<PressureResponseMap> response;
  if (pressureResponse_ && std::isfinite(r.friction.muStatic)) {
    try {
      response = pressureResponse_->finish(model, r.friction.muStatic);
    } catch (const std::runtime_error& e) {
      PetscPrintf(model.comm(), "gradfric-fem: no /pressure_response in the results file: %s\n", e.what());
    }
  }
  historyPlan_->writeOnRank0(model.comm(), [&](const std::string& tmp) {
    using namespace io;
    H5File file(GF_H5(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)));
    writeStringAttribute(file, "format", "gradfric-fem-history");
    writeIntAttribute(file, "format_version", 2);  // 2: conventions of the ensemble file (docs/fem.md)
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
      const int every = std::max(1, params_.historyEvery);
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
    {  // The property fields used: E per cell column, friction per bottom-face column (both vary along x only).
      const FemParameters& q = model.params();
      const Grading& g = model.grading();
      const PropertySampler sampler(g, q.nx, q.ny);  // the fields (-field_*) or the bands
      std::vector<double> x, modulus, muS, muK;
      for (int i = 0; i < q.nx; ++i) {
        const double centre = (i + 0.5) / q.nx;
        x.push_back(centre * q.plate.length);
        modulus.push_back(q.plate.youngsModulus * sampler.modulus(centre, 0.5));
        muS.push_back(q.plate.muStatic * sampler.muStatic(centre, 0.5));
        muK.push_back(q.plate.muKinetic * sampler.muKinetic(centre, 0.5));
      }
      if (g.fields) {  // fields may vary along y: every bottom cell, [ny][nx] row-major
        std::vector<double> maps[4];
        for (int j = 0; j < q.ny; ++j)
          for (int i = 0; i < q.nx; ++i) {
            const double u = (i + 0.5) / q.nx, v = (j + 0.5) / q.ny;
            maps[0].push_back(q.plate.youngsModulus * sampler.modulus(u, v));
            maps[1].push_back(q.plate.muStatic * sampler.muStatic(u, v));
            maps[2].push_back(q.plate.muKinetic * sampler.muKinetic(u, v));
            maps[3].push_back(q.plate.pressure * sampler.pressure(u, v));
          }
        H5Group fieldGroup = createGroup(file, "fields");
        const char* names[4] = {"E_map", "mu_s_map", "mu_k_map", "p_map"};
        const char* units[4] = {"Pa", "1", "1", "Pa"};
        for (int k = 0; k < 4; ++k) {
          H5Dataset d = vector(fieldGroup, names[k], maps[k], units[k],
                               "property field at the centre of every bottom cell, fem_ny x fem_nx row-major (docs/fields.md)");
          writeIntAttribute(d, "rows", q.ny);
          writeIntAttribute(d, "columns", q.nx);
        }
      }
      H5Group properties = createGroup(file, "properties");
      H5Dataset column = vector(properties, "x", x, "m", "centre of each cell column along the grading axis x");
      makeDimensionScale(column, "x");
      const H5Dataset fields[] = {
          vector(properties, "E", modulus, "Pa", "Young's modulus of every cell of the column"),
          vector(properties, "mu_s", muS, "1",
                 "local static coefficient of the bottom faces of the column (a node takes the area-weighted mean "
                 "of its faces)"),
          vector(properties, "mu_k", muK, "1", "local kinetic coefficient of the bottom faces of the column")};
      for (const auto& d : fields) attachScale(d, column, 0);
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
      H5Group provenance = createGroup(file, "provenance");
      writeProvenance(provenance, provenance_);
    }
    writeIntAttribute(file, "complete", 1);
  });
  historyWritten_ = true;
}

void OutputFiles::writeXdmf() {
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  int written = 1;
  if (rank == 0) {
    // The .xmf names the fields file (in place by now) and is written to its temporary.
    try {
      describeFieldsAndWriteXdmf(fieldsPath_, xmfPlan_->workPath());
    } catch (const std::exception& e) {
      written = 0;
      std::fprintf(stderr, "gradfric-fem: warning: could not write %s: %s\n", xmfPath_.c_str(), e.what());
    }
  }
  GF_CALL_MPI(MPI_Bcast(&written, 1, MPI_INT, 0, comm_));
  if (written)
    xmfPlan_->commit(comm_);
  else
    xmfPlan_->discard(comm_);
}

void OutputFiles::finish() {
  if (viewer_) {
    try {
      GF_CALL(PetscViewerPopFormat(viewer_));
      GF_CALL(PetscViewerDestroy(&viewer_));  // collective: the last writes of the fields file
    } catch (const std::exception& e) {
      int rank = 0;
      MPI_Comm_rank(comm_, &rank);
      abortJob(comm_, "writing " + fieldsPlan_->workPath() + " failed on rank " + std::to_string(rank) + ": " + e.what());
    }
  }
  GF_CALL_MPI(MPI_Barrier(comm_));
  finished_ = true;  // complete: a failed rename below keeps the new files under their temporary names
  // Renamed into place only now: an earlier result stays whole until here.
  if (historyPlan_ && historyWritten_) historyPlan_->commit(comm_);
  if (fieldsPlan_ && snapshots_ > 0) {
    fieldsPlan_->commit(comm_);
    writeXdmf();
  }
}

}  // namespace gradfric::fem
