#include "gradfric/fem/output.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"

#include <hdf5.h>
#include <petscdmplex.h>
#include <petscfe.h>
#include <petscviewerhdf5.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
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

void h5check(herr_t status, const char* what) {
  if (status < 0) throw std::runtime_error(std::string("HDF5 error: ") + what);
}

void writeDataset(hid_t group, const char* name, const std::vector<double>& data) {
  hsize_t n = data.size();
  hid_t space = H5Screate_simple(1, &n, nullptr);
  hid_t set = H5Dcreate2(group, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (set < 0) throw std::runtime_error(std::string("HDF5: cannot create dataset ") + name);
  if (n) h5check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), name);
  H5Dclose(set);
  H5Sclose(space);
}

void writeAttribute(hid_t object, const char* name, double value) {
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(object, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  h5check(H5Awrite(attr, H5T_NATIVE_DOUBLE, &value), name);
  H5Aclose(attr);
  H5Sclose(space);
}

void writeAttribute(hid_t object, const char* name, const std::string& value) {
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, std::max<std::size_t>(1, value.size()));
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  h5check(H5Awrite(attr, type, value.empty() ? " " : value.c_str()), name);
  H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
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
  for (std::size_t i = 0; i < cellStress.size(); ++i)
    for (int k = 0; k < 6; ++k) s[6 * i + k] = cellStress[i][k];
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
    const std::string tmp = path_ + ".tmp";
    hid_t file = H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (file < 0) throw std::runtime_error("HDF5: cannot create " + tmp);
    writeAttribute(file, "format", std::string("gradfric-fem-history"));
    writeAttribute(file, "format_version", 1.0);
    hid_t history = H5Gcreate2(file, "history", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const int every = std::max(1, params_.historyEvery);
    std::vector<double> t, mu, fn;
    for (std::size_t i = 0; i < r.time.size(); i += every) {
      t.push_back(r.time[i]);
      mu.push_back(r.mu[i]);
      fn.push_back(r.normalForce[i]);
    }
    writeDataset(history, "time", t);
    writeDataset(history, "mu", mu);
    writeDataset(history, "normal_force", fn);
    writeAttribute(history, "time_unit", std::string("s since the start of sliding"));
    writeAttribute(history, "mu_definition", std::string("|total tangential contact force| / (p L^2)"));
    H5Gclose(history);
    hid_t results = H5Gcreate2(file, "results", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    writeAttribute(results, "mu_s", r.friction.muStatic);
    writeAttribute(results, "mu_k", r.friction.muKinetic);
    writeAttribute(results, "peak_time", r.friction.peakTime);
    writeAttribute(results, "eq2_peak_time", model.params().eq2PeakTime());
    writeAttribute(results, "first_slip_time", r.friction.firstSlipTime);
    writeAttribute(results, "slide_start", r.slideStart);
    writeAttribute(results, "settled_normal_force", r.settledNormalForce);
    writeAttribute(results, "peak_confirmed", r.friction.peakConfirmed ? 1.0 : 0.0);
    writeAttribute(results, "kinetic_window_complete", r.friction.kineticComplete ? 1.0 : 0.0);
    writeAttribute(results, "dt", r.dt);
    writeAttribute(results, "stable_dt", r.stableDt);
    writeAttribute(results, "steps", static_cast<double>(r.steps));
    writeAttribute(results, "wall_seconds", r.wallPressure + r.wallSliding);
    H5Gclose(results);
    hid_t parameters = H5Gcreate2(file, "parameters", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    for (const auto& o : record.all()) {
      std::string name = o.name;
      while (!name.empty() && name[0] == '-') name.erase(0, 1);
      writeAttribute(parameters, name.c_str(), o.value + " [" + o.unit + "] (" + originText(o.origin) + ")");
    }
    H5Gclose(parameters);
    writeAttribute(file, "complete", 1.0);
    H5Fclose(file);
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
      const std::string script = std::string(PETSC_DIR) + "/" + PETSC_ARCH + "/lib/petsc/bin/petsc_gen_xdmf.py";
      const std::string alt = std::string(PETSC_DIR) + "/lib/petsc/bin/petsc_gen_xdmf.py";
      const std::string use = exists(script) ? script : alt;
      // Debian's python3-h5py belongs to the system interpreter (a pyenv python3 may lack it).
      const std::string python = exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
      const std::string command = python + " '" + use + "' '" + fieldsPath_ + "' > /dev/null 2>&1";
      if (std::system(command.c_str()) != 0 || !exists(xmfPath_))
        std::fprintf(stderr, "gradfric-fem: warning: could not write %s with %s\n", xmfPath_.c_str(), use.c_str());
    }
  }
  GF_CALL_MPI(MPI_Barrier(comm_));
  finished_ = true;
}

}  // namespace gradfric::fem
