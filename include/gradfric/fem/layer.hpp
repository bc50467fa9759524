#pragma once
// The contract of a FEM physics term ("layer", as PyLith's physics objects): the elastic
// operator, the top loading, the bulk viscosity, the weight, the contact (penalty or kinematic),
// the mass damping. PlateModel holds the active ones in a list, in the order their forces are
// added (the sums at a node must keep that order to stay bit for bit), and its right-hand side and
// post-step are loops over it; an effect that is off is not in the list. A new optional term is
// one file, src/fem/terms/<name>.cpp (its Layer subclass, its options, when it is built), plus one
// line in the registry src/fem/terms/terms.def (term_registry.hpp; docs/fem.md, "Adding a FEM
// term", with the weight, src/fem/terms/gravity.cpp, as the worked example).
#include "gradfric/core/exact_sum.hpp"
#include "gradfric/core/state_archive.hpp"
#include "gradfric/fem/sliding_damping.hpp"

#include <petscvec.h>

#include <string>

namespace gradfric::fem {

class LumpedMass;
class PropertySink;

// Totals of one right-hand side summed over ranks (PlateModel::contactTotals).
struct ContactTotals {
  double fx = 0, fy = 0, fn = 0;  // total contact force on the plate [N]
  double topZ = 0;                // sum over the top nodes of area * u_z [m^3] (pressure work -p dZ)
  double driveX = 0, driveY = 0;  // force of the slider on the top in step 2 [N] (work: F . v dt)
  long long stick = 0, slip = 0, open = 0;
  long long everSlipped = 0;      // nodes that slipped or lost contact since resetSlipRecord
  long long nodes = 0;            // bottom nodes
};

// The same totals on this rank, as exact sums (core/exact_sum.hpp), so that their totals over
// ranks have the same bits on any number of ranks. Layers add to them during a right-hand side.
struct ContactSums {
  ExactSum fx, fy, fn, topZ, driveX, driveY;
  long long stick = 0, slip = 0, open = 0, everSlipped = 0, nodes = 0;
};

// What a layer sees of the step being evaluated.
struct LayerContext {
  double t = 0, dt = 0;
  bool sliding = false;        // step 2 of the loading protocol
  double pressure = 0;         // the top pressure at t (loading_protocol.hpp) [Pa]
  SlidingDamping damping;      // the mass damping of this step (it acts on the accelerations)
  const LumpedMass* mass = nullptr;
  // The layer is the first of the list and setsForce(): it sets F's force slots instead of adding
  // to them (so F needs no zeroing pass).
  bool setForce = false;
};

// Energy a layer took from the plate since the start of the run [J]: this rank's share, summed
// exactly over ranks, and/or a value already over ranks (added after, in the list's order: the
// bits of today's balance).
struct LayerWork {
  ExactSum rankShare;
  double overRanks = 0.0;
  bool hasOverRanks = false;
};

class Layer {
public:
  virtual ~Layer() = default;
  virtual const char* name() const = 0;
  // Adds the term's force at the global state X and ctx.t to the force slots of the global
  // right-hand side F (state layout, state_view.hpp) and its share of the step's totals.
  virtual void addForce(const LayerContext& ctx, Vec X, Vec F, ContactSums& sums) = 0;
  // The force of a load that does not depend on the state, at its full value, added to the force
  // slots of F: the load the static pressure step (pressed_equilibrium.hpp) balances.
  virtual void addDeadLoad(Vec /*F*/) const {}
  // Once F holds accelerations (M^-1 f + mass damping): constraints on them (the slider's).
  virtual void constrain(const LayerContext& /*ctx*/, Vec /*X*/, Vec /*F*/, ContactSums& /*sums*/) {}
  // After each accepted step (the TS post-step), before the observers: pending state committed,
  // the step's work accumulated.
  virtual void postStep(double /*dt*/) {}
  virtual LayerWork work() const { return {}; }  // collective
  // Saves or restores what the term carries from step to step on this rank (a checkpoint): its
  // committed state and the work done since the start. A term without such state has nothing.
  virtual void archive(StateArchive& /*a*/) {}
  // One line for the run's printout of the effects used.
  virtual std::string describe() const = 0;
  // Per-cell and per-node fields the term reads (plate_properties.hpp), for the output.
  virtual void writeProperties(PropertySink& /*sink*/) const {}
  // Whether addForce can set every force slot (honoured when ctx.setForce).
  virtual bool setsForce() const { return false; }
};

}  // namespace gradfric::fem
