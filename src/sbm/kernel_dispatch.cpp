// The fast spring-block kernel's entry: the choice at run time among its compiled steps, one per
// law (those with a per-block state included), stiffness (uniform or graded) and friction layout, each for AVX-512, AVX2 and baseline
// x86-64 (kernel_isa.hpp). The steps are declared in kernel_entries.hpp and compiled in the
// kernel_<isa>_<stiffness>.cpp files; this file sees none of their code.
#include "kernel_entries.hpp"

#include "gradfric/sbm/kernel_isa.hpp"

namespace gradfric::sbm {

namespace {

// The one the processor supports best is chosen at run time (kernel_isa.hpp: a test may force
// each in turn to check that they agree bit for bit).
template <class Law, bool Graded, SiteLayout L>
void stepVariant(FastLattice<Law>& lattice, bool verlet, bool active, double t, double h, double& sumX, double& sumY) {
  switch (kernelIsaInUse()) {
    case KernelIsa::Avx512: stepAvx512<Law, Graded, L>(lattice, verlet, active, t, h, sumX, sumY); return;
    case KernelIsa::Avx2: stepAvx2<Law, Graded, L>(lattice, verlet, active, t, h, sumX, sumY); return;
    default: stepBaseline<Law, Graded, L>(lattice, verlet, active, t, h, sumX, sumY); return;
  }
}

template <class Law, bool Graded>
void stepLayout(FastLattice<Law>& lattice, SiteLayout layout, bool verlet, bool active, double t, double h,
                double& sumX, double& sumY) {
  if (layout == SiteLayout::Uniform)
    stepVariant<Law, Graded, SiteLayout::Uniform>(lattice, verlet, active, t, h, sumX, sumY);
  else if (layout == SiteLayout::PerColumn)
    stepVariant<Law, Graded, SiteLayout::PerColumn>(lattice, verlet, active, t, h, sumX, sumY);
  else stepVariant<Law, Graded, SiteLayout::PerSite>(lattice, verlet, active, t, h, sumX, sumY);
}

}  // namespace

template <class Law>
void FastLattice<Law>::dispatch(double& sumX, double& sumY) {
  const double t = time();
  const double h = motion_.timeStep;
  const bool verlet = motion_.integrator == Integrator::VelocityVerlet;
  const bool active = useActiveSet();
  if (active) ++activeSetSteps_;
  if (stiffness_.graded) stepLayout<Law, true>(*this, law_.sites.layout, verlet, active, t, h, sumX, sumY);
  else stepLayout<Law, false>(*this, law_.sites.layout, verlet, active, t, h, sumX, sumY);
}

namespace {
KernelIsa forcedIsa = KernelIsa::Automatic;

KernelIsa bestIsa() {
#if GF_KERNEL_ISA_CLONES
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f")) return KernelIsa::Avx512;
  if (__builtin_cpu_supports("avx2")) return KernelIsa::Avx2;
#endif
  return KernelIsa::Baseline;
}
}  // namespace

bool kernelIsaSupported(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::Automatic:
    case KernelIsa::Baseline: return true;
    case KernelIsa::Avx2: return bestIsa() != KernelIsa::Baseline;
    case KernelIsa::Avx512: return bestIsa() == KernelIsa::Avx512;
  }
  return false;
}

bool forceKernelIsa(KernelIsa isa) {
  if (!kernelIsaSupported(isa)) return false;
  forcedIsa = isa;
  return true;
}

KernelIsa kernelIsaInUse() {
  static const KernelIsa best = bestIsa();
  return forcedIsa == KernelIsa::Automatic ? best : forcedIsa;
}

const char* kernelIsaName(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::Avx512: return "avx512f";
    case KernelIsa::Avx2: return "avx2";
    case KernelIsa::Baseline: return "baseline x86-64";
    default: return "automatic";
  }
}

#define GF_INSTANTIATE_DISPATCH(Law) template void FastLattice<Law>::dispatch(double&, double&);
GF_FRICTION_LAWS(GF_INSTANTIATE_DISPATCH)
GF_STATE_FRICTION_LAWS(GF_INSTANTIATE_DISPATCH)
#undef GF_INSTANTIATE_DISPATCH

}  // namespace gradfric::sbm
