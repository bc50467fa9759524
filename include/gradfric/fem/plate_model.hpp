#pragma once
// The FEM model of the plate (PyLith-like): the mesh (plate_mesh), the lumped mass (lumped_mass),
// the local properties built once (plate_properties), the loading protocol (loading_protocol) and
// a list of physics layers (layer.hpp), each adding its force to the one right-hand side the TS
// calls:
//   state per vertex [u_x u_y u_z v_x v_y v_z] (fields "displacement", "velocity"; state_view.hpp);
//   RHS = [v ; M^-1 (sum of the layers' forces) - gamma v], then the layers' constraints (the top's
//   tangential acceleration held at zero while it slides).
// The layers, in the order their forces are added: the elastic operator (always; it sets the
// force slots), the top loading (always), the bulk viscosity (optional), the registry's optional
// terms (term_registry.hpp: the weight, ...), the contact boundary (penalty or kinematic: the
// kinematic contact comes last, it needs every other force), the mass damping (it acts on the
// accelerations, in the M^-1 pass).
#include "gradfric/fem/bulk_viscosity.hpp"
#include "gradfric/fem/contact_boundary.hpp"
#include "gradfric/fem/elastic_operator.hpp"
#include "gradfric/fem/layer.hpp"
#include "gradfric/fem/loading_protocol.hpp"
#include "gradfric/fem/lumped_mass.hpp"
#include "gradfric/fem/mass_damping.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/fem/plate_mesh.hpp"
#include "gradfric/fem/plate_properties.hpp"
#include "gradfric/fem/stable_step.hpp"
#include "gradfric/fem/top_loading.hpp"
#include "gradfric/physics/grading.hpp"

#include <petscts.h>

#include <memory>
#include <utility>
#include <vector>

namespace gradfric::fem {

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

  const PlateMesh& mesh() const { return mesh_; }
  const LumpedMass& mass() const { return mass_; }
  const PlateProperties& properties() const { return properties_; }
  // The active layers, in the order of their forces; and the ones other code needs by name (the
  // contact boundary is built also when -fem_contact none leaves it out of the list).
  const std::vector<Layer*>& layers() const { return layers_; }
  ElasticOperator& elastic() { return *elastic_; }
  const ContactBoundary& contact() const { return *contact_; }
  const TopLoading& top() const { return *top_; }

  // Time integration.
  Vec createState() const;  // zero state (global)
  void rhs(double t, Vec X, Vec F);
  void postStep();  // the TS post-step, after each accepted step: every layer's, in the list's order
  void recordOnset(double t, double dt) { contact_->recordOnset(t, dt); }  // for the interface resolution check (sliding)
  void recordFirstSlips(double t) { contact_->recordFirstSlips(t); }  // for the first-slip map (sliding)

  // The loading protocol (loading_protocol.hpp).
  const LoadingProtocol& protocol() const { return protocol_; }
  Phase phase() const { return protocol_.phase(); }
  void setPhase(Phase phase) { protocol_.setPhase(phase); }
  void startSliding(Vec X);  // phase Sliding; the top's tangential velocity set to the slider's
  // Switches on the damping of the sliding plate (params.peakDamping, peakStiffnessDamping) from the
  // next step on: called once the static peak is confirmed. True if any damping was switched on.
  bool startPeakDamping();
  bool peakDampingOn() const { return protocol_.peakDampingOn(); }
  double pressureAt(double t) const { return protocol_.pressureAt(t); }

  ContactTotals contactTotals() const;  // of the last rhs evaluation, summed over ranks
  double kineticEnergy(Vec X) const { return mass_.kineticEnergy(X); }
  double elasticEnergy(Vec X) { return elastic_->energy(X); }
  // Energy the layers took from the plate since the start of the run, summed over ranks [J]:
  // friction, inelastic impacts, damping (mass-proportional, bulk viscosity, and the
  // stiffness-proportional term with params.energyAudit), and with penalties the springs' energy.
  double dissipatedEnergy() const;
  // Saves or restores this rank's state between steps: the protocol's phase, every built term's
  // state (active or not: a term switched on later has its own) and the totals of the last
  // right-hand side (the start of sliding reads them before the next one).
  void archive(StateArchive& a);

private:
  // Builds a layer; it joins the list when active.
  template <class L, class... Args>
  L* add(bool active, Args&&... args) {
    return static_cast<L*>(adopt(std::make_unique<L>(std::forward<Args>(args)...), active));
  }
  // Owns a built layer (an optional term's, from its registry entry, or add's); in the list if active.
  Layer* adopt(std::unique_ptr<Layer> layer, bool active) {
    owned_.push_back(std::move(layer));
    if (active) layers_.push_back(owned_.back().get());
    return owned_.back().get();
  }
  // F = [v ; M^-1 f + the mass damping's acceleration]; the damping's energy per block to its layer.
  void accelerate(const LayerContext& ctx, Vec X, Vec F);

  FemParameters params_;
  Grading grading_;
  PlateMesh mesh_;
  LumpedMass mass_;
  PlateProperties properties_;
  LoadingProtocol protocol_;
  std::vector<std::unique_ptr<Layer>> owned_;
  std::vector<Layer*> layers_;
  ElasticOperator* elastic_ = nullptr;
  TopLoading* top_ = nullptr;
  ContactBoundary* contact_ = nullptr;
  MassDamping* damping_ = nullptr;  // null when no mass damping is on
  double stableDt_ = 0, dt_ = 0;
  ContactSums lastTotals_;  // this rank's
};

}  // namespace gradfric::fem
