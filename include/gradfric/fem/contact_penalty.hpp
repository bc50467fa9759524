#pragma once
// Pointwise contact physics of the FEM, pure arithmetic, no PETSc: a node of the bottom face
// against the rigid plane z = 0. Normal penalty; tangential penalty (elastic slip) capped by the
// paper's Eq. 1, mu(v) times the contact pressure (return map onto the friction cone).
#include "gradfric/physics/friction_law.hpp"

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
};

// gap: z of the node (negative = penetration); ux, uy: tangential displacement; anchor: the
// committed anchor; vx, vy: tangential velocity of the node (the plane is at rest).
// The sliding velocity of Eq. 1 is the slip rate: zero for a node that was sticking (its velocity
// is only elastic motion of the penalty spring, so the threshold to start slipping is mu_s p
// exactly, Eq. 1 at v = 0), the node's tangential speed for a node that was slipping.
inline ContactTraction penaltyContact(const PenaltyStiffness& k, const ExponentialVelocityWeakening& law, double gap,
                                      double ux, double uy, double anchorX, double anchorY, double vx, double vy,
                                      bool wasSlipping) {
  ContactTraction r;
  if (gap >= 0.0) {  // open: no traction, the elastic slip is released
    r.anchorX = ux;
    r.anchorY = uy;
    return r;
  }
  r.pressure = -k.normal * gap;
  const double trialX = -k.tangential * (ux - anchorX);
  const double trialY = -k.tangential * (uy - anchorY);
  const double trial = std::sqrt(trialX * trialX + trialY * trialY);
  const double slipRate = wasSlipping ? std::sqrt(vx * vx + vy * vy) : 0.0;
  const double cap = law.coefficient(slipRate) * r.pressure;
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
