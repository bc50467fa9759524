#include "gradfric/fem/output.hpp"

#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/format.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/campaign/campaign_file.hpp"
#include "gradfric/fem/log_events.hpp"
#include "gradfric/fem/run_extras.hpp"
#include "gradfric/fem/sweep.hpp"
#include "gradfric/fem/xdmf.hpp"
#include "gradfric/io/collective_file.hpp"
#include "gradfric/io/file_room.hpp"

#include <hdf5.h>
#include <petscdmplex.h>
#include <petscfe.h>
#include <petscviewerhdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <stdexcept>

namespace gradfric::fem {

namespace {

std::string stem(const std::string& path) {
  const auto dot = path.rfind('.');
  const auto slash = path.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path;
  return path.substr(0, dot);
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
  resultsPlan_ = plan(path_);
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
    for (const auto* plan : {&resultsPlan_, &fieldsPlan_, &xmfPlan_})
      if (*plan) (*plan)->discard(comm_);
  }
}

void OutputFiles::archiveObserver(StateArchive& a) {
  int recording = pressureResponse_ != nullptr;
  a.field("output.pressureResponse", recording);
  if (recording != (pressureResponse_ != nullptr)) throw CheckpointMismatch("the checkpoint's run had another output");
  if (pressureResponse_) pressureResponse_->archive(a);
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

void OutputFiles::writeSnapshot(PlateModel& model, Vec state, double t) {
  if (fieldsPath_.empty()) return;
  const LogEventScope timed(femLogEvents().output);
  reserveSnapshotRoom(model);  // a full disk: the same CollectiveError on every rank, before any write
  try {
    writeFields(model, state, t);
  } catch (const std::exception& e) {
    // Past the reservation a write can still fail (an I/O error), perhaps on this rank only,
    // inside a collective call the others wait in: unwinding would wait there too. One line,
    // then every rank ends.
    int rank = 0;
    MPI_Comm_rank(comm_, &rank);
    abortJob(comm_, "writing " + fieldsPlan_->workPath() + " failed on rank " + std::to_string(rank) + ": " + e.what());
  }
}

// The parallel fields file grows by a snapshot at a time, inside PETSc's collective HDF5 writes:
// rank 0 reserves the room first, from the file's end (twice the fields, the mesh with the first
// one, and room for HDF5's records, allocated but perhaps not written yet), and the ranks agree on
// the outcome. What is left of the room is given back when rank 0 describes the file at the end.
void OutputFiles::reserveSnapshotRoom(PlateModel& model) {
  const FemParameters& q = model.params();
  const std::uint64_t nodes = std::uint64_t(q.nx + 1) * (q.ny + 1) * (q.nz + 1);
  const std::uint64_t cells = static_cast<std::uint64_t>(model.mesh().globalCells());
  std::uint64_t bytes = 2 * 8 * (10 * nodes + 6 * cells);  // state, contact, stress: PETSc's and VIZ copies
  if (!viewer_) bytes += 8 * (40 * cells + 10 * nodes);     // the mesh (plex and VIZ)
  bytes = io::withMetadataRoom(bytes);
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  std::string error;
  if (rank == 0) {
    try {
      const std::string& tmp = fieldsPlan_->workPath();
      if (!viewer_) {
        io::createEmptyHdf5File(tmp, bytes);  // opened by the viewer in append mode: the room stays
      } else if (const std::string room = io::reserveRoom(tmp, bytes); !room.empty()) {
        throw std::runtime_error(io::writeFailure(tmp, "no room for snapshot " + std::to_string(snapshots_ + 1) +
                                                           " (" + std::to_string(bytes) + " bytes): " + room));
      }
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  agreeOnError(comm_, error);
}

void OutputFiles::writeFields(PlateModel& model, Vec state, double t) {
  const std::string tmp = fieldsPlan_->workPath();
  if (!viewer_) {
    createFieldDMs(model);
    GF_CALL(PetscViewerHDF5Open(model.comm(), tmp.c_str(), FILE_MODE_APPEND, &viewer_));  // made by rank 0
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

// The file a one-point, one-realisation FEM sweep of this run would write (the same schema, steps
// and statistics: sweep_run.cpp), named gradfric-fem-run, plus the run's FEM extras under /fem.
void OutputFiles::writeResults(const PlateModel& model, const FemRunResult& r, const RunParameters& scene,
                               const RunParameters& record) {
  if (path_.empty()) return;
  // The pressure response's regression, gathered on rank 0 (collective; the same decision on every rank).
  std::optional<PressureResponseMap> response;
  if (pressureResponse_ && std::isfinite(r.friction.muStatic)) {
    try {
      response = pressureResponse_->finish(model, r.friction.muStatic);
    } catch (const std::runtime_error& e) {
      PetscPrintf(model.comm(), "gradfric-fem: no /fem/pressure_response in the results file: %s\n", e.what());
    }
  }
  std::optional<FirstSlipMap> firstSlips;  // gathered on rank 0 (collective)
  if (params_.measurement.firstSlipMap) firstSlips = gatherFirstSlipMap(model);
  const std::vector<PropertyProfile> properties = gatherPropertyProfiles(model);  // collective
  FemSweep campaign = oneRunCampaign(params_, model.grading(), scene);
  // Written after the run: the history's capacity is its samples, none padded (a sweep's file,
  // made before its runs, keeps room for the longest a run can take).
  const std::size_t samples = std::min(r.friction.time.size(), r.friction.mu.size());
  campaign.layout.historyCapacity = static_cast<int>(std::max<std::size_t>(samples, 1));
  io::ResultsFile file = io::ResultsFile::create(comm_, resultsPlan_->workPath(), campaign.layout, campaign.table,
                                                 campaign.sceneAttributes);
  file.setRun(campaign.runAttributes, provenance_);
  io::TaskOutput task = taskOutputOf(r);  // as a sweep's point
  task.wallSeconds = r.wallPressure + r.wallSliding;
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  std::string error;
  if (rank == 0) {  // the group leader's write, as in the sweep's runner
    try {
      file.writeTask(task);
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  agreeOnError(comm_, error);
  file.flush();
  campaign::writeStatistics(file, 1, campaign.sweep.reference, false);
  writeErrorBars(file, campaign);  // the sweep's rule for its one point
  const std::string xdmf = snapshots_ > 0 ? xmfPath_.substr(xmfPath_.rfind('/') + 1) : "";
  std::vector<io::Attribute> derived;  // the record's entries the scene does not have
  std::set<std::string> known;
  for (const io::Attribute& a : io::optionAttributes(scene)) known.insert(a.name);
  for (const io::Attribute& a : io::optionAttributes(record))
    if (!known.count(a.name)) derived.push_back(a);
  const RunExtras extras{model, r, response, firstSlips, properties, xdmf, derived,
                         {study::describeBar(campaign.bars[0][0]), study::describeBar(campaign.bars[1][0])}};
  file.addGroups(runExtrasBytes(extras), [&](hid_t h5) { writeRunExtras(h5, extras); });
  file.markCompleteAndClose();  // complete; renamed into place with the fields files in finish()
  resultsWritten_ = true;
}

// Rank 0 adds the fields' descriptions to their file and writes the .xmf, both to their
// temporaries; the ranks agree on the outcome before anything is renamed.
void OutputFiles::describeFields() {
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  std::string error;
  if (rank == 0) {
    try {
      const std::string heavy = fieldsPath_.substr(fieldsPath_.rfind('/') + 1);  // beside the .xmf
      describeFieldsAndWriteXdmf(fieldsPlan_->workPath(), heavy, xmfPlan_->workPath());
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  agreeOnError(comm_, error);
}

void OutputFiles::finish() {
  if (!pending_.empty()) {  // snapshot times the run ended before: said, not dropped silently
    std::string times;
    for (double t : pending_) times += (times.empty() ? "" : ", ") + formatReal(t);
    PetscPrintf(comm_,
                "gradfric-fem: warning: %zu snapshot(s) not written, at %s s: the run ended before them (a run "
                "stops once its -friction_observables are known; -fem_stop_when_known false runs to "
                "-fem_slide_time)\n",
                pending_.size(), times.c_str());
  }
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
  if (fieldsPlan_ && snapshots_ > 0) describeFields();
  finished_ = true;  // complete: a failed rename below keeps the new files under their temporary names
  // Renamed into place only now, every file complete: an earlier result stays whole until here.
  if (resultsPlan_ && resultsWritten_) resultsPlan_->commit(comm_);
  if (fieldsPlan_ && snapshots_ > 0) {
    fieldsPlan_->commit(comm_);
    xmfPlan_->commit(comm_);
  }
}

}  // namespace gradfric::fem
