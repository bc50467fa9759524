#pragma once
// Pointwise contact physics of the FEM, pure arithmetic, no PETSc: a node of the bottom face
// against the rigid plane z = 0. Normal penalty; tangential penalty (elastic slip) capped by the
// friction law (the paper's Eq. 1 by default) times the contact pressure (return map onto the
// friction cone). The law is the one the spring-block kernels use (physics/friction_laws.hpp),
// its sites the bottom nodes, its strengths the nodes' coefficients mu_s,i, mu_k,i.
#include "gradfric/physics/normal_stress_memory.hpp"
#include "gradfric/physics/friction_laws.hpp"
#include "gradfric/physics/slip_state_law.hpp"
#include "gradfric/physics/state_weakening_law.hpp"

#include <cmath>

namespace gradfric::fem {

enum class ContactState : int { Open = 0, Stick = 1, Slip = 2 };

struct PenaltyStiffness {
  double normal;      // k_n [Pa/m]: contact pressure per unit penetration
  double tangential;  // k_t [Pa/m]: shear traction per unit elastic slip
};

// Tractions (per unit area) on the plate from the plane, and the updated slip anchor.
struct ContactTraction {
  double pressure = 0;            // p_c >= 0
  double tx = 0, ty = 0;          // tangential traction on the plate
  double anchorX = 0, anchorY = 0;  // tangential position where the elastic slip is zero
  ContactState state = ContactState::Open;
  double strength = 0;            // the friction coefficient that capped the traction (in contact)
  double frictionPressure = 0;    // the pressure the strength multiplies: p_c, or the memory's p*
};

// The friction coefficient of a contact node: a law with a per-site state answers itself, at the
// node's state after slipping `slip` [m] over the step dt (sliding) or sticking, kept pending
// (friction_law.hpp, "Laws with a per-site state"); with a plain law a sticking node holds up to
// its static strength and a sliding one feels the law's sliding strength at its speed.
template <class Law>
inline double contactStrength(Law& law, int site, double speed, double slip, double dt, bool sliding) {
  if constexpr (hasSiteState<Law>::value) {
    return law.contactStrength(site, speed, slip, dt, sliding);
  } else {
    const int slot = law.sites.slotOfSite(site);
    const double staticStrength = law.sites.staticAt(slot);
    return sliding ? law.slidingStrength(staticStrength, law.sites.kineticAt(slot), speed) : staticStrength;
  }
}

// site: the node's index among the law's sites; gap: z of the node (negative = penetration);
// ux, uy: tangential displacement; anchor: the committed anchor; vx, vy: tangential velocity of
// the node (the plane is at rest). A node that was sticking holds up to the law's static
// threshold mu_s p (its velocity is only elastic motion of the penalty spring); a node that was
// slipping feels the law's sliding strength at its tangential speed, the slip rate. slip: the
// node's tangential displacement since the last commit when it was slipping (a slip-length law's
// state evolves over it; plain laws ignore it); dt: the step (a state law's evolution).
// memory, remembered: the law's normal-stress memory and the node's committed p*
// (physics/normal_stress_memory.hpp; none by default: the strength multiplies p_c itself).
template <class Law>
inline ContactTraction penaltyContact(const PenaltyStiffness& k, Law& law, int site, double gap, double ux,
                                      double uy, double anchorX, double anchorY, double vx, double vy,
                                      bool wasSlipping, double slip = 0.0, double dt = 0.0,
                                      const NormalStressMemory& memory = {}, double remembered = 0.0) {
  ContactTraction r;
  const double slipRate = wasSlipping && dt > 0.0 ? slip / dt : 0.0;
  if (gap >= 0.0) {  // open: no traction, the elastic slip is released, p* relaxes towards 0
    r.anchorX = ux;
    r.anchorY = uy;
    r.frictionPressure = memory.relax(remembered, 0.0, slipRate, dt);
    return r;
  }
  r.pressure = -k.normal * gap;
  r.frictionPressure = memory.relax(remembered, r.pressure, slipRate, dt);
  const double trialX = -k.tangential * (ux - anchorX);
  const double trialY = -k.tangential * (uy - anchorY);
  const double trial = std::sqrt(trialX * trialX + trialY * trialY);
  const double strength = contactStrength(law, site, std::sqrt(vx * vx + vy * vy), slip, dt, wasSlipping);
  r.strength = strength;
  const double cap = strength * r.frictionPressure;
  if (trial <= cap) {
    r.tx = trialX;
    r.ty = trialY;
    r.anchorX = anchorX;
    r.anchorY = anchorY;
    r.state = ContactState::Stick;
    return r;
  }
  const double scale = cap / trial;  // return onto the cone, along the trial direction
  r.tx = trialX * scale;
  r.ty = trialY * scale;
  r.anchorX = ux + r.tx / k.tangential;
  r.anchorY = uy + r.ty / k.tangential;
  r.state = ContactState::Slip;
  return r;
}

}  // namespace gradfric::fem
