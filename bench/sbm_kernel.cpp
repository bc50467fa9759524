// Nanoseconds per block per RK4 step of the spring-block kernels, fast and plain reference, and
// whole realisations stepped from t = 0 against idle work skipped, in one run (the machines are shared and noisy: compare the ratio, not the absolute figures).
//
//   build/bench/bench_sbm_kernel [--benchmark_min_time=2] [-- N]
//
// The lattice (N_b = 120 by default, paper parameters, sigma = 2.8 %) is first driven past its
// static peak so that blocks stick and slip as in a real run; then whole RK4 steps are timed.
#include "gradfric/sbm/integrator.hpp"
#include "gradfric/sbm/reference_lattice.hpp"
#include "gradfric/sbm/kernel_isa.hpp"
#include "gradfric/sbm/lattice.hpp"
#include "gradfric/sbm/model.hpp"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

using namespace gradfric;
using namespace gradfric::sbm;

namespace {

int blocksPerSide = 120;

struct Setup {
  Parameters parameters;
  LatticeStiffness stiffness;
  FrictionField friction;
  Motion motion;
};

Setup makeSetup() {
  Setup s;
  Grading grading;
  s.parameters.blocksPerSide = blocksPerSide;
  s.parameters.damping = 0.1 * std::sqrt(s.parameters.axialStiffness(s.parameters.plate.youngsModulus) / s.parameters.blockMass());
  s.parameters.timeStep = 0.25 * stableTimeStep(s.parameters, grading);
  s.stiffness = buildStiffness(s.parameters, grading);
  s.friction = buildFriction(s.parameters, grading, StreamKey{1, 0, 0});
  s.motion = motionOf(s.parameters, s.parameters.timeStep, s.parameters.damping);
  return s;
}

template <template <class> class Lattice, Integrator scheme = Integrator::RK4, class Law = CoulombStickSlip,
          bool SkipIdle = false, bool SmallStrain = false>
void benchmarkStep(benchmark::State& state) {
  Setup s = makeSetup();
  s.stiffness.smallStrain = SmallStrain;
  s.motion.integrator = scheme;
  s.motion.skipIdle = SkipIdle;  // false: the full sweep every step
  Lattice<Law> lattice(s.stiffness, [&] {
    const std::size_t blocks = std::size_t(blocksPerSide) * blocksPerSide;
    if constexpr (hasBlockState<Law>) return Law::make(s.friction, FrictionLawSettings{}, blocks);
    else return Law::make(s.friction, FrictionLawSettings{});
  }(), s.motion);
  // Warm up into the sliding phase: just past the loading time, most blocks slip.
  while (lattice.time() < 1.05 * s.parameters.loadingTime()) lattice.step();
  for (auto _ : state) benchmark::DoNotOptimize(lattice.step());
  const double blocks = double(s.parameters.blocksPerSide) * s.parameters.blocksPerSide;
  state.counters["ns_per_block_step"] =
      benchmark::Counter(blocks * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["slipped_blocks"] = lattice.slippedBlocks();
}

void BM_FastLattice(benchmark::State& state) { benchmarkStep<FastLattice>(state); }
void BM_ReferenceLattice(benchmark::State& state) { benchmarkStep<ReferenceLattice>(state); }
void BM_FastLatticeVerlet(benchmark::State& state) { benchmarkStep<FastLattice, Integrator::VelocityVerlet>(state); }
// The same sliding lattice with idle work skipped: Verlet on the active set of tiles.
void BM_FastLatticeVerletSkipIdle(benchmark::State& state) {
  benchmarkStep<FastLattice, Integrator::VelocityVerlet, CoulombStickSlip, true>(state);
}
// The same sliding lattice with small-strain springs (-sbm_spring small_strain): no square roots.
void BM_FastLatticeVerletSmallStrain(benchmark::State& state) {
  benchmarkStep<FastLattice, Integrator::VelocityVerlet, CoulombStickSlip, false, true>(state);
}
void BM_FastLatticeExponential(benchmark::State& state) {
  benchmarkStep<FastLattice, Integrator::RK4, ExponentialVelocityWeakening>(state);
}
// The state law's cost (block_state.hpp): on both kernels, against the exponential law on each
// (the fast kernel's full sweep and active set), Verlet, the default.
void BM_FastLatticeVerletState(benchmark::State& state) {
  benchmarkStep<FastLattice, Integrator::VelocityVerlet, StateWeakening>(state);
}
void BM_FastLatticeVerletStateSkipIdle(benchmark::State& state) {
  benchmarkStep<FastLattice, Integrator::VelocityVerlet, StateWeakening, true>(state);
}
void BM_ReferenceLatticeVerletState(benchmark::State& state) {
  benchmarkStep<ReferenceLattice, Integrator::VelocityVerlet, StateWeakening>(state);
}
void BM_ReferenceLatticeVerletExponential(benchmark::State& state) {
  benchmarkStep<ReferenceLattice, Integrator::VelocityVerlet, ExponentialVelocityWeakening>(state);
}
void BM_FastLatticeVerletExponential(benchmark::State& state) {
  benchmarkStep<FastLattice, Integrator::VelocityVerlet, ExponentialVelocityWeakening>(state);
}
void BM_FastLatticeVerletExponentialSkipIdle(benchmark::State& state) {
  benchmarkStep<FastLattice, Integrator::VelocityVerlet, ExponentialVelocityWeakening, true>(state);
}
// The Verlet full sweep on each ISA version of the kernel (kernel_isa.hpp; the same numbers bit
// for bit), where the processor has it.
template <KernelIsa Isa>
void BM_FastLatticeVerletOn(benchmark::State& state) {
  if (!forceKernelIsa(Isa)) {
    state.SkipWithError("not supported by this processor");
    return;
  }
  benchmarkStep<FastLattice, Integrator::VelocityVerlet>(state);
  forceKernelIsa(KernelIsa::Automatic);
}
void BM_FastLatticeVerletAvx2(benchmark::State& state) { BM_FastLatticeVerletOn<KernelIsa::Avx2>(state); }
void BM_FastLatticeVerletBaseline(benchmark::State& state) { BM_FastLatticeVerletOn<KernelIsa::Baseline>(state); }
BENCHMARK(BM_FastLattice)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FastLatticeExponential)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FastLatticeVerlet)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FastLatticeVerletSkipIdle)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FastLatticeVerletSmallStrain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FastLatticeVerletAvx2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FastLatticeVerletBaseline)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReferenceLattice)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReferenceLatticeVerletState)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReferenceLatticeVerletExponential)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FastLatticeVerletExponential)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FastLatticeVerletExponentialSkipIdle)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FastLatticeVerletState)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FastLatticeVerletStateSkipIdle)->Unit(benchmark::kMillisecond);

// Whole realisations of the default scene's graded plate (friction, linear, Delta = 0.2, the
// driver's derived defaults), stepped from t = 0 (the old path) and with idle work skipped (the
// new one): mu_s only (stops at the confirmed peak), and full (through the mu_k window).
// The laws' realisations: the same plate under the exponential and the state law (Verlet, idle
// work skipped, through the mu_k window), on the kernel asked for.
// The default scene's graded plate: friction, linear, Delta = 0.2, 10 bands.
Grading defaultSceneGrading() {
  Grading grading;
  grading.profile = GradingProfile::Linear;
  grading.property = GradedProperty::Friction;
  grading.delta = 0.2;
  grading.bands = 10;
  return grading;
}

template <bool Kinetic, bool SkipIdle>
void benchmarkRealisation(benchmark::State& state, const char* law = "coulomb", Kernel kernel = Kernel::Fast) {
  const Grading grading = defaultSceneGrading();
  Parameters p;
  p.blocksPerSide = blocksPerSide;
  p.damping = 0.1 * std::sqrt(p.axialStiffness(p.plate.youngsModulus) / p.blockMass());
  p.timeStep = defaultTimeStep(p, grading);
  p.skipIdle = SkipIdle;
  p.frictionLaw.name = law;
  Request q;
  const double load = p.loadingTime();
  q.measurement.kinetic = Kinetic;
  q.measurement.historyInterval = 1e-3 * load;
  q.measurement.kineticDelay = 0.5 * load;
  q.measurement.kineticWidth = load;
  q.measurement.peakHold = 0.25 * load;
  q.maxTime = 20 * load;
  std::uint32_t realisation = 0;
  double steps = 0, quiet = 0, muStatic = 0;
  for (auto _ : state) {
    const Result r = simulate(p, grading, q, StreamKey{1, 1, realisation++}, kernel);
    steps += double(r.steps);
    quiet += r.friction.firstSlipTime / p.timeStep;
    muStatic += r.friction.muStatic;
  }
  state.counters["steps"] = steps / double(state.iterations());
  state.counters["steps_before_first_slip"] = quiet / double(state.iterations());
  state.counters["mu_s"] = muStatic / double(state.iterations());
}
void BM_RealisationMuStaticStepped(benchmark::State& s) { benchmarkRealisation<false, false>(s); }
void BM_RealisationMuStaticSkipIdle(benchmark::State& s) { benchmarkRealisation<false, true>(s); }
void BM_RealisationFullStepped(benchmark::State& s) { benchmarkRealisation<true, false>(s); }
void BM_RealisationFullSkipIdle(benchmark::State& s) { benchmarkRealisation<true, true>(s); }
BENCHMARK(BM_RealisationMuStaticStepped)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_RealisationMuStaticSkipIdle)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_RealisationFullStepped)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_RealisationFullSkipIdle)->Unit(benchmark::kSecond)->Iterations(2);
void BM_RealisationExponential(benchmark::State& s) { benchmarkRealisation<true, true>(s, "exponential"); }
void BM_RealisationState(benchmark::State& s) { benchmarkRealisation<true, true>(s, "state"); }
void BM_RealisationStateReference(benchmark::State& s) {
  benchmarkRealisation<true, true>(s, "state", Kernel::Reference);
}
BENCHMARK(BM_RealisationExponential)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_RealisationState)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_RealisationStateReference)->Unit(benchmark::kSecond)->Iterations(2);

// The random surface's share of a realisation: the lattice's friction built from each kind of
// surface (the per-block draws of the model before it, the cells, the Gaussian field), against the
// full realisation of the same plate above (BM_RealisationFullSkipIdle); the ratios are printed.
template <SurfaceKind Kind>
void BM_BuildFriction(benchmark::State& state) {
  const Grading grading = defaultSceneGrading();
  Parameters p;
  p.blocksPerSide = blocksPerSide;
  p.surface.kind = Kind;
  std::uint32_t realisation = 0;
  for (auto _ : state) benchmark::DoNotOptimize(buildFriction(p, grading, StreamKey{1, 0, realisation++}));
}
BENCHMARK(BM_BuildFriction<SurfaceKind::Blocks>)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BuildFriction<SurfaceKind::Cells>)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BuildFriction<SurfaceKind::Gaussian>)->Unit(benchmark::kMillisecond);

// Keeps each benchmark's ns per block-step to print the ratio at the end.
class RatioReporter : public benchmark::ConsoleReporter {
public:
  std::map<std::string, double> nsPerBlockStep;
  std::map<std::string, double> cpuSeconds;  // per iteration
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& run : runs) {
      if (run.run_type == Run::RT_Iteration && run.iterations > 0)
        cpuSeconds[run.benchmark_name()] = run.cpu_accumulated_time / double(run.iterations);
      auto it = run.counters.find("ns_per_block_step");
      if (it != run.counters.end() && run.run_type == Run::RT_Iteration)
        nsPerBlockStep[run.benchmark_name()] = it->second.value;
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  for (int i = 1; i < argc; ++i) blocksPerSide = std::atoi(argv[i]) > 1 ? std::atoi(argv[i]) : blocksPerSide;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  const double fast = reporter.nsPerBlockStep["BM_FastLattice"];
  const double plain = reporter.nsPerBlockStep["BM_ReferenceLattice"];
  const double verlet = reporter.nsPerBlockStep["BM_FastLatticeVerlet"];
  if (fast > 0 && plain > 0)
    std::printf("\nN_b = %d: fast %.1f ns, reference %.1f ns per block per RK4 step; speed-up %.2fx\n", blocksPerSide,
                fast, plain, plain / fast);
  const auto& t = reporter.cpuSeconds;
  auto ratio = [&](const char* what, const char* old, const char* now) {
    if (t.count(old) && t.count(now) && t.at(now) > 0)
      std::printf("%s realisation: stepped %.2f s, idle work skipped %.2f s (CPU): %.2fx faster\n", what, t.at(old),
                  t.at(now), t.at(old) / t.at(now));
  };
  ratio("mu_s-only", "BM_RealisationMuStaticStepped/iterations:2", "BM_RealisationMuStaticSkipIdle/iterations:2");
  ratio("full", "BM_RealisationFullStepped/iterations:2", "BM_RealisationFullSkipIdle/iterations:2");
  const auto full = t.find("BM_RealisationFullSkipIdle/iterations:2");
  if (full != t.end() && full->second > 0)
    for (const char* kind : {"Blocks", "Cells", "Gaussian"}) {
      const auto it = t.find(std::string("BM_BuildFriction<SurfaceKind::") + kind + ">");
      if (it != t.end())
        std::printf("N_b = %d: friction from the %s surface %.2f ms, %.2f %% of a full realisation (%.2f s)\n",
                    blocksPerSide, kind, 1e3 * it->second, 100 * it->second / full->second, full->second);
    }
  const double active = reporter.nsPerBlockStep["BM_FastLatticeVerletSkipIdle"];
  if (verlet > 0 && active > 0)
    std::printf("N_b = %d: velocity Verlet, sliding plate: full sweep %.1f ns, active set %.1f ns per block per step\n",
                blocksPerSide, verlet, active);
  if (verlet > 0 && plain > 0)
    std::printf("N_b = %d: velocity Verlet full sweep %.1f ns per block per step, plain reference (RK4) %.1f ns\n",
                blocksPerSide, verlet, plain);
  const double small = reporter.nsPerBlockStep["BM_FastLatticeVerletSmallStrain"];
  if (verlet > 0 && small > 0)
    std::printf("N_b = %d: velocity Verlet full sweep, small-strain springs %.1f ns per block per step (%.2fx the exact springs' cost)\n",
                blocksPerSide, small, small / verlet);
  const double state = reporter.nsPerBlockStep["BM_ReferenceLatticeVerletState"];
  const double plainExponential = reporter.nsPerBlockStep["BM_ReferenceLatticeVerletExponential"];
  const double fastExponential = reporter.nsPerBlockStep["BM_FastLatticeVerletExponential"];
  const double activeExponential = reporter.nsPerBlockStep["BM_FastLatticeVerletExponentialSkipIdle"];
  const double fastState = reporter.nsPerBlockStep["BM_FastLatticeVerletState"];
  const double activeState = reporter.nsPerBlockStep["BM_FastLatticeVerletStateSkipIdle"];
  if (state > 0 && plainExponential > 0)
    std::printf("N_b = %d: velocity Verlet, reference kernel: state law %.1f ns per block per step, exponential law "
                "%.1f ns (%.2fx)\n",
                blocksPerSide, state, plainExponential, state / plainExponential);
  if (fastState > 0 && fastExponential > 0)
    std::printf("N_b = %d: velocity Verlet, fast kernel: state law %.1f ns full sweep, %.1f ns active set; exponential "
                "law %.1f ns, %.1f ns: state/exponential %.2fx (full sweep), %.2fx (active set)\n",
                blocksPerSide, fastState, activeState, fastExponential, activeExponential, fastState / fastExponential,
                activeExponential > 0 ? activeState / activeExponential : 0.0);
  if (fastState > 0 && state > 0)
    std::printf("N_b = %d: state law, reference kernel / fast kernel: %.2fx (full sweep), %.2fx (active set)\n",
                blocksPerSide, state / fastState, activeState > 0 ? state / activeState : 0.0);
  const char* const exponentialRun = "BM_RealisationExponential/iterations:2";
  const char* const stateRun = "BM_RealisationState/iterations:2";
  const char* const stateReferenceRun = "BM_RealisationStateReference/iterations:2";
  if (t.count(exponentialRun) && t.count(stateRun) && t.count(stateReferenceRun))
    std::printf("full realisation, N_b = %d: exponential law %.2f s, state law %.2f s (%.2fx), state law on the "
                "reference kernel %.2f s (%.2fx the fast kernel's) (CPU)\n",
                blocksPerSide, t.at(exponentialRun), t.at(stateRun), t.at(stateRun) / t.at(exponentialRun),
                t.at(stateReferenceRun), t.at(stateReferenceRun) / t.at(stateRun));
  std::printf("kernel version in use: %s\n", kernelIsaName(kernelIsaInUse()));
  const double avx2 = reporter.nsPerBlockStep["BM_FastLatticeVerletAvx2"];
  const double baseline = reporter.nsPerBlockStep["BM_FastLatticeVerletBaseline"];
  if (verlet > 0 && (avx2 > 0 || baseline > 0))
    std::printf("N_b = %d: velocity Verlet full sweep per version: %s %.1f ns, avx2 %.1f ns, baseline %.1f ns "
                "(0: not run or not supported)\n",
                blocksPerSide, kernelIsaName(kernelIsaInUse()), verlet, avx2, baseline);
  if (verlet > 0 && fast > 0)
    std::printf("N_b = %d: velocity Verlet %.1f ns per block per step, %.2fx cheaper per step than fast RK4\n",
                blocksPerSide, verlet, fast / verlet);
  return 0;
}
