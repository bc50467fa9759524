#pragma once
// The contact boundary of the plate: the bottom nodes against the rigid plane z = 0 with the
// friction law (one law object, a site per node: its local graded coefficients), by penalty
// (pointwise penaltyContact, addForce) or exactly (pointwise kinematicContact, addKinematicForce).
// The contact state (stick/slip, slip anchor) of an RHS evaluation is pending until commit(),
// which the TS post-step calls once per accepted step; commit() also adds the work the contact
// forces did on the plate over the step (trapezoidal in the displacement), for the energy balance.
#include "gradfric/fem/contact_kinematic.hpp"
#include "gradfric/fem/contact_law.hpp"
#include "gradfric/fem/contact_penalty.hpp"
#include "gradfric/fem/sliding_damping.hpp"
#include "gradfric/fem/plate_mesh.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/physics/process_zone.hpp"

#include "gradfric/core/exact_sum.hpp"

#include <utility>
#include <vector>

namespace gradfric::fem {

// Totals of one evaluation summed over ranks (PlateModel::contactTotals).
struct ContactTotals {
  double fx = 0, fy = 0, fn = 0;  // total contact force on the plate [N]
  double topZ = 0;                // sum over the top nodes of area * u_z [m^3] (pressure work -p dZ)
  double driveX = 0, driveY = 0;  // force of the slider on the top in step 2 [N] (work: F . v dt)
  long long stick = 0, slip = 0, open = 0;
  long long everSlipped = 0;      // nodes that slipped or lost contact since resetSlipRecord
  long long nodes = 0;            // bottom nodes
};

// The same totals on this rank, as exact sums (core/exact_sum.hpp), so that their totals over
// ranks have the same bits on any number of ranks.
struct ContactSums {
  ExactSum fx, fy, fn, topZ, driveX, driveY;
  long long stick = 0, slip = 0, open = 0, everSlipped = 0, nodes = 0;
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
    double weakenStart = -1, weakenEnd = -1;  // times its strength fell 10 % and 90 % of the way to mu_k
    double pressure = 0, tx = 0, ty = 0;  // of the last evaluation
    double force[3] = {0, 0, 0}, u[3] = {0, 0, 0};  // committed contact force and displacement
    double work = 0;  // done by the contact force on the node since the start (the same on any partition)
    double pendingForce[3] = {0, 0, 0}, pendingU[3] = {0, 0, 0};
  };

  // muStatic, muKinetic: the plate's mean coefficients, graded by grading's friction factor;
  // law: the friction law of every node (contact_law.hpp); memoryLength: with a stateless law, the
  // slip length of its friction memory [m] (0: the law without state); healingOnly: the memory's
  // weakening at once, only the healing over it (slip_state_law.hpp).
  ContactBoundary(const PlateMesh& mesh, const PenaltyStiffness& stiffness, double muStatic, double muKinetic,
                  const FrictionLawSettings& law, const Grading& grading, double memoryLength = 0.0,
                  bool healingOnly = false);

  // Adds the contact force of the state X (global) to the force slots of F and returns the
  // totals of this rank; the new contact state is pending. dt: the step (the law's state evolves
  // over it).
  ContactSums addForce(Vec X, Vec F, double dt);
  // Kinematic contact (gfverlet): F's force slots hold every other force; the acceleration the
  // RHS will return is F / m plus the mass-proportional damping (mass per block); dt the step.
  ContactSums addKinematicForce(Vec X, Vec F, const std::vector<double>& mass, const SlidingDamping& damping,
                                  double dt);
  void commit();  // accept the pending contact state (after a step)
  void resetSlipRecord();  // from now on, everSlipped counts slips after this point (and the slip per step)
  // After each sliding step at time t, with a law that weakens over a slip (the state law): notes
  // the nodes whose committed strength has fallen 10 % and 90 % of the way from mu_s to mu_k (for
  // processZone()) and the step's largest slip (for largestSlipPerStep()).
  void recordOnset(double t);
  // The process zone measured from those times over the nodes that started weakening by
  // latestStart (physics/process_zone.hpp); collective.
  ProcessZone processZone(double latestStart) const;
  // The largest slip of a node in one step from resetSlipRecord to time `until` (as recordOnset
  // saw it), over ranks [m].
  double largestSlipPerStep(double until) const;
  // Work of the contact forces on the plate over the committed steps, summed over ranks [J]
  // (negative: friction and the inelastic normal impacts dissipate; with penalties it includes
  // the energy the springs store).
  double work() const;

  const std::vector<Node>& nodes() const { return nodes_; }
  const ContactLaw& law() const { return law_; }  // its per-node state
  double committedStrength(int site) const;      // the coefficient of node `site` at its committed state
  double largestStaticCoefficient() const;  // over the nodes and ranks
  // Mean penetration and its spread over the bottom nodes, over ranks (for tests).
  void penetration(Vec X, double* mean, double* minimum, double* maximum) const;

private:
  MPI_Comm comm_;
  PenaltyStiffness stiffness_;
  std::vector<Node> nodes_;
  ContactLaw law_;  // one site per node: its local coefficients (area-weighted over its faces' bands)
  double lastStepSlip_ = 0;  // this rank's largest slip of a node in the last committed step
  std::vector<std::pair<double, double>> slipRecord_;  // (time, running maximum) where it grew
  // Adds the evaluation's force on node n (at displacement xb) to its block's right-hand side fb and
  // to the totals, and keeps it pending until commit.
  void applyNodeForce(Node& n, const PetscScalar* xb, PetscScalar* fb, double fx, double fy, double fz,
                      ContactSums& totals);
  static double tangentialStep(const Node& n, const PetscScalar* xb);
};

}  // namespace gradfric::fem
