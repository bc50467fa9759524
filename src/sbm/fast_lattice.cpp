// The production spring-block kernel, FastLattice (integrator.hpp): its state, the quiet phase
// before the first slip (quiet_phase.hpp), the choice between the full sweep and the active set,
// and the bookkeeping of stick states. The sweeps are in full_sweep.hpp, active_set.hpp and
// rk4_sweep.hpp, entered through kernel_dispatch.cpp (kernel_entries.hpp).
#include "gradfric/sbm/integrator.hpp"
#include "gradfric/sbm/quiet_phase.hpp"
#include "row_springs.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace gradfric::sbm {


namespace {

// cos and sin of an angle in degrees, exact at multiples of 90 degrees.
void directionOf(double degrees, double& cx, double& cy) {
  const double turns = degrees / 90.0;
  if (turns == std::floor(turns)) {
    static const double c[4] = {1, 0, -1, 0}, s[4] = {0, 1, 0, -1};
    const int q = ((static_cast<long long>(turns) % 4) + 4) % 4;
    cx = c[q];
    cy = s[q];
    return;
  }
  cx = std::cos(degrees * M_PI / 180.0);
  cy = std::sin(degrees * M_PI / 180.0);
}

}  // namespace

Motion motionOf(const Parameters& p, double timeStep, double damping) {
  double cx, cy;
  directionOf(p.plate.slidingAngle, cx, cy);
  return {timeStep, damping, p.blockMass(), p.plate.velocity * cx, p.plate.velocity * cy, p.integrator, p.skipIdle};
}

template <class Law>
FastLattice<Law>::FastLattice(const LatticeStiffness& stiffness, Law law, const Motion& motion)
    : stiffness_(stiffness), law_(std::move(law)), motion_(motion), nb_(stiffness.blocksPerSide) {
  const std::size_t n = std::size_t(nb_) * nb_;
  for (auto* v : {&ux_, &uy_, &vx_, &vy_, &sx_, &sy_, &svx_, &svy_, &accUx_, &accUy_, &accVx_, &accVy_, &mobile_,
                 &frictionX_, &frictionY_})
    v->assign(n, 0.0);
  state_.assign(n, Stuck);
  everSlipped_.assign(n, 0);
  for (auto* v : {&fx_, &fy_, &carryX_, &carryY_, &nextX_, &nextY_, &springX_, &springY_, &sliderRowX_, &sliderRowY_})
    v->assign(nb_, 0.0);
  if (motion_.integrator == Integrator::VelocityVerlet) {
    rowPieces_.assign(8 * std::size_t(nb_ + 1), 0.0);
    padRowPieces(rowPieces(), nb_);
  }
  constexpr std::int64_t kNever = std::int64_t(1) << 52;
  if constexpr (hasBlockState<Law>) {  // every block at rest at theta = 0 (block_state.hpp)
    startX_.assign(n, 0.0);
    startY_.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) strength_.push_back(law_.strengthAt(int(i), law_.state[i]));
    // The quiet phase ends when the first block no longer holds at its strength at theta = 0; not
    // with strengths a caller changes between steps (as the reference kernel).
    if (motion_.skipIdle && motion_.fixedStrengths)
      quietUntil_ = firstSlipStepAtRestPerBlock(stiffness_, strength_, motion_, kNever);
  } else if (motion_.skipIdle) {
    quietUntil_ = firstSlipStepAtRest(stiffness_, law_, motion_, kNever);
  }
  if (motion_.skipIdle) {
    if (motion_.integrator == Integrator::VelocityVerlet) {
      tiles_ = (nb_ + kTile - 1) / kTile;
      for (auto* v : {&pieceHx_, &pieceHy_, &pieceVx_, &pieceVy_, &pieceDx_, &pieceDy_, &pieceAx_, &pieceAy_})
        v->assign(std::size_t(nb_) * (nb_ + 1), 0.0);
      for (int r = 0; r < nb_; ++r) padRowPieces(keptPieces(r), nb_);
      pieceStep_.assign(std::size_t(nb_) * tiles_, -1);
      mobileStep_.assign(std::size_t(nb_) * tiles_, -1);
      holdFrom_.assign(std::size_t(nb_) * tiles_, -1);
      holdUntil_.assign(std::size_t(nb_) * tiles_, -1);
      heldRow_.assign(tiles_, 0);
      movedAround_.assign(tiles_, -1);
      columnMoved_.assign(tiles_, -1);
    }
  }
}

// After a block of row r started to slip at t_n: the first slips of those that never slipped.
template <class Law>
void FastLattice<Law>::firstSlips(int r, double t) {
  const int base = r * nb_;
  for (int c = 0; c < nb_; ++c) {
    const int i = base + c;
    if (mobile_[i] == 0.0 || everSlipped_[i]) continue;
    everSlipped_[i] = 1;
    ++slipped_;
    if (firstSlip_) firstSlip_[i] = t;
  }
}

template <class Law>
std::vector<std::uint8_t> FastLattice<Law>::blockStates() const {
  std::vector<std::uint8_t> states(mobile_.size());
  for (std::size_t i = 0; i < states.size(); ++i) states[i] = mobile_[i] != 0.0 ? Slipping : Stuck;
  return states;
}

template <class Law>
RowPieces FastLattice<Law>::rowPieces() {
  const std::size_t stride = std::size_t(nb_) + 1;
  double* p = rowPieces_.data() + 1;
  return RowPieces{p, p + stride, p + 2 * stride, p + 3 * stride, p + 4 * stride, p + 5 * stride, p + 6 * stride,
                   p + 7 * stride};
}

template <class Law>
RowPieces FastLattice<Law>::keptPieces(int r) {
  const std::size_t at = std::size_t(r) * (nb_ + 1) + 1;
  return RowPieces{pieceHx_.data() + at, pieceHy_.data() + at, pieceVx_.data() + at, pieceVy_.data() + at,
                   pieceDx_.data() + at, pieceDy_.data() + at, pieceAx_.data() + at, pieceAy_.data() + at};
}

// The active set pays while few tiles are stale; once more than half of them are, the full sweep
// is cheaper (no pieces to store): switch, and look again every kModeCheck steps whether fewer
// than a quarter of the tiles hold a slipping block.
template <class Law>
bool FastLattice<Law>::useActiveSet() {
  constexpr int kModeCheck = 16;
  if (!motion_.skipIdle || motion_.integrator != Integrator::VelocityVerlet) return false;
  const int total = nb_ * tiles_;
  if (activeMode_) {
    if (steps_ > nextModeCheck_ && 2 * staleTiles_ > total) {
      activeMode_ = false;
      nextModeCheck_ = steps_ + kModeCheck;
    }
    return activeMode_;
  }
  if (steps_ < nextModeCheck_) return false;
  int slipping = 0;
  for (int r = 0; r < nb_; ++r)
    for (int tile = 0; tile < tiles_; ++tile) {
      const double* mobile = mobile_.data() + r * nb_ + tile * kTile;
      const int w = std::min(kTile, nb_ - tile * kTile);
      for (int c = 0; c < w; ++c)
        if (mobile[c] != 0.0) {
          ++slipping;
          break;
        }
    }
  if (4 * slipping >= total) {
    nextModeCheck_ = steps_ + kModeCheck;
    return false;
  }
  // Enter: every piece stale, every tile possibly moved in the last step (full sweep).
  activeMode_ = true;
  nextModeCheck_ = steps_ + 1;  // the first active step evaluates every tile: do not judge it
  std::fill(pieceStep_.begin(), pieceStep_.end(), -1);
  std::fill(mobileStep_.begin(), mobileStep_.end(), steps_ - 1);
  std::fill(holdUntil_.begin(), holdUntil_.end(), -1);
  return true;
}

template <class Law>
StepObservation FastLattice<Law>::step() {
  StepObservation observation{time(), 0.0, 0.0};
  if (steps_ < quietUntil_) {  // at rest: nothing to integrate, the sums are known
    restSliderForceSums(stiffness_, motion_, steps_, sliderRowX_.data(), observation.sliderForceX,
                        observation.sliderForceY);
    ++steps_;
    return observation;
  }
  dispatch(observation.sliderForceX, observation.sliderForceY);
  ++steps_;
  return observation;
}

#define GF_INSTANTIATE_FAST_LATTICE(Law) template class FastLattice<Law>;
GF_FRICTION_LAWS(GF_INSTANTIATE_FAST_LATTICE)
GF_STATE_FRICTION_LAWS(GF_INSTANTIATE_FAST_LATTICE)
#undef GF_INSTANTIATE_FAST_LATTICE

}  // namespace gradfric::sbm
