#pragma once
// Eq. 1 with a weakening length: a state-variable friction law whose steady state is the paper's
// Eq. 1 exactly and whose onset weakens over a slip distance D_c (docs/accuracy_fem.md, "The
// friction law"). Per site a state theta [m] (theta = 0: a site that never slid):
//   mu(theta)    = mu_k + (mu_s - mu_k) exp(-theta / D_c)
//   dtheta / dt  = |V| - (v_c / D_c) theta
// - steady sliding at V: theta = |V| D_c / v_c, so mu = Eq. 1 at V (the kinetic results stay the
//   paper's);
// - fast slip (|V| >> v_c): theta grows as the slip, so mu falls from mu_s to mu_k over D_c of slip
//   (exponential slip weakening, fracture energy (mu_s - mu_k) p D_c): the length a mesh can resolve,
//   which Eq. 1 alone lacks (Rice, Lapusta & Ranjith 2001; Day et al. 2005);
// - at rest theta decays over D_c / v_c: the site heals back towards mu_s (ageing).
// This is the "fast" state evolution of Ampuero & Ben-Zion (2008, SEM2DPACK) with an exponential
// strength. It was chosen over Ruina's slip law (the friction memory of slip_state_law.hpp) because
// it also heals at rest, and over the ageing law because its steady state is Eq. 1 itself.
//
// A site's state is pending until commit() (a model may evaluate more than once per step). The
// update over a step dt at the step's mean slip rate V is exact for constant V:
//   theta' = theta e^(-v_c dt / D_c) + V (D_c / v_c) (1 - e^(-v_c dt / D_c)).
// Pure arithmetic, no PETSc.
#include "gradfric/core/state_archive.hpp"
#include "gradfric/physics/friction_law.hpp"
#include "gradfric/physics/friction_laws_settings.hpp"

#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace gradfric {

struct StateWeakening {
  static constexpr const char* name = "state";

  FrictionSites sites;
  double criticalVelocity = 0;  // v_c [m/s] (-friction_v_c)
  double slipLength = 0;        // D_c [m] (-friction_d_c)
  std::vector<double> state;    // per site: committed theta [m]
  std::vector<double> pending;  // per site: theta after the last evaluation [m]

  // The per-site state saved or restored (checkpoints).
  void archive(StateArchive& a) {
    a.fixedField("law.state", state);
    a.fixedField("law.pending", pending);
  }

  static StateWeakening make(FrictionSites sites, const FrictionLawSettings& settings, std::size_t siteCount) {
    StateWeakening law{std::move(sites), settings.criticalVelocity, settings.slipLength, {}, {}};
    law.state.assign(siteCount, 0.0);
    law.pending = law.state;
    return law;
  }
  static std::string describe(const FrictionLawSettings& settings) {
    std::ostringstream text;
    text << "Eq. 1 with a weakening length: mu_k + (mu_s - mu_k) exp(-theta/D_c), dtheta/dt = |V| - (v_c/D_c) theta; "
            "steady state Eq. 1, slip weakening over D_c; v_c = "
         << settings.criticalVelocity << " m/s, D_c = " << settings.slipLength << " m";
    return text.str();
  }

  // The healing factor of a step dt [s] at rest, e^(-v_c dt / D_c) (a kernel computes it once).
  double decayOver(double dt) const { return std::exp(-criticalVelocity * dt / slipLength); }
  // The state after a step whose healing factor is decay, at mean slip rate speed [m/s], from theta.
  double evolveWith(double theta, double speed, double decay) const {
    return theta * decay + speed * (slipLength / criticalVelocity) * (1.0 - decay);
  }
  // The state after a step dt [s] at mean slip rate speed [m/s] from theta (exact for constant speed).
  double evolve(double theta, double speed, double dt) const { return evolveWith(theta, speed, decayOver(dt)); }
  // The state after a step dt [s] (healing factor decay) over which the site slid `slip` [m].
  double evolveBySlip(double theta, double slip, double dt, double decay) const {
    const double speed = dt > 0 ? slip / dt : 0.0;
    return evolveWith(theta, speed, decay);
  }
  // The strength at state theta of a site with static and kinetic strengths s and k.
  double strengthBetween(double s, double k, double theta) const { return k + (s - k) * std::exp(-theta / slipLength); }
  // The coefficient (or force, in the sites' units) of site at state theta.
  double strengthAt(int site, double theta) const {
    const int slot = sites.slotOfSite(site);
    return strengthBetween(sites.staticAt(slot), sites.kineticAt(slot), theta);
  }
  // Eq. 1: the steady strength at slip rate v (what a site sliding steadily at v feels).
  double steadyStrength(int site, double speed) const {
    return strengthAt(site, speed * slipLength / criticalVelocity);
  }
  // One evaluation of site: it slid `slip` [m] over dt [s] since the last commit (0 if it stuck);
  // its new state is pending, its strength at that state returned.
  double advance(int site, double slip, double dt) {
    pending[site] = evolveBySlip(state[site], slip, dt, decayOver(dt));
    return strengthAt(site, pending[site]);
  }
  void commit() { state = pending; }

  // What a contact asks of every law with a per-site state (friction_law.hpp).
  bool hasState() const { return true; }
  double committedStrength(int site) const { return strengthAt(site, state[site]); }
  // A site in contact: sliding, it slid `slip` over dt; sticking, it heals over dt.
  double contactStrength(int site, double /*speed*/, double slip, double dt, bool sliding) {
    return advance(site, sliding ? slip : 0.0, dt);
  }
  void keepOpen(int) {}  // a site out of contact keeps its state
};

}  // namespace gradfric
