#pragma once
// The FEM model of the plate as a composition of its layers (PyLith-like): the mesh
// (plate_mesh), the lumped mass (lumped_mass), the elastic operator (elastic_operator), the bulk
// viscosity (bulk_viscosity, optional), the contact boundary (contact_boundary, penalty or
// kinematic: the kinematic contact comes last, it needs every other force) and the top loading
// (top_loading). rhs() sums their
// contributions into the one right-hand side the TS calls:
//   state per vertex [u_x u_y u_z v_x v_y v_z] (fields "displacement", "velocity");
//   RHS = [v ; M^-1 (f_int + f_pressure + f_contact) - gamma v], the top's tangential
//   acceleration held at zero while it slides.
#include "gradfric/fem/bulk_viscosity.hpp"
#include "gradfric/fem/contact_boundary.hpp"
#include "gradfric/fem/elastic_operator.hpp"
#include "gradfric/fem/lumped_mass.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/fem/plate_mesh.hpp"
#include "gradfric/fem/sliding_damping.hpp"
#include "gradfric/fem/stable_step.hpp"
#include "gradfric/fem/top_loading.hpp"
#include "gradfric/physics/grading.hpp"

#include <petscts.h>

namespace gradfric::fem {

enum class Phase { Pressure, Sliding };

class PlateModel {
public:
  PlateModel(MPI_Comm comm, const FemParameters& params, const Grading& grading);
  PlateModel(const PlateModel&) = delete;
  PlateModel& operator=(const PlateModel&) = delete;

  MPI_Comm comm() const { return mesh_.comm(); }
  DM dm() const { return mesh_.dm(); }
  const FemParameters& params() const { return params_; }  // with the derived defaults
  const Grading& grading() const { return grading_; }
  // Stable step of the explicit scheme, and the step of the run (params.dt or dtSafety * stable).
  double stableTimeStep() const { return stableDt_; }
  double timeStep() const { return dt_; }

  // The layers.
  const PlateMesh& mesh() const { return mesh_; }
  const LumpedMass& mass() const { return mass_; }
  ElasticOperator& elastic() { return elastic_; }
  const ContactBoundary& contact() const { return contact_; }
  const TopLoading& top() const { return top_; }

  // Time integration.
  Vec createState() const;  // zero state (global)
  void rhs(double t, Vec X, Vec F);
  void commitContact();  // the TS post-step, after each accepted step: contact state, damping work
  void recordOnset(double t) { contact_.recordOnset(t); }  // for the interface resolution check (sliding)
  Phase phase() const { return phase_; }
  void setPhase(Phase phase) { phase_ = phase; }
  void startSliding(Vec X);  // phase Sliding; the top's tangential velocity set to the slider's
  // Switches on the damping of the sliding plate (params.peakDamping, peakStiffnessDamping) from the
  // next step on: called once the static peak is confirmed. True if any damping was switched on.
  bool startPeakDamping();
  bool peakDampingOn() const { return peakDampingOn_; }
  SlidingDamping massDamping() const;  // of the current phase
  double pressureAt(double t) const { return top_.pressureAt(t, phase_ == Phase::Sliding); }
  ContactTotals contactTotals() const;  // of the last rhs evaluation, summed over ranks
  double kineticEnergy(Vec X) const { return mass_.kineticEnergy(X); }
  double elasticEnergy(Vec X) { return elastic_.energy(X); }
  // Energy the contact forces and the damping (mass-proportional, bulk viscosity, and the
  // stiffness-proportional term with params.energyAudit) took from the plate since the start of
  // the run, summed over ranks [J]: friction, inelastic impacts, damping, and with penalties the
  // energy the springs hold.
  double dissipatedEnergy() const;

private:
  double stiffnessDampingPower(Vec X);  // over ranks [W]

  FemParameters params_;
  Grading grading_;
  PlateMesh mesh_;
  LumpedMass mass_;
  ElasticOperator elastic_;
  BulkViscosity bulk_;
  ContactBoundary contact_;
  TopLoading top_;
  double stableDt_ = 0, dt_ = 0;
  Phase phase_ = Phase::Pressure;
  ContactSums lastTotals_;  // this rank's
  bool peakDampingOn_ = false;
  // The mass damping's energy per owned block over the step of the last rhs (power x dt), and its
  // running sum per block: each block's sum is the same on any partition, and the total over blocks
  // is exact (dissipatedEnergy), so it has the same bits on any number of ranks. The bulk
  // viscosity's (per cell, rarely on) goes straight into exact sums.
  std::vector<double> dampingStep_, dampingWork_;
  ExactSum bulkStep_, bulkWork_;
  double stiffnessPower_ = 0, stiffnessWork_ = 0;  // over ranks (params.energyAudit only)
  OwnedVec velocityAsDisplacement_;             // for the audit: v in the displacement slots
};

}  // namespace gradfric::fem
