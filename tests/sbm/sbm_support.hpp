#pragma once
// Paper parameters with the derived defaults the driver would compute, for tests.
#include "gradfric/sbm/model.hpp"
#include "gradfric/sbm/parameters.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace gradfric::sbm::testing {

inline double naturalFrequency(const Parameters& p) { return std::sqrt(p.axialStiffness(p.plate.youngsModulus) / p.blockMass()); }

// dtSafety > 0: that fraction of the stability limit; 0: the shipped default step.
inline Parameters paperParameters(int blocksPerSide, double sigma, const Grading& grading = {}, double dtSafety = 0.0,
                                  double dampingFactor = 0.1) {
  Parameters p;
  p.blocksPerSide = blocksPerSide;
  p.surface.sigmaStatic = p.surface.sigmaKinetic = sigma;
  p.surface.correlationLength = p.spacing();  // one cell per block: the tests' small plates keep their disorder
  p.damping = dampingFactor * naturalFrequency(p);
  p.timeStep = dtSafety > 0 ? dtSafety * stableTimeStep(p, grading) : defaultTimeStep(p, grading);
  return p;
}

// A grading of one property by a profile in `bands` bands (the tests' plates).
inline Grading grading(GradingProfile profile, GradedProperty property, double delta, int bands = 10) {
  Grading g;
  g.profile = profile;
  g.property = property;
  g.delta = delta;
  g.bands = bands;
  return g;
}

// A triangular grading of property in 4 bands: the kernels' equivalence tests' plate.
inline Grading triangular(GradedProperty property, double delta) {
  return grading(GradingProfile::Triangular, property, delta, 4);
}

// The moment-balance pressure kept its balances through a run: the normal force p L^2 and the
// moment H F at every step.
inline void expectPressureBalances(const Result& r) {
  const PressureCouplingRecord& c = r.pressureCoupling;
  ASSERT_TRUE(c.active);
  EXPECT_GT(c.updates, r.steps / 2);
  EXPECT_LT(c.largestForceError, 1e-13);
  EXPECT_LT(c.largestMomentError, 1e-12);
}

inline Request defaultRequest(const Parameters& p) {
  Request q;
  const double load = p.loadingTime();
  q.measurement.historyInterval = 0.0;
  q.measurement.kineticDelay = 0.5 * load;
  q.measurement.kineticWidth = load;
  q.measurement.peakHold = 0.25 * load;
  q.maxTime = 20 * load;
  return q;
}

// One realisation (stream {11, 0, 3}) on both kernels under the moment-balance pressure (edge
// length H), each checked to keep its balances.
struct KernelPair {
  Result fast, reference;
};
inline KernelPair bothKernelsUnderMomentBalance(Parameters p, const Grading& g) {
  p.pressureResponse.source = PressureResponseSource::MomentBalance;
  p.pressureResponse.edgeLength = p.plate.thickness;
  const Request q = defaultRequest(p);
  KernelPair r{simulate(p, g, q, {11, 0, 3}, Kernel::Fast), simulate(p, g, q, {11, 0, 3}, Kernel::Reference)};
  for (const Result* each : {&r.fast, &r.reference}) expectPressureBalances(*each);
  return r;
}

struct Sample {
  double mean = 0, standardError = 0;
};

inline Sample staticFrictionSample(const Parameters& p, const Grading& g, int realisations, std::uint32_t sweepIndex) {
  Request q = defaultRequest(p);
  q.measurement.kinetic = false;
  q.measurement.firstSlipMap = false;
  std::vector<double> values;
  for (int r = 0; r < realisations; ++r)
    values.push_back(simulate(p, g, q, StreamKey{42, sweepIndex, std::uint32_t(r)}).friction.muStatic);
  Sample s;
  for (double v : values) s.mean += v / values.size();
  double var = 0;
  for (double v : values) var += (v - s.mean) * (v - s.mean) / (values.size() - 1);
  s.standardError = std::sqrt(var / values.size());
  return s;
}

}  // namespace gradfric::sbm::testing
