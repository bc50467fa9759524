// The plain reference: an array of blocks, each summing the forces of its 8 neighbours (every
// spring evaluated twice), and textbook RK4 on the whole state vector. Same physics and the same
// stick/slip rule as FastLattice; the tests compare the two.
#include "gradfric/sbm/integrator.hpp"
#include "gradfric/sbm/spring.hpp"

#include <cmath>

namespace gradfric::sbm {

ReferenceLattice::ReferenceLattice(const LatticeStiffness& stiffness, const FrictionField& friction,
                                   const Motion& motion)
    : stiffness_(stiffness), friction_(friction), motion_(motion), nb_(stiffness.blocksPerSide) {
  blocks_.assign(std::size_t(nb_) * nb_, Block{0, 0, 0, 0});
  state_.assign(blocks_.size(), Stuck);
  everSlipped_.assign(blocks_.size(), 0);
}

void ReferenceLattice::forces(const std::vector<Block>& y, double t, std::vector<double>& fx,
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
      const double ks = stiffness_.slider[c];
      double Fx = ks * (motion_.sliderVelocityX * t - y[i].ux);
      double Fy = ks * (motion_.sliderVelocityY * t - y[i].uy);
      for (const auto& n : neighbours) {
        const int rr = r + n.dr, cc = c + n.dc;
        if (rr < 0 || rr >= nb || cc < 0 || cc >= nb) continue;
        const int j = rr * nb + cc;
        double k, restLength;
        if (n.dr == 0) {
          k = stiffness_.horizontal[std::min(c, cc)];
          restLength = l;
        } else if (n.dc == 0) {
          k = stiffness_.vertical[c];
          restLength = l;
        } else {
          k = stiffness_.diagonal[std::min(c, cc)];
          restLength = ld;
        }
        const Force2 f = springForce(k, n.dc * l, n.dr * l, restLength, y[j].ux - y[i].ux, y[j].uy - y[i].uy);
        Fx += f.x;
        Fy += f.y;
      }
      fx[i] = Fx;
      fy[i] = Fy;
    }
  }
}

void ReferenceLattice::drivingForces(std::vector<double>& fx, std::vector<double>& fy) const {
  forces(blocks_, time(), fx, fy);
}

void ReferenceLattice::derivative(const std::vector<Block>& y, double t, std::vector<Block>& dy) const {
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

StepObservation ReferenceLattice::step() {
  const double t = time();
  const double h = motion_.timeStep;
  StepObservation observation{t, 0.0, 0.0};
  // Stick/slip transitions with the driving forces of the state at t_n.
  std::vector<double> fx, fy;
  forces(blocks_, t, fx, fy);
  for (int r = 0; r < nb_; ++r) {
    for (int c = 0; c < nb_; ++c) {
      const int i = r * nb_ + c;
      observation.sliderForceX += stiffness_.slider[c] * (motion_.sliderVelocityX * t - blocks_[i].ux);
      observation.sliderForceY += stiffness_.slider[c] * (motion_.sliderVelocityY * t - blocks_[i].uy);
      if (state_[i] == Slipping) continue;
      const double threshold = friction_.staticAt(r, c);
      const bool holds = fx[i] * fx[i] + fy[i] * fy[i] <= threshold * threshold;
      if (state_[i] == Stuck && !holds) {
        state_[i] = Slipping;
        if (!everSlipped_[i]) {
          everSlipped_[i] = 1;
          ++slipped_;
          if (firstSlip_) firstSlip_[i] = t;
        }
      } else if (state_[i] == Reversed) {
        if (holds) {
          state_[i] = Stuck;
          blocks_[i].vx = blocks_[i].vy = 0.0;
        } else {
          state_[i] = Slipping;
        }
      }
    }
  }
  // The kinetic friction of this step, frozen for the four stages (see integrator.hpp).
  const std::size_t n = blocks_.size();
  frictionX_.assign(n, 0.0);
  frictionY_.assign(n, 0.0);
  for (int r = 0; r < nb_; ++r) {
    for (int c = 0; c < nb_; ++c) {
      const int i = r * nb_ + c;
      if (state_[i] == Stuck) continue;
      const Block& b = blocks_[i];
      const double speed = std::sqrt(b.vx * b.vx + b.vy * b.vy);
      const double force = std::sqrt(fx[i] * fx[i] + fy[i] * fy[i]);
      const double kinetic = friction_.kineticAt(r, c);
      if (speed > 0) {
        frictionX_[i] = kinetic * b.vx / speed;
        frictionY_[i] = kinetic * b.vy / speed;
      } else if (force > 0) {
        frictionX_[i] = kinetic * fx[i] / force;
        frictionY_[i] = kinetic * fy[i] / force;
      }
    }
  }
  // Classical RK4.
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
    if (state_[i] != Stuck && b.vx * frictionX_[i] + b.vy * frictionY_[i] < 0.0) state_[i] = Reversed;
  }
  ++steps_;
  return observation;
}

std::vector<double> ReferenceLattice::displacementX() const {
  std::vector<double> out;
  for (const auto& b : blocks_) out.push_back(b.ux);
  return out;
}
std::vector<double> ReferenceLattice::displacementY() const {
  std::vector<double> out;
  for (const auto& b : blocks_) out.push_back(b.uy);
  return out;
}
std::vector<double> ReferenceLattice::velocityX() const {
  std::vector<double> out;
  for (const auto& b : blocks_) out.push_back(b.vx);
  return out;
}

}  // namespace gradfric::sbm

namespace gradfric::sbm {
std::vector<double> ReferenceLattice::velocityY() const {
  std::vector<double> out;
  for (const auto& b : blocks_) out.push_back(b.vy);
  return out;
}
}  // namespace gradfric::sbm
