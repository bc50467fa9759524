#pragma once
// The plain spring-block kernel (integrator.hpp has the stick/slip rule it shares with
// FastLattice): the tests' reference for every law, those with a per-block state
// (GF_STATE_FRICTION_LAWS, the state law of state_weakening_law.hpp) included.
//
// With a state law, the state theta_i of block i is advanced once per step, at the start of step
// n (time t_n), over the step that just ended: its slip is the block's displacement increment
// |u_i(t_n) - u_i(t_n-1)| (blocks slide on a fixed substrate, so that increment over dt is the
// slip rate; a stuck block has none and heals), then committed. The block's strength at that
// state, S_i = mu_k,i F_n + (mu_s,i - mu_k,i) F_n exp(-theta_i/D_c), replaces mu_s,i F_n in the
// static threshold (a block at rest holds while |F_mot| <= S_i; a block that slid recently is
// weaker, a healed one holds up to mu_s,i F_n) and is the sliding force of the step. This is the
// FEM contact's choice (fem/contact_penalty.hpp: a sticking node is capped by the strength at its
// healed state, not by mu_s). Until the first slip nothing moves and theta stays 0: with
// Motion::skipIdle both kernels jump over that quiet phase, bit for bit the stepped run.
// FastLattice does the same per block, in the same order of operations (src/sbm/block_state.hpp).
#include "gradfric/sbm/integrator.hpp"

#include <cstdint>
#include <vector>

namespace gradfric::sbm {

template <class Law>
class ReferenceLattice {
public:
  ReferenceLattice(const LatticeStiffness& stiffness, Law law, const Motion& motion);
  StepObservation step();
  double time() const { return double(steps_) * motion_.timeStep; }
  std::int64_t steps() const { return steps_; }
  int slippedBlocks() const { return slipped_; }
  void recordFirstSlips(double* times) { firstSlip_ = times; }
  std::vector<double> displacementX() const;
  std::vector<double> displacementY() const;
  std::vector<double> velocityX() const;
  std::vector<double> velocityY() const;  // half-step velocity with Verlet
  // Driving force F_mot (springs + slider) on every block at the current state (for tests).
  void drivingForces(std::vector<double>& fx, std::vector<double>& fy) const;
  Law& law() { return law_; }  // as FastLattice::law()
  // The friction force of the last step on block i [N] (for tests).
  double frictionX(int i) const { return frictionX_[i]; }
  double frictionY(int i) const { return frictionY_[i]; }
  // The first step integrated: 0, or with a state law and Motion::skipIdle the step of the first slip.
  std::int64_t quietSteps() const { return quietUntil_; }

  struct Block {
    double ux, uy, vx, vy;
  };

private:
  void forces(const std::vector<Block>& y, double t, std::vector<double>& fx, std::vector<double>& fy) const;
  void derivative(const std::vector<Block>& y, double t, std::vector<Block>& dy) const;
  void kick(const std::vector<double>& fx, const std::vector<double>& fy);  // Verlet half kick
  void markReversals();
  void rk4(double t);
  void advanceStates();  // state laws: each block's state over the last step, committed
  double staticThreshold(int r, int c, int i) const;
  std::vector<double> frictionX_, frictionY_;  // friction force of the step [N]
  LatticeStiffness stiffness_;
  Law law_;
  Motion motion_;
  int nb_;
  std::int64_t steps_ = 0;
  int slipped_ = 0;
  double* firstSlip_ = nullptr;
  std::vector<Block> blocks_;
  std::vector<std::uint8_t> state_;
  std::vector<std::uint8_t> everSlipped_;
  // State laws only: each block's strength at its committed state [N], and its displacement at the
  // start of the last step (the slip of that step is the increment since).
  std::vector<double> strength_, startX_, startY_;
  std::int64_t quietUntil_ = 0;
};

}  // namespace gradfric::sbm
