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
#include "gradfric/fem/edge_grading.hpp"
#include "gradfric/fem/layer.hpp"
#include "gradfric/fem/plate_properties.hpp"
#include "gradfric/fem/sliding_damping.hpp"
#include "gradfric/physics/process_zone.hpp"

#include "gradfric/core/exact_sum.hpp"

#include <limits>
#include <utility>
#include <vector>

namespace gradfric::fem {

// The nodes that slid while their strength mu(theta) was above 1 (docs/flutter.md: sliding on the
// rigid plane is then ill-posed), up to a time: their number and their share of the contact area.
struct SlidingAboveOne {
  long nodes = 0;
  double areaFraction = 0;
  double fastestRate = 0;     // the largest slip rate of a node sliding at mu > 1 [m/s]
  double largestElement = 0;  // the largest in-plane element side next to those nodes [m]
};

struct ContactSettings {
  bool kinematic = false;      // -fem_contact kinematic: exact contact (gfverlet), else penalty springs
  PenaltyStiffness stiffness;  // the penalty springs
  FrictionLawSettings law;     // the friction law of every node (contact_law.hpp)
  double memoryLength = 0.0;   // with a stateless law, its friction memory's slip length [m] (0: none)
  bool healingOnly = false;    // the memory's weakening at once, only the healing over it
};

// The contact layer: the last force of the list (the kinematic contact needs every other force).
class ContactBoundary : public Layer {
public:
  struct Node {
    PetscInt block;  // owned block in the global state vector
    double x, y;     // position
    double area;
    double anchorX = 0, anchorY = 0, pendingX = 0, pendingY = 0;
    ContactState state = ContactState::Open, pendingState = ContactState::Open;
    bool everSlipped = false;
    double firstSlip = std::numeric_limits<double>::quiet_NaN();  // time its committed state first was Slip [s]
    double weakenStart = -1, weakenEnd = -1;  // times its strength fell 10 % and 90 % of the way to mu_k
    double slidAboveOne = -1;  // time it first slid with its strength mu(theta) above 1 (-1: never)
    double stepSlip = 0;       // its tangential slip over the last committed step [m] (0: not sliding)
    double pressure = 0, tx = 0, ty = 0;  // of the last evaluation
    double force[3] = {0, 0, 0}, u[3] = {0, 0, 0};  // committed contact force and displacement
    double work = 0;  // done by the contact force on the node since the start (the same on any partition)
    double pendingForce[3] = {0, 0, 0}, pendingU[3] = {0, 0, 0};
  };

  // The nodes and their coefficients mu_s, mu_k: properties.bottomNodes().
  ContactBoundary(const PlateProperties& properties, MPI_Comm comm, const ContactSettings& settings);

  // The layer: the contact force of the state X (penalty, or kinematic from F's other forces, the
  // mass and the mass damping of ctx) into the force slots of F and the step's totals; the new
  // contact state is pending until the post-step commits it.
  const char* name() const override { return "contact"; }
  void addForce(const LayerContext& ctx, Vec X, Vec F, ContactSums& sums) override;
  void postStep(double) override { commit(); }
  LayerWork work() const override;  // minus the work of the contact forces on the plate
  void archive(StateArchive& a) override;  // the nodes' contact state, the law's per-node state
  std::string describe() const override;
  void writeProperties(PropertySink& sink) const override;

  // The penalty contact's force; dt: the step (the law's state evolves over it).
  void addPenaltyForce(Vec X, Vec F, double dt, ContactSums& totals);
  // Kinematic contact (gfverlet): F's force slots hold every other force; the acceleration the
  // RHS will return is F / m plus the mass-proportional damping (mass per block); dt the step.
  void addKinematicForce(Vec X, Vec F, const std::vector<double>& mass, const SlidingDamping& damping, double dt,
                         ContactSums& totals);
  void commit();  // accept the pending contact state (after a step)
  // From now on, everSlipped and firstSlip count slips after this point (and the slip per step).
  void resetSlipRecord();
  // After each sliding step at time t, with first_slip asked for: the nodes that slide now and never
  // did before get firstSlip = t (the first-slip map, first_slip_map.hpp).
  void recordFirstSlips(double t);
  // At the start of sliding: every node's remembered pressure p* is its pressure (the plate has
  // been pressed at rest, where p* would follow p over L_sigma / V*).
  void settleRememberedPressure();
  // After each sliding step at time t, with a law that weakens over a slip (the state law): notes
  // the nodes whose committed strength has fallen 10 % and 90 % of the way from mu_s to mu_k (for
  // processZone()), the step's largest slip (for largestSlipPerStep()) and the nodes that slide with
  // a strength above 1 and the fastest of them (for slidAboveOne()); dt: the step.
  void recordOnset(double t, double dt);
  // The process zone measured from those times over the nodes that started weakening by
  // latestStart (physics/process_zone.hpp); collective.
  ProcessZone processZone(double latestStart) const;
  // The largest slip of a node in one step from resetSlipRecord to time `until` (as recordOnset
  // saw it), over ranks [m].
  double largestSlipPerStep(double until) const;
  // The nodes that slid with mu(theta) > 1 from the start of sliding to `until`, the fastest of
  // their slip rates and the largest element side next to them (the mesh's axes x, y); collective.
  SlidingAboveOne slidAboveOne(double until, const MeshAxis& x, const MeshAxis& y) const;
  // Work of the contact forces on the plate over the committed steps, summed over ranks [J]
  // (negative: friction and the inelastic normal impacts dissipate; with penalties it includes
  // the energy the springs store).
  double contactWork() const;

  const std::vector<Node>& nodes() const { return nodes_; }
  const ContactLaw& law() const { return law_; }  // its per-node state, the normal-stress memory's too
  double committedStrength(int site) const;      // the coefficient of node `site` at its committed state
  double largestStaticCoefficient() const;  // over the nodes and ranks
  // Mean penetration and its spread over the bottom nodes, over ranks (for tests).
  void penetration(Vec X, double* mean, double* minimum, double* maximum) const;

private:
  MPI_Comm comm_;
  ContactSettings settings_;
  PenaltyStiffness stiffness_;
  std::vector<Node> nodes_;
  ContactLaw law_;  // one site per node: its local coefficients (area-weighted over its faces' bands)
  bool randomSurface_ = false;  // the coefficients carry the random surface (for the stored fields' description)
  double lastStepSlip_ = 0;  // this rank's largest slip of a node in the last committed step
  std::vector<std::pair<double, double>> slipRecord_;  // (time, running maximum) where it grew
  std::vector<std::pair<double, double>> aboveOneRates_;  // (time, running maximum slip rate at mu > 1)
  // Adds the evaluation's force on node n (at displacement xb) to its block's right-hand side fb and
  // to the totals, and keeps it pending until commit.
  void applyNodeForce(Node& n, const PetscScalar* xb, PetscScalar* fb, double fx, double fy, double fz,
                      ContactSums& totals);
  static double tangentialStep(const Node& n, const PetscScalar* u);
};

}  // namespace gradfric::fem
