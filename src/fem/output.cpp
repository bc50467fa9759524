#include "gradfric/fem/output.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/xdmf.hpp"
#include "gradfric/io/hdf5_attributes.hpp"

#include <hdf5.h>
#include <petscdmplex.h>
#include <petscfe.h>
#include <petscviewerhdf5.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace gradfric::fem {

namespace {

bool exists(const std::string& path) { return std::ifstream(path).good(); }

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
      throw InputError("-fem_snapshot_times", "(given)", "only together with -fem_output <file.h5>");
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
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int clash = 0;
  if (rank == 0 && !params.overwrite)
    clash = exists(path_) ? 1 : (!fieldsPath_.empty() && (exists(fieldsPath_) || exists(xmfPath_))) ? 2 : 0;
  GF_CALL_MPI(MPI_Bcast(&clash, 1, MPI_INT, 0, comm));
  if (clash)
    throw InputError("-fem_output", path_,
                     std::string("a path that does not exist yet (") + (clash == 1 ? path_ : fieldsPath_) +
                         " exists; add -fem_output_overwrite to replace it)");
  // Refuse an unwritable place before the run, not after it.
  int ok = 1;
  if (rank == 0) {
    std::ofstream probe(path_ + ".tmp");
    ok = probe.good() ? 1 : 0;
    probe.close();
    std::remove((path_ + ".tmp").c_str());
  }
  GF_CALL_MPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
  if (!ok) throw InputError("-fem_output", path_, "a writable path");
}

OutputFiles::~OutputFiles() {
  if (viewer_) PetscViewerDestroy(&viewer_);
  if (contactDM_) DMDestroy(&contactDM_);
  if (stressDM_) DMDestroy(&stressDM_);
  if (!finished_) {  // failed run: leave nothing half-written
    int rank = 0;
    MPI_Comm_rank(comm_, &rank);
    if (rank == 0) {
      if (!path_.empty()) std::remove((path_ + ".tmp").c_str());
      if (!fieldsPath_.empty()) std::remove((fieldsPath_ + ".tmp").c_str());
    }
  }
}

StepObserver OutputFiles::snapshotObserver(PlateModel& model) {
  if (pending_.empty()) return {};
  return [this, &model](double t, Vec state) {
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
  const std::string tmp = fieldsPath_ + ".tmp";
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
  for (const auto& n : model.bottomNodes()) {
    c[4 * n.block + 0] = n.pressure;
    c[4 * n.block + 1] = n.tx;
    c[4 * n.block + 2] = n.ty;
    c[4 * n.block + 3] = static_cast<double>(static_cast<int>(n.state));
  }
  GF_CALL(VecRestoreArray(contact, &c));
  GF_CALL(VecView(contact, viewer_));
  GF_CALL(DMRestoreGlobalVector(contactDM_, &contact));
  std::vector<std::array<double, 6>> cellStress;
  model.cellStresses(state, &cellStress);
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
  int rank = 0;
  MPI_Comm_rank(model.comm(), &rank);
  if (rank == 0) {
    using namespace io;
    const std::string tmp = path_ + ".tmp";
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
      writeRealAttribute(results, "mu_s", r.muS);
      writeRealAttribute(results, "mu_k", r.muK);
      writeRealAttribute(results, "peak_time", r.peakTime);
      writeRealAttribute(results, "eq2_peak_time", model.params().eq2PeakTime());
      writeRealAttribute(results, "first_slip_time", r.firstSlipTime);
      writeRealAttribute(results, "slide_start", r.slideStart);
      writeRealAttribute(results, "settled_normal_force", r.settledNormalForce);
      writeIntAttribute(results, "peak_confirmed", r.peakConfirmed ? 1 : 0);
      writeIntAttribute(results, "kinetic_window_complete", r.windowComplete ? 1 : 0);
      writeRealAttribute(results, "dt", r.dt);
      writeRealAttribute(results, "stable_dt", r.stableDt);
      writeIntAttribute(results, "steps", static_cast<int>(r.steps));
      writeRealAttribute(results, "wall_seconds", r.wallPressure + r.wallSliding);
      H5Group units = createGroup(results, "units");
      for (const char* name : {"peak_time", "eq2_peak_time", "first_slip_time", "slide_start", "dt", "stable_dt",
                               "wall_seconds"})
        writeStringAttribute(units, name, "s");
      for (const char* name : {"mu_s", "mu_k", "settled_normal_force", "peak_confirmed", "kinetic_window_complete",
                               "steps"})
        writeStringAttribute(units, name, "1");
    }
    {  // The property fields used: E per cell column, friction per bottom-face column (both vary along x only).
      const FemParameters& q = model.params();
      const Grading& g = model.grading();
      std::vector<double> x, modulus, muS, muK;
      for (int i = 0; i < q.nx; ++i) {
        const double centre = (i + 0.5) / q.nx;
        x.push_back(centre * q.plate.length);
        modulus.push_back(q.plate.youngsModulus * g.modulusFactor(centre));
        muS.push_back(q.plate.muStatic * g.frictionFactor(centre));
        muK.push_back(q.plate.muKinetic * g.frictionFactor(centre));
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
  }
  historyWritten_ = true;
}

void OutputFiles::finish() {
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  if (viewer_) {
    GF_CALL(PetscViewerPopFormat(viewer_));
    GF_CALL(PetscViewerDestroy(&viewer_));
  }
  GF_CALL_MPI(MPI_Barrier(comm_));
  if (rank == 0) {
    if (!path_.empty() && historyWritten_) std::rename((path_ + ".tmp").c_str(), path_.c_str());
    if (!fieldsPath_.empty() && snapshots_ > 0) {
      std::rename((fieldsPath_ + ".tmp").c_str(), fieldsPath_.c_str());
      try {
        describeFieldsAndWriteXdmf(fieldsPath_, xmfPath_);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "gradfric-fem: warning: could not write %s: %s\n", xmfPath_.c_str(), e.what());
      }
    }
  }
  GF_CALL_MPI(MPI_Barrier(comm_));
  finished_ = true;
}

}  // namespace gradfric::fem
