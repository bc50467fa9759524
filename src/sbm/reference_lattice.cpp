// The plain reference: an array of blocks, each summing the forces of its 8 neighbours (every
// spring evaluated twice), and textbook RK4 or velocity Verlet on the whole state vector. Same
// physics, the same friction law and the same stick/slip rule as FastLattice; the tests compare
// the two, for every law (reference_lattice.hpp).
#include "gradfric/sbm/reference_lattice.hpp"

#include "gradfric/sbm/quiet_phase.hpp"
#include "gradfric/sbm/spring.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace gradfric::sbm {

template <class Law>
ReferenceLattice<Law>::ReferenceLattice(const LatticeStiffness& stiffness, Law law, const Motion& motion)
    : stiffness_(stiffness), law_(std::move(law)), motion_(motion), nb_(stiffness.blocksPerSide) {
  blocks_.assign(std::size_t(nb_) * nb_, Block{0, 0, 0, 0});
  frictionX_.assign(blocks_.size(), 0.0);
  frictionY_.assign(blocks_.size(), 0.0);
  state_.assign(blocks_.size(), Stuck);
  everSlipped_.assign(blocks_.size(), 0);
  if constexpr (hasBlockState<Law>) {
    startX_.assign(blocks_.size(), 0.0);
    startY_.assign(blocks_.size(), 0.0);
    for (std::size_t i = 0; i < blocks_.size(); ++i) strength_.push_back(law_.strengthAt(int(i), law_.state[i]));
    // The quiet phase: every block at rest at theta = 0 until the first one no longer holds at its
    // strength there (not with strengths a caller changes between steps).
    if (motion_.skipIdle && motion_.fixedStrengths)
      quietUntil_ = firstSlipStepAtRestPerBlock(stiffness_, strength_, motion_, std::int64_t(1) << 52);
  }
}

// State laws: the state of every block over the step that just ended, from its slip (its
// displacement increment: the substrate is fixed), committed once; its strength at the new state.
template <class Law>
void ReferenceLattice<Law>::advanceStates() {
  if constexpr (hasBlockState<Law>) {
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
      const double slip = slipOf(blocks_[i].ux - startX_[i], blocks_[i].uy - startY_[i]);
      strength_[i] = law_.advance(int(i), slip, motion_.timeStep);
      startX_[i] = blocks_[i].ux;
      startY_[i] = blocks_[i].uy;
    }
    law_.commit();
  }
}

// The static threshold of block i at (r, c): mu_s,i F_n, or with a state law its current strength.
template <class Law>
double ReferenceLattice<Law>::staticThreshold(int r, int c, int i) const {
  if constexpr (hasBlockState<Law>) return strength_[i];
  else return law_.sites.staticAt(law_.sites.slot(r, c));
}

template <class Law>
void ReferenceLattice<Law>::forces(const std::vector<Block>& y, double t, std::vector<double>& fx,
                              std::vector<double>& fy) const {
  const int nb = nb_;
  const double l = stiffness_.spacing;
  const double ld = std::sqrt(2.0) * l;
  fx.assign(y.size(), 0.0);
  fy.assign(y.size(), 0.0);
  struct Neighbour {
    int dr, dc;
  };
  static const Neighbour neighbours[8] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
  for (int r = 0; r < nb; ++r) {
    for (int c = 0; c < nb; ++c) {
      const int i = r * nb + c;
      const double ks = stiffness_.sliderAt(r, c);
      double Fx = ks * (motion_.sliderVelocityX * t - y[i].ux);
      double Fy = ks * (motion_.sliderVelocityY * t - y[i].uy);
      for (const auto& n : neighbours) {
        const int rr = r + n.dr, cc = c + n.dc;
        if (rr < 0 || rr >= nb || cc < 0 || cc >= nb) continue;
        const int j = rr * nb + cc;
        // Each spring belongs to the lower of its two rows, and to the left of its two columns.
        const RowStiffness springs = stiffness_.row(std::min(r, rr));
        double k, restLength;
        if (n.dr == 0) {
          k = springs.horizontal[std::min(c, cc)];
          restLength = l;
        } else if (n.dc == 0) {
          k = springs.vertical[c];
          restLength = l;
        } else {
          k = n.dr == n.dc ? springs.diagonal[std::min(c, cc)] : springs.antiDiagonal[std::min(c, cc)];
          restLength = ld;
        }
        const double dux = y[j].ux - y[i].ux, duy = y[j].uy - y[i].uy;
        const Force2 f = stiffness_.smallStrain ? latticeSpringForce<true>(k, n.dc * l, n.dr * l, restLength, dux, duy)
                                                : latticeSpringForce<false>(k, n.dc * l, n.dr * l, restLength, dux, duy);
        Fx += f.x;
        Fy += f.y;
      }
      fx[i] = Fx;
      fy[i] = Fy;
    }
  }
}

template <class Law>
void ReferenceLattice<Law>::drivingForces(std::vector<double>& fx, std::vector<double>& fy) const {
  forces(blocks_, time(), fx, fy);
}

template <class Law>
void ReferenceLattice<Law>::derivative(const std::vector<Block>& y, double t, std::vector<Block>& dy) const {
  std::vector<double> fx, fy;
  forces(y, t, fx, fy);
  dy.resize(y.size());
  for (int r = 0; r < nb_; ++r) {
    for (int c = 0; c < nb_; ++c) {
      const int i = r * nb_ + c;
      if (state_[i] == Stuck) {
        dy[i] = Block{0, 0, 0, 0};
        continue;
      }
      dy[i].ux = y[i].vx;
      dy[i].uy = y[i].vy;
      dy[i].vx = (fx[i] - frictionX_[i]) / motion_.mass - motion_.damping * y[i].vx;
      dy[i].vy = (fy[i] - frictionY_[i]) / motion_.mass - motion_.damping * y[i].vy;
    }
  }
}

// Velocity Verlet half kick with the friction of the step: v += h/2 (F - F_f) / m - h/2 gamma v
// (damping with the velocity at hand, as FastLattice).
template <class Law>
void ReferenceLattice<Law>::kick(const std::vector<double>& fx, const std::vector<double>& fy) {
  const double half = 0.5 * motion_.timeStep;
  for (std::size_t i = 0; i < blocks_.size(); ++i) {
    if (state_[i] == Stuck) continue;
    Block& b = blocks_[i];
    b.vx += half * ((fx[i] - frictionX_[i]) / motion_.mass - motion_.damping * b.vx);
    b.vy += half * ((fy[i] - frictionY_[i]) / motion_.mass - motion_.damping * b.vy);
  }
}

// A moving block whose velocity points against the step's friction reversed.
template <class Law>
void ReferenceLattice<Law>::markReversals() {
  for (std::size_t i = 0; i < blocks_.size(); ++i) {
    const Block& b = blocks_[i];
    if (state_[i] != Stuck && b.vx * frictionX_[i] + b.vy * frictionY_[i] < 0.0) state_[i] = Reversed;
  }
}

template <class Law>
StepObservation ReferenceLattice<Law>::step() {
  const double t = time();
  const bool verlet = motion_.integrator == Integrator::VelocityVerlet;
  StepObservation observation{t, 0.0, 0.0};
  if (steps_ < quietUntil_) {  // at rest (state laws): the slider sums of the stepped run, in its order
    for (int r = 0; r < nb_; ++r)
      for (int c = 0; c < nb_; ++c) {
        observation.sliderForceX += stiffness_.sliderAt(r, c) * (motion_.sliderVelocityX * t - blocks_[r * nb_ + c].ux);
        observation.sliderForceY += stiffness_.sliderAt(r, c) * (motion_.sliderVelocityY * t - blocks_[r * nb_ + c].uy);
      }
    ++steps_;
    return observation;
  }
  std::vector<double> fx, fy;
  forces(blocks_, t, fx, fy);
  if (verlet) {  // close the previous step: v_n = v_{n-1/2} + h/2 a_n, that step's friction
    kick(fx, fy);
    markReversals();
  }
  advanceStates();  // state laws only
  // Stick/slip transitions with the driving forces of the state at t_n.
  for (int r = 0; r < nb_; ++r) {
    for (int c = 0; c < nb_; ++c) {
      const int i = r * nb_ + c;
      observation.sliderForceX += stiffness_.sliderAt(r, c) * (motion_.sliderVelocityX * t - blocks_[i].ux);
      observation.sliderForceY += stiffness_.sliderAt(r, c) * (motion_.sliderVelocityY * t - blocks_[i].uy);
      const double force2 = fx[i] * fx[i] + fy[i] * fy[i], threshold = staticThreshold(r, c, i);
      switch (stickSlipChange(state_[i], holdsAtRest<Law>(force2, threshold))) {
        case StickSlipChange::StartsToSlip:
          state_[i] = Slipping;
          if (!everSlipped_[i]) {
            everSlipped_[i] = 1;
            ++slipped_;
            if (firstSlip_) firstSlip_[i] = t;
          }
          break;
        case StickSlipChange::Resticks:
          state_[i] = Stuck;
          blocks_[i].vx = blocks_[i].vy = 0.0;
          break;
        case StickSlipChange::SlidesOn: state_[i] = Slipping; break;
        case StickSlipChange::None: break;
      }
    }
  }
  // The friction force of this step, frozen for the step (see integrator.hpp).
  for (int r = 0; r < nb_; ++r) {
    for (int c = 0; c < nb_; ++c) {
      const int i = r * nb_ + c;
      const Block& b = blocks_[i];
      const int slot = law_.sites.slot(r, c);
      const double speed2 = b.vx * b.vx + b.vy * b.vy;
      const double mobile = state_[i] == Stuck ? 0.0 : 1.0, force2 = fx[i] * fx[i] + fy[i] * fy[i];
      double perDirection;
      if constexpr (hasBlockState<Law>) {  // the strength at the block's state, along v (or F_mot from rest)
        perDirection = frictionPerDirectionAt(strength_[i], mobile, speed2, force2);
      } else {
        perDirection = frictionPerDirection(law_, law_.sites.staticAt(slot), law_.sites.kineticAt(slot), mobile,
                                            speed2, force2);
      }
      frictionX_[i] = perDirection * (speed2 > 0 ? b.vx : fx[i]);
      frictionY_[i] = perDirection * (speed2 > 0 ? b.vy : fy[i]);
    }
  }
  if (verlet) {  // open this step: v_{n+1/2} = v_n + h/2 a_n, u_{n+1} = u_n + h v_{n+1/2}
    kick(fx, fy);
    for (auto& b : blocks_) {
      b.ux += motion_.timeStep * b.vx;
      b.uy += motion_.timeStep * b.vy;
    }
  } else {
    rk4(t);
    markReversals();
  }
  ++steps_;
  return observation;
}

// Classical RK4 on the whole state, the friction and stick states frozen.
template <class Law>
void ReferenceLattice<Law>::rk4(double t) {
  const double h = motion_.timeStep;
  const std::size_t n = blocks_.size();
  std::vector<Block> k1, k2, k3, k4, y(n);
  auto axpy = [&](const std::vector<Block>& k, double a) {
    for (std::size_t i = 0; i < n; ++i)
      y[i] = Block{blocks_[i].ux + a * k[i].ux, blocks_[i].uy + a * k[i].uy, blocks_[i].vx + a * k[i].vx,
                   blocks_[i].vy + a * k[i].vy};
  };
  derivative(blocks_, t, k1);
  axpy(k1, 0.5 * h);
  derivative(y, t + 0.5 * h, k2);
  axpy(k2, 0.5 * h);
  derivative(y, t + 0.5 * h, k3);
  axpy(k3, h);
  derivative(y, t + h, k4);
  for (std::size_t i = 0; i < n; ++i) {
    Block& b = blocks_[i];
    b.ux += h / 6.0 * (((k1[i].ux + 2.0 * k2[i].ux) + 2.0 * k3[i].ux) + k4[i].ux);
    b.uy += h / 6.0 * (((k1[i].uy + 2.0 * k2[i].uy) + 2.0 * k3[i].uy) + k4[i].uy);
    b.vx += h / 6.0 * (((k1[i].vx + 2.0 * k2[i].vx) + 2.0 * k3[i].vx) + k4[i].vx);
    b.vy += h / 6.0 * (((k1[i].vy + 2.0 * k2[i].vy) + 2.0 * k3[i].vy) + k4[i].vy);
  }
}

template <class Law>
std::vector<double> ReferenceLattice<Law>::displacementX() const {
  std::vector<double> out;
  for (const auto& b : blocks_) out.push_back(b.ux);
  return out;
}
template <class Law>
std::vector<double> ReferenceLattice<Law>::displacementY() const {
  std::vector<double> out;
  for (const auto& b : blocks_) out.push_back(b.uy);
  return out;
}
template <class Law>
std::vector<double> ReferenceLattice<Law>::velocityX() const {
  std::vector<double> out;
  for (const auto& b : blocks_) out.push_back(b.vx);
  return out;
}
template <class Law>
std::vector<double> ReferenceLattice<Law>::velocityY() const {
  std::vector<double> out;
  for (const auto& b : blocks_) out.push_back(b.vy);
  return out;
}

#define GF_INSTANTIATE_REFERENCE_LATTICE(Law) template class ReferenceLattice<Law>;
GF_FRICTION_LAWS(GF_INSTANTIATE_REFERENCE_LATTICE)
GF_STATE_FRICTION_LAWS(GF_INSTANTIATE_REFERENCE_LATTICE)
#undef GF_INSTANTIATE_REFERENCE_LATTICE

}  // namespace gradfric::sbm
