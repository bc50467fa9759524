#pragma once
// Output of the FEM driver (docs/fem.md, "Output").
//  <output>              parallel HDF5: the campaign layout of a one-point, one-realisation FEM
//                        sweep (io/results_file.hpp, format gradfric-fem-run): /realisations
//                        (mu_s, mu_k, peak_time, ...), /history (the friction observer's mu(t),
//                        sampled every -friction_history_interval), /statistics, /sweep,
//                        /properties, /scene, /run; plus the run's FEM extras under /fem
//                        (run_extras.hpp): its scalars, the normal force, the physics' property
//                        values, the field maps and /fem/pressure_response/g, the map the SBM reads.
//  <stem>_fields.h5/.xmf field snapshots in PETSc's HDF5 VIZ layout (ParaView opens the .xmf):
//                        /vertex_fields/state_displacement, state_velocity, bottom_contact (contact
//                        pressure, t_x, t_y, state 0 open 1 stick 2 slip), /cell_fields/cell_stress
//                        (xx, yy, zz, yz, xz, xy) [PETSc names them <vector>_<field>].
// Nothing is overwritten unless -output_overwrite; files are written under a temporary name
// and renamed at the end, every one of them complete, so a failed run leaves no half-written
// result and any earlier one whole. A write error (a full disk) ends every rank with one message
// and exit 1: the room for every write is reserved first (io/file_room.hpp).
#include "gradfric/core/options.hpp"
#include "gradfric/fem/pressure_response_recorder.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/io/provenance.hpp"
#include "gradfric/io/output_plan.hpp"

#include <memory>
#include <optional>
#include <string>

namespace gradfric::fem {

class OutputFiles {
public:
  // Collective. Plans every file before any work (io::OutputPlan): throws the same InputError on
  // every rank for an existing file without overwriting, a directory, a missing or read-only folder.
  OutputFiles(MPI_Comm comm, const FemParameters& params);
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  // An observer writing a snapshot at each requested time and recording the pressure response
  // (empty without an output file). Collective.
  StepObserver snapshotObserver(PlateModel& model);
  void writeSnapshot(PlateModel& model, Vec state, double tSliding);
  // The observer's state for a checkpoint (the pressure response's sums so far).
  void archiveObserver(StateArchive& a);
  // Collective: the results file, complete, under its temporary name (renamed in finish()). scene:
  // the options as read (a sweep's /scene), record: with what the run derived since (/fem/derived).
  void writeResults(const PlateModel& model, const FemRunResult& result, const RunParameters& scene,
                    const RunParameters& record);
  // Collective: closes the fields file, writes the .xmf, renames temporaries into place.
  void finish();

private:
  void createFieldDMs(PlateModel& model);
  void writeFields(PlateModel& model, Vec state, double tSliding);
  void reserveSnapshotRoom(PlateModel& model);
  void describeFields();
  MPI_Comm comm_;
  FemParameters params_;
  io::Provenance provenance_;
  std::string path_, fieldsPath_, xmfPath_;
  std::vector<double> pending_;  // snapshot times not yet written
  int snapshots_ = 0;
  PetscViewer viewer_ = nullptr;
  DM contactDM_ = nullptr, stressDM_ = nullptr;
  bool resultsWritten_ = false, finished_ = false;
  std::unique_ptr<PressureResponseRecorder> pressureResponse_;  // with an output file
  std::optional<io::OutputPlan> resultsPlan_, fieldsPlan_, xmfPlan_;  // where each file goes
};

}  // namespace gradfric::fem
