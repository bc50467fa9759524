#pragma once
// The flutter of sliding, simulated: an elastic strip slides steadily on a rigid flat at constant
// Coulomb friction mu, and a small perturbation of one wavelength lambda either grows at the rate
// the dispersion relation predicts (mu > 1) or does not (mu <= 1). docs/flutter.md, "The
// simulation that verifies it".
//
// The problem is the steady sliding linearised about its uniform state, so the base state drops
// out and only the perturbation is simulated: plane strain, periodic along the sliding direction x
// over one wavelength, the flat at z = 0 keeping the base in contact (u_z = 0, its reaction R_z is
// the normal force) and the sliding base resisted by F_x = -mu R_z (the friction of a base sliding
// in +x, perturbed). Bilinear squares, lumped mass, central differences; the top is free, deep
// enough that the mode (which decays into the body over about a wavelength) does not feel it.
// The discrete system is invariant under shifts along x, so its Fourier modes evolve apart: the
// amplitude at the seeded wavenumber is that mode's alone, whatever the grid-scale modes do.
// With `memory` T > 0 the friction is mu times the relaxed reaction R*, dR*/dt = (R - R*) / T per
// base node (the normal-stress memory linearised about steady sliding: T = L / (|V| + V*)), R* = R
// of the seed at t = 0, advanced over each step exactly for R linear in time over the step.
// An independent check of the relation: it uses neither the relation nor its roots. Units: c_s,
// lambda and the density are 1. Pure arithmetic, no PETSc.
#include <array>
#include <vector>

namespace gradfric {

struct SlidingStripSettings {
  double friction = 1.2;               // mu, constant
  double poisson = 1.0 / 3.0;          // nu (plane strain)
  int elementsPerWavelength = 32;      // along x and z
  double depth = 4.0;                  // of the strip [lambda]
  double duration = 10.0;              // simulated [lambda / c_s]
  double courant = 0.3;                // time step over h / c_p
  double memory = 0;  // relaxation time T of the normal-stress memory [lambda / c_s]; 0: none
};

struct SlidingStripHistory {
  std::vector<double> time;       // [lambda / c_s], one sample per step
  std::vector<double> amplitude;  // |Fourier amplitude| of the base's u_x at the wavenumber 2 pi / lambda
  std::vector<double> phase;      // its argument, continuous in time [rad]
  double step = 0;                // the time step [lambda / c_s]
};

// Seeds u_x = eps cos(k x) exp(-k z) at rest and integrates for settings.duration.
SlidingStripHistory simulateSlidingStrip(const SlidingStripSettings& settings);

// The least-squares slope of log(amplitude) over time in [from, to]: the growth rate [c_s / lambda].
double fittedGrowthRate(const SlidingStripHistory& history, double from, double to);
// The wave's phase speed from the slope of the phase over [from, to] [c_s]: exp(i k (x - c t)) at
// k = 2 pi / lambda turns its amplitude's phase at -k c. Positive: it travels with the sliding.
double fittedPhaseSpeed(const SlidingStripHistory& history, double from, double to);

// Two waves at the seeded wavenumber at once (the memory's flutter branch and its mode against the
// sliding, which beat in the amplitude): the complex amplitude a(t) = amplitude e^{i phase} fitted
// over [from, to] as A1 e^{s1 t} + A2 e^{s2 t} by linear prediction (Prony) with the lag `lag`
// [lambda / c_s]: least squares over every sample of a(t + 2 lag) = c1 a(t + lag) + c0 a(t), then
// e^{s lag} are the roots of z^2 - c1 z - c0. growth = Re s [c_s / lambda], speed = -Im s / k [c_s]
// (unambiguous for |speed| < 1 / (2 lag)). Sorted by speed, the faster along the sliding first.
struct FittedWave {
  double growthRate = 0;
  double phaseSpeed = 0;
};
std::array<FittedWave, 2> fittedWavePair(const SlidingStripHistory& history, double from, double to,
                                         double lag = 0.1);

}  // namespace gradfric
