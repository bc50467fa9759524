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
//
// With a normal-stress memory (docs/flutter.md, "With a normal-stress memory"): the strength is mu
// times a filtered pressure p*, dp*/dt = (|V| + V*) (p - p*) / L, a relaxation time
// T = L / (|V| + V*). About steady sliding p* = p, so |V|'s perturbation drops out and
// p*' = p' / (1 - i omega T), omega = k c_s eta. With the memory K = |k| c_s T >= 0:
//   D(eta) = i s alpha eta^2 (1 - i s K eta) - mu (2 - eta^2 - 2 alpha beta) = 0
// (k > 0: i alpha eta^2 (1 - i K eta) = mu (2 - eta^2 - 2 alpha beta); k < 0 still the conjugate;
// K = 0 is the Coulomb relation, evaluated bit for bit as before). For K > 0:
// - the only real-axis root besides eta = 0 is eta_c^2 = 2 mu (mu - sqrt(mu^2 - 1)) (c_s < c < c_p),
//   reached at K = K_c (memoryCutoff), where the flutter root (continued from the Coulomb one) crosses
//   into the decaying half plane. No root enters from infinity or through eta = 0 or the branch
//   points, so the flutter branch grows for 0 < K < K_c and for no K > K_c (monotone cut-off);
// - the neutral Coulomb root against the sliding (beyond -c_p/c_s) moves into the growing half plane
//   for every K > 0 and every mu > 0, mu <= 1 included: a second growing root near -c_p/c_s, with
//   K Im(eta) (growth rate times T) bounded over K (memoryModeGrowth), -> 0 as K -> 0 and as K -> inf.
//   The problem is well-posed (growth <= x / T for every k) but not stable.
// PETSc-free, no MPI.
#include <complex>
#include <vector>

namespace gradfric {

// c_s / c_p of an isotropic solid, sqrt((1 - 2 nu) / (2 - 2 nu)).
double shearToPressureSpeedRatio(double nu);

// The residual D(eta) above for the wave-number sign kSign (+1: k > 0, -1: k < 0) and the memory
// K = |k| c_s T (0: Coulomb). Throws std::invalid_argument for nu outside (0, 0.5), kSign not +-1
// or K < 0.
std::complex<double> slidingDispersion(std::complex<double> eta, double mu, double nu, int kSign = 1,
                                       double memory = 0.0);

// The number of growing roots (Im(k c) > 1e-9 |k| c_s) by the argument principle on a rectangle
// in the growing half plane (upper for kSign = +1, lower for -1) that encloses every root (its
// size from the large-|eta| asymptote D / eta^2 ~ s c_s/c_p eta; `halfWidth` > 0 overrides it).
// Throws std::runtime_error if the winding is not near an integer (a root on the contour). With the
// memory K, the same rectangle encloses every root (|1 - i K eta| >= 1 there). Roots with
// Im(eta) < 1e-9 count as neutral: the memory's mode against the sliding has Im(eta) ~ K^-3 for
// large K, so counts of it are meaningful up to K ~ 100 only.
int countGrowingSlidingRoots(double mu, double nu, int kSign = 1, double halfWidth = 0.0, double memory = 0.0);

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
// `memory`: K = |k| c_s T (0: Coulomb).
SlidingMode growingSlidingMode(double mu, double nu, double memory = 0.0);
// Every growing root for k > 0, the fastest first: with the memory, the flutter branch
// (direction +1, for K < K_c and mu > 1) and the mode against the sliding (direction -1, K > 0).
std::vector<SlidingMode> growingSlidingModes(double mu, double nu, double memory = 0.0);

// Im(omega) [1/s] = (2 pi / wavelength) c_s Im(eta) of that mode, 0 when there is none; with a
// relaxation time T [s] of the normal-stress memory, at K = (2 pi / wavelength) c_s T.
double slidingGrowthRate(double mu, double nu, double shearSpeed, double wavelength, double relaxationTime = 0.0);

// K_c: the memory K = |k| c_s T above which the flutter branch no longer grows, for mu > 1 (0 for
// mu <= 1), in closed form (the real-axis crossing above). 0.7098 at mu 1.2, 1.0751 at mu 1.4 (nu 1/3).
// Meant where the Coulomb root exists (nu >= 0.07 up to mu 2, docs/flutter.md).
double memoryCutoff(double mu, double nu);
// 2 pi c_s T / K_c [m]: the shortest wavelength that still grows, which a mesh must resolve (0 for
// mu <= 1). shearSpeed [m/s], relaxationTime T [s].
double memoryCutoffWavelength(double mu, double nu, double shearSpeed, double relaxationTime);
// The largest K Im(eta) over K in (0, K_c) of the flutter branch: its growth rate is at most this / T
// at any wavelength (0 for mu <= 1 or without a Coulomb root).
double memoryFlutterGrowth(double mu, double nu);
// The largest K Im(eta) over all K > 0 of the other growing root the memory introduces, the mode
// against the sliding near -c_p/c_s (0 for mu <= 0): its growth rate is at most this / T. Followed by
// continuation in K from the neutral Coulomb root beyond -c_p/c_s, for K up to 100 (beyond, the
// value falls as 1/K^2). 0.0430 at mu 1.2, 0.0537 at mu 1.4 (nu 1/3).
double memoryModeGrowth(double mu, double nu);

}  // namespace gradfric
