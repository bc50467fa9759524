#pragma once
// Private to the fast spring-block kernel: its compiled entries, one per law x (uniform|graded
// stiffness) x friction layout, each for AVX-512, AVX2 and baseline x86-64 (kernel_isa.hpp).
// kernel_dispatch.cpp chooses among them at run time and sees only these declarations; the
// definitions (kernel_step.hpp) are instantiated in one translation unit per instruction set and
// stiffness (kernel_<isa>_<stiffness>.cpp), so that a parallel build compiles them side by side.
#include "gradfric/sbm/integrator.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define GF_KERNEL_ISA_CLONES 1
#define GF_TARGET(isa) __attribute__((target(isa)))
#else
#define GF_KERNEL_ISA_CLONES 0
#define GF_TARGET(isa)
#endif

namespace gradfric::sbm {

// One step of the lattice: the active set, the Verlet full sweep or RK4's four stages.
template <class Law, bool Graded, SiteLayout L>
GF_TARGET("avx512f") void stepAvx512(FastLattice<Law>& lattice, bool verlet, bool active, double t, double h,
                                     double& sumX, double& sumY);
template <class Law, bool Graded, SiteLayout L>
GF_TARGET("avx2") void stepAvx2(FastLattice<Law>& lattice, bool verlet, bool active, double t, double h,
                                double& sumX, double& sumY);
template <class Law, bool Graded, SiteLayout L>
void stepBaseline(FastLattice<Law>& lattice, bool verlet, bool active, double t, double h, double& sumX,
                  double& sumY);

}  // namespace gradfric::sbm

// The explicit instantiations of one entry at one stiffness, for every law and layout: each
// kernel_<isa>_<stiffness>.cpp expands it once.
#define GF_KERNEL_ENTRY_AT(entry, Law, Graded, L) \
  template void entry<Law, Graded, SiteLayout::L>(FastLattice<Law>&, bool, bool, double, double, double&, double&);
#define GF_KERNEL_ENTRY_LAYOUTS(entry, Law, Graded) \
  GF_KERNEL_ENTRY_AT(entry, Law, Graded, Uniform)   \
  GF_KERNEL_ENTRY_AT(entry, Law, Graded, PerColumn) \
  GF_KERNEL_ENTRY_AT(entry, Law, Graded, PerSite)
