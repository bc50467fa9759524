#pragma once
// The FEM model of the plate: DMPlex box mesh (METIS-partitioned), Q1 displacement and velocity,
// density-weighted lumped mass, the specialised elastic kernel (one precomputed 24x24 box-cell
// stiffness scaled by each cell's E) and the generic PetscFE residual kept as its reference,
// penalty contact with Eq. 1 friction on the bottom face, the top pressure and the top velocity.
//
// State vector (TS solution): per vertex [u_x u_y u_z v_x v_y v_z] (fields "displacement",
// "velocity"); the right-hand side is [v ; M^-1 (f_int + f_pressure + f_contact) - gamma v].
#include <petscsection.h>  // petsc_handle.hpp names PetscSFDestroy/PetscSectionDestroy without
#include <petscsf.h>       // including their headers
#include "gradfric/core/options.hpp"
#include "gradfric/core/petsc_handle.hpp"
#include "gradfric/fem/contact_penalty.hpp"
#include "gradfric/fem/hex_element.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/grading.hpp"

#include <petscdmplex.h>
#include <petscts.h>

#include <array>
#include <vector>

namespace gradfric::fem {

enum class Phase { Pressure, Sliding };

// The elastic internal force f = -sum_cells E_c K_hat (u_e + beta v_e), scattered into f.
// cellOffsets: 8 local offsets per cell (element node order); u, v, f index with them.
// v may be null (beta ignored). Hot kernel: one clone per instruction set.
void elasticKernel(PetscInt numCells, const PetscInt* cellOffsets, const double* cellModulus, const double* stiffness,
                   const double* u, const double* v, double beta, double* f);

// The stable step of the explicit scheme for these parameters (no mesh needed: every cell is the
// same box): element frequencies with the stiffest graded E, contact penalty, damping.
double stableTimeStep(const FemParameters& params, const Grading& grading);
// The step a run uses: params.dt if set (refused with the limit in the message if above the
// stable step), else dtSafety * stable step. Throws InputError.
double chooseTimeStep(const FemParameters& params, const Grading& grading);
// Refuses, before any work, a run of more than 1e9 steps (pressure step + sliding at the chosen
// dt), naming the option the user set that made it so (see core/run_limits.hpp).
void requireFemRunLength(const FemParameters& params, const Grading& grading, const RunParameters* record);

struct ContactTotals {
  double fx = 0, fy = 0, fn = 0;  // total contact force on the plate [N]
  double topZ = 0;                // sum over the top nodes of area * u_z [m^3] (pressure work -p dZ)
  double driveX = 0, driveY = 0;  // force of the slider on the top in step 2 [N] (work: F . v dt)
  long long stick = 0, slip = 0, open = 0;
};

class PlateModel {
public:
  PlateModel(MPI_Comm comm, const FemParameters& params, const Grading& grading);
  PlateModel(const PlateModel&) = delete;
  PlateModel& operator=(const PlateModel&) = delete;

  MPI_Comm comm() const { return comm_; }
  DM dm() const { return dm_; }
  const FemParameters& params() const { return params_; }
  const Grading& grading() const { return grading_; }
  PetscInt globalCells() const { return globalCells_; }
  PetscInt localCells() const { return numCells_; }
  PetscInt globalVertices() const { return globalVertices_; }

  // Stable step of the explicit scheme from the element frequencies (mesh, wave speed), the
  // contact penalty and the damping; the model's dt (params.dt or dtSafety * stable).
  double stableTimeStep() const { return stableDt_; }
  double timeStep() const { return dt_; }

  // Displacement-only DM (one field) for the elastic-force comparison; vectors are global.
  DM displacementDM();
  void elasticForceSpecialised(Vec u, Vec f);  // f = -K u (global vectors of displacementDM)
  void elasticForceGeneric(Vec u, Vec f);      // the same through PetscFE (reference)

  // Time integration.
  Vec createState() const;  // zero state (global)
  void rhs(double t, Vec X, Vec F);
  void commitContact();  // accept the contact state of the last rhs evaluation (after a step)
  void setPhase(Phase phase) { phase_ = phase; }
  Phase phase() const { return phase_; }
  void startSliding(Vec X);  // set the top tangential velocity to v (direction theta)
  double pressureAt(double t) const;
  ContactTotals contactTotals() const;  // of the last rhs evaluation, summed over ranks
  double kineticEnergy(Vec X) const;
  double elasticEnergy(Vec X);
  double totalMass() const;
  double topArea() const;  // sum of the top nodal areas (= L^2)
  // Mean penetration and its spread over the owned bottom nodes with contact (for tests).
  void bottomPenetration(Vec X, double* mean, double* minimum, double* maximum) const;

  // Fields for output: per local cell the average stress (Voigt), per owned bottom node.
  struct BottomNode {
    PetscInt block;  // owned block in the global state vector
    double x, y;     // position
    double area;
    double anchorX = 0, anchorY = 0, pendingX = 0, pendingY = 0;
    ContactState state = ContactState::Open, pendingState = ContactState::Open;
    double pressure = 0, tx = 0, ty = 0;  // of the last rhs evaluation
  };
  const std::vector<BottomNode>& bottomNodes() const { return bottom_; }
  void cellStresses(Vec X, std::vector<std::array<double, 6>>* stress);
  PetscLogEvent rhsEvent() const { return evRhs_; }

private:
  void buildMesh();
  void buildCells();
  void buildNodes();
  void computeStableStep();
  void setupGeneric();

  MPI_Comm comm_;
  FemParameters params_;
  Grading grading_;
  OwnedDM dm_, dmU_, dmAux_;
  OwnedVec xLocal_, fLocal_, auxLocal_;
  OwnedVec uGlobal_, fGlobal_, uLocal_, fLocalU_;  // displacement-DM work vectors of rhs()
  BoxElement element_;
  PetscInt numCells_ = 0, globalCells_ = 0, globalVertices_ = 0;
  PetscInt vStart_ = 0, vEnd_ = 0;
  std::vector<PetscInt> cellVertices_;    // 8 local vertex points (minus vStart) per cell
  std::vector<PetscInt> cellStateOff_;    // 8 offsets into the local state vector per cell
  std::vector<PetscInt> cellDispOff_;     // 8 offsets into a local displacement vector per cell
  std::vector<double> cellModulus_;       // E per cell
  std::vector<double> invMass_;           // per owned block
  std::vector<double> mass_;
  std::vector<BottomNode> bottom_;
  // The contact's friction law, one site per bottom node (its band's mu_s, mu_k).
  ExponentialVelocityWeakening contactLaw_;
  struct TopNode {
    PetscInt block;
    double area;
  };
  std::vector<TopNode> top_;
  PetscInt ownedBlocks_ = 0;
  double stableDt_ = 0, dt_ = 0;
  Phase phase_ = Phase::Pressure;
  ContactTotals lastTotals_;
  bool genericReady_ = false;
  PetscLogEvent evRhs_ = 0, evContact_ = 0, evKernel_ = 0, evGeneric_ = 0;
};

}  // namespace gradfric::fem
