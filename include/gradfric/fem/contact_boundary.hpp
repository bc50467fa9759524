#pragma once
// The contact boundary of the plate: the bottom nodes against the rigid plane z = 0 with the
// friction law (one law object, a site per node: its local graded coefficients), by penalty
// (pointwise penaltyContact, addForce) or exactly (pointwise kinematicContact, addKinematicForce).
// The contact state (stick/slip, slip anchor) of an RHS evaluation is pending until commit(),
// which the TS post-step calls once per accepted step; commit() also adds the work the contact
// forces did on the plate over the step (trapezoidal in the displacement), for the energy balance.
#include "gradfric/fem/contact_kinematic.hpp"
#include "gradfric/fem/contact_penalty.hpp"
#include "gradfric/fem/sliding_damping.hpp"
#include "gradfric/fem/plate_mesh.hpp"
#include "gradfric/physics/exponential_law.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/physics/slip_state_law.hpp"

#include <vector>

namespace gradfric::fem {

// The friction law of the contact boundary: paper Eq. 1, with the per-node slip state of
// -fem_slip_length (slip_state_law.hpp; D_c = 0: Eq. 1 itself).
using ContactLaw = WithSlipLength<ExponentialVelocityWeakening>;

// Totals of one evaluation on this rank (ContactBoundary) or summed over ranks (PlateModel).
struct ContactTotals {
  double fx = 0, fy = 0, fn = 0;  // total contact force on the plate [N]
  double topZ = 0;                // sum over the top nodes of area * u_z [m^3] (pressure work -p dZ)
  double driveX = 0, driveY = 0;  // force of the slider on the top in step 2 [N] (work: F . v dt)
  long long stick = 0, slip = 0, open = 0;
  long long everSlipped = 0;      // nodes that slipped or lost contact since resetSlipRecord
  long long nodes = 0;            // bottom nodes
};

class ContactBoundary {
public:
  struct Node {
    PetscInt block;  // owned block in the global state vector
    double x, y;     // position
    double area;
    double anchorX = 0, anchorY = 0, pendingX = 0, pendingY = 0;
    ContactState state = ContactState::Open, pendingState = ContactState::Open;
    bool everSlipped = false;
    double pressure = 0, tx = 0, ty = 0;  // of the last evaluation
    double force[3] = {0, 0, 0}, u[3] = {0, 0, 0};  // committed contact force and displacement
    double pendingForce[3] = {0, 0, 0}, pendingU[3] = {0, 0, 0};
  };

  // muStatic, muKinetic: the plate's mean coefficients, graded by grading's friction factor;
  // slipLength: D_c of the nodes' slip state [m] (0: Eq. 1 without state); healingOnly: Eq. 1's
  // weakening at once, only the healing over D_c (slip_state_law.hpp).
  ContactBoundary(const PlateMesh& mesh, const PenaltyStiffness& stiffness, double muStatic, double muKinetic,
                  double criticalVelocity, const Grading& grading, double slipLength = 0.0,
                  bool healingOnly = false);

  // Adds the contact force of the state X (global) to the force slots of F and returns the
  // totals of this rank; the new contact state is pending.
  ContactTotals addForce(Vec X, Vec F);
  // Kinematic contact (gfverlet): F's force slots hold every other force; the acceleration the
  // RHS will return is F / m plus the mass-proportional damping (mass per block); dt the step.
  ContactTotals addKinematicForce(Vec X, Vec F, const std::vector<double>& mass, const SlidingDamping& damping,
                                  double dt);
  void commit();  // accept the pending contact state (after a step)
  void resetSlipRecord();  // from now on, everSlipped counts slips after this point
  // Work of the contact forces on the plate over the committed steps, summed over ranks [J]
  // (negative: friction and the inelastic normal impacts dissipate; with penalties it includes
  // the energy the springs store).
  double work() const;

  const std::vector<Node>& nodes() const { return nodes_; }
  const ContactLaw& law() const { return law_; }  // its per-node slip state (with -fem_slip_length)
  double largestStaticCoefficient() const;  // over the nodes and ranks
  // Mean penetration and its spread over the bottom nodes, over ranks (for tests).
  void penetration(Vec X, double* mean, double* minimum, double* maximum) const;

private:
  MPI_Comm comm_;
  PenaltyStiffness stiffness_;
  std::vector<Node> nodes_;
  ContactLaw law_;  // one site per node: its local coefficients (area-weighted over its faces' bands)
  double work_ = 0;  // this rank's share of work()
  // Adds the evaluation's force on node n (at displacement xb) to its block's right-hand side fb and
  // to the totals, and keeps it pending until commit.
  void applyNodeForce(Node& n, const PetscScalar* xb, PetscScalar* fb, double fx, double fy, double fz,
                      ContactTotals& totals);
  static double tangentialStep(const Node& n, const PetscScalar* xb);
  void keepSlipState(int site, ContactState state, double strength);
};

}  // namespace gradfric::fem
