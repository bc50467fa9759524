#pragma once
// The plane-strain "flutter" of steady sliding with constant Coulomb friction (docs/flutter.md).
// An elastic half-space z > 0 (shear speed c_s, Poisson ratio nu) slides in +x on a rigid flat
// z = 0, contact kept (u_z = 0), shear traction mu times the pressure against the sliding (the
// slip rate keeps its sign under small perturbations, so the law stays linear). Perturbations
// phi, psi ~ exp(i k (x - c t) - |k| alpha z) and exp(... - |k| beta z), eta = c / c_s,
//   alpha = sqrt(1 - eta^2 c_s^2 / c_p^2),  beta = sqrt(1 - eta^2),  c_p^2 / c_s^2 = (2 - 2 nu) / (1 - 2 nu),
// give, with s = sign(k),
//   D(eta) = i s alpha eta^2 - mu (2 - eta^2 - 2 alpha beta) = 0.
// Growth is Im(k c) > 0, i.e. Im(eta) > 0 for k > 0 and Im(eta) < 0 for k < 0. Branches: the
// decaying ones, Re(alpha), Re(beta) > 0, off the real axis; on the real axis (|eta| > 1 or
// > c_p/c_s) the limit from the growing side (radiation into the body). The k < 0 relation is the
// conjugate, D_-(eta) = conj(D_+(conj(eta))): its roots are the conjugates of the k > 0 ones, the
// same waves, so one side suffices and the phase velocity c_s Re(eta) gives the direction.
// eta = 0 is always a (double) root: a rigid shift, not a mode; the count divides it out.
// Results: neutral at mu = 1 with eta = sqrt(2) (2 - eta^2 = 0, beta = -i) for every nu; one
// growing root for mu > 1, travelling with the sliding, none for mu <= 1; the growth rate
// k c_s Im(eta) is proportional to k (Hadamard ill-posed). At small nu (below ~0.07) the root
// returns to the real axis beyond c_p at a mu <= 2 (1.78 at nu = 0.05): no growing root there.
// PETSc-free, no MPI.
#include <complex>

namespace gradfric {

// c_s / c_p of an isotropic solid, sqrt((1 - 2 nu) / (2 - 2 nu)).
double shearToPressureSpeedRatio(double nu);

// The residual D(eta) above for the wave-number sign kSign (+1: k > 0, -1: k < 0). Throws
// std::invalid_argument for nu outside (0, 0.5) or kSign not +-1.
std::complex<double> slidingDispersion(std::complex<double> eta, double mu, double nu, int kSign = 1);

// The number of growing roots (Im(k c) > 1e-9 |k| c_s) by the argument principle on a rectangle
// in the growing half plane (upper for kSign = +1, lower for -1) that encloses every root (its
// size from the large-|eta| asymptote D / eta^2 ~ s c_s/c_p eta; `halfWidth` > 0 overrides it).
// Throws std::runtime_error if the winding is not near an integer (a root on the contour).
int countGrowingSlidingRoots(double mu, double nu, int kSign = 1, double halfWidth = 0.0);

// The growing mode for k > 0 (the k < 0 one is its conjugate): growing = false (eta = 0) when
// there is none. direction = +1 when the phase travels with the sliding (Re(eta) > 0), -1 against.
struct SlidingMode {
  bool growing = false;
  std::complex<double> eta{0.0, 0.0};  // c / c_s
  int direction = 0;
};
// Found without a starting guess: the argument principle brackets the root in a box of 1e-4
// (bisecting the enclosing rectangle), Newton polishes it. With several roots, the fastest.
// Throws std::runtime_error if the bracketing fails (never seen for mu <= 2, nu in [0.05, 0.49]).
SlidingMode growingSlidingMode(double mu, double nu);

// Im(omega) [1/s] = (2 pi / wavelength) c_s Im(eta) of that mode, 0 when there is none.
double slidingGrowthRate(double mu, double nu, double shearSpeed, double wavelength);

}  // namespace gradfric
