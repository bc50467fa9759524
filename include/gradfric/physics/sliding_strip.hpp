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
// An independent check of the relation: it uses neither the relation nor its roots. Units: c_s,
// lambda and the density are 1. Pure arithmetic, no PETSc.
#include <vector>

namespace gradfric {

struct SlidingStripSettings {
  double friction = 1.2;               // mu, constant
  double poisson = 1.0 / 3.0;          // nu (plane strain)
  int elementsPerWavelength = 32;      // along x and z
  double depth = 4.0;                  // of the strip [lambda]
  double duration = 10.0;              // simulated [lambda / c_s]
  double courant = 0.3;                // time step over h / c_p
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

}  // namespace gradfric
