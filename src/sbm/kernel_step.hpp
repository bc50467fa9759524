#pragma once
// Private to the fast spring-block kernel: the definitions of its per-ISA entries
// (kernel_entries.hpp). The sweeps they run are forced inline (kernel_inline.hpp), so each entry
// compiles the whole step for its own instruction set: full_sweep.hpp (velocity Verlet, the full
// sweep), active_set.hpp (velocity Verlet on the active set), rk4_sweep.hpp (RK4).
#include "active_set.hpp"
#include "full_sweep.hpp"
#include "kernel_entries.hpp"
#include "rk4_sweep.hpp"

namespace gradfric::sbm {

template <class Law, bool Graded, SiteLayout L>
GF_ALWAYS_INLINE void fullStep(FastLattice<Law>& lattice, bool verlet, bool active, double t, double h,
                               double& sumX, double& sumY) {
  if (active) {
    lattice.template verletStepActive<Graded, L>(t, sumX, sumY);
    return;
  }
  if (verlet) {
    lattice.template verletStep<Graded, L>(t, sumX, sumY);
    return;
  }
  lattice.template rk4Stage<Graded, L, 1>(t, sumX, sumY);
  lattice.template rk4Stage<Graded, L, 2>(t + 0.5 * h, sumX, sumY);
  lattice.template rk4Stage<Graded, L, 3>(t + 0.5 * h, sumX, sumY);
  lattice.template rk4Stage<Graded, L, 4>(t + h, sumX, sumY);
}

template <class Law, bool Graded, SiteLayout L>
GF_TARGET("avx512f") void stepAvx512(FastLattice<Law>& lattice, bool verlet, bool active, double t, double h,
                                     double& sumX, double& sumY) {
  fullStep<Law, Graded, L>(lattice, verlet, active, t, h, sumX, sumY);
}
template <class Law, bool Graded, SiteLayout L>
GF_TARGET("avx2") void stepAvx2(FastLattice<Law>& lattice, bool verlet, bool active, double t, double h,
                                double& sumX, double& sumY) {
  fullStep<Law, Graded, L>(lattice, verlet, active, t, h, sumX, sumY);
}
template <class Law, bool Graded, SiteLayout L>
void stepBaseline(FastLattice<Law>& lattice, bool verlet, bool active, double t, double h, double& sumX,
                  double& sumY) {
  fullStep<Law, Graded, L>(lattice, verlet, active, t, h, sumX, sumY);
}

}  // namespace gradfric::sbm
