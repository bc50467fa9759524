#pragma once
// Pointwise exact (kinematic, predictor-corrector) contact of a bottom node against the rigid
// plane z = 0 for the explicit central-difference step, pure arithmetic, no PETSc: the reference
// the penalty contact (contact_penalty.hpp) is measured against.
//
// In gfverlet the right-hand side at t_{n+1} sees the half-step velocity v_{n+1/2}, and the
// acceleration a it returns moves the node to z_{n+2} = z_{n+1} + dt (v_{n+1/2} + dt a). With the
// acceleration of every other force a_free, the node's predicted position is
// z* = z + dt (v + dt a_free). If z* < 0 the node would penetrate: the normal force
// f_n = -m z* / dt^2 puts it exactly on the plane. In contact, the tangential force that stops
// the node (tangential velocity zero after the step) is f_stick = -m (v_t + dt a_free,t) / dt; the
// node sticks while the law's threshold holds (|f_stick| <= mu(|v_t|) f_n: mu_s f_n for a node at
// rest, the sliding friction for a moving node, which stops only if that friction can stop it),
// else it slides with mu(|v_t|) f_n of the same law against its trial motion. No spring: no penetration, no
// elastic slip, no penalty frequency in the stable step.
#include "gradfric/fem/contact_penalty.hpp"

#include <cmath>

namespace gradfric::fem {

struct KinematicContactForce {
  double fn = 0, fx = 0, fy = 0;  // force of the plane on the node [N]
  ContactState state = ContactState::Open;
  double strength = 0;            // the friction coefficient available (in contact)
  double frictionForce = 0;       // the normal force the strength multiplies: f_n, or the memory's f*
};

// site: the node's index among the law's sites; mass [kg]; dt [s]; gap: z of the node;
// v: its velocity (half step); aFree: its acceleration from every other force; slip: its
// tangential displacement since the last commit (a slip-length law's state evolves over it);
// memory, remembered: the law's normal-stress memory and the node's committed f*
// (physics/normal_stress_memory.hpp, applied to the node's normal force: the pressure times its area).
template <class Law>
inline KinematicContactForce kinematicContact(Law& law, int site, double mass, double dt, double gap,
                                              const double v[3], const double aFree[3], double slip = 0.0,
                                              const NormalStressMemory& memory = {}, double remembered = 0.0) {
  KinematicContactForce r;
  const double slipRate = dt > 0.0 ? slip / dt : 0.0;
  const double predicted = gap + dt * (v[2] + dt * aFree[2]);
  if (predicted >= 0.0) {  // open: the node stays on or above the plane by itself
    r.frictionForce = memory.relax(remembered, 0.0, slipRate, dt);
    return r;
  }
  r.fn = -mass * predicted / (dt * dt);
  r.frictionForce = memory.relax(remembered, r.fn, slipRate, dt);
  const double stickX = -mass * (v[0] + dt * aFree[0]) / dt;
  const double stickY = -mass * (v[1] + dt * aFree[1]) / dt;
  const double stickSquared = stickX * stickX + stickY * stickY;
  // The friction available: mu(|v_t|) f_n, mu_s f_n at rest (Eq. 1 at v = 0). A node at rest
  // sticks while the static threshold holds; a sliding node stops (sticks) only if the friction it
  // feels can stop it within the step, else it slides on.
  const double slipSpeed = std::sqrt(v[0] * v[0] + v[1] * v[1]);
  r.strength = contactStrength(law, site, slipSpeed, slip, dt, true);
  const double strength = r.strength * r.frictionForce;
  if (StaticThreshold::holds(stickSquared, strength)) {
    r.fx = stickX;
    r.fy = stickY;
    r.state = ContactState::Stick;
    return r;
  }
  const double scale = strength / std::sqrt(stickSquared);
  r.fx = stickX * scale;
  r.fy = stickY * scale;
  r.state = ContactState::Slip;
  return r;
}

}  // namespace gradfric::fem
