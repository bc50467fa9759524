#pragma once
// One random surface shared by both models: the local disorder of the static and kinetic friction
// coefficients (and optionally of Young's modulus) as a field over the plate with its own
// correlation length l_c, independent of the lattice or mesh that samples it. A spring block takes
// the field averaged over its own area, a FEM node the average over its tributary area.
// The realisation depends only on (seed, realisation, position): it is counter-based
// (RandomStream keyed by (seed, realisation), no sweep index), so it is the same surface on any
// lattice, any mesh, any number of ranks and at every sweep point. PETSc-free (docs/surface.md).
//
// Kinds of field (standard-normal deviations z_s, z_k, z_E; one RandomStream purpose each):
//  - Cells: cell (i, j) = [i l_c, (i+1) l_c) x [j l_c, (j+1) l_c), anchored at the plate's corner
//    (0, 0), holds independent standard normals, item = (uint32 i) << 32 | (uint32 j); cells beyond
//    the plate exist too. Covariance: the probability that two points share a cell.
//  - Gaussian: z(x) = sum_n w(x - x_n) xi_n over white noise xi_n on the grid x_n = n l_c / 4
//    anchored at (0, 0), w(x, y) = g(x) g(y), g(s) = exp(-2 s^2 / l_c^2) / sqrt(S), truncated at
//    |s| <= 2 l_c per axis; S = sum_{|n| <= 8} g(n l_c / 4)^2 makes the variance 1 at the grid
//    nodes. Covariance exp(-r^2 / l_c^2); the variance lies within 1e-7 of 1 anywhere (6.1e-8 at
//    worst, the truncated tail), and the grid's own periodicity is below 1e-16 (Poisson summation).
//
// Averages over a rectangle are exact for the field as defined (no quadrature):
//  - Cells: edges are quantised to multiples of 2^-32 l_c (a shift below 2.4e-10 l_c, which puts a
//    lattice's edges computed as x = L c / N exactly on the cells' boundaries when they are
//    aligned), so every overlap is an exact binary number; overlap products and their products
//    with z are split without rounding (two-product by fma) into an ExactSum. The integral is
//    therefore exact and additive: the integral of a block equals the sum of its sub-blocks'
//    integrals bit for bit (integralOver). The average is that integral rounded once, divided by
//    the block's area (exact for aligned dyadic blocks). Consequences: a block inside one cell
//    returns the cell's value exactly, and on a lattice aligned with the cells a coarse block of
//    2 x 2 cells equals ExactSum of its four fine blocks (one cell each) / 4 bitwise.
//  - Gaussian: separable; each 1D integral of g over [x0, x1] through erf (erfc in the tails).
//    Rounding only: averages agree with sums of sub-block averages to about 1e-13.
#include "gradfric/core/exact_sum.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace gradfric {

// Blocks: the spring-block lattice's independent draw per block, l_c = the block (the model
// before this surface existed; kept so that its files can be extended). Not a field: RandomSurface
// refuses it, the lattice draws it itself (sbm/lattice.hpp).
enum class SurfaceKind { Cells, Gaussian, Blocks };

struct SurfaceSettings {
  double sigmaStatic = 0.0;        // relative dispersion of mu_s, >= 0
  double sigmaKinetic = 0.0;       // relative dispersion of mu_k, >= 0
  double sigmaModulus = 0.0;       // relative dispersion of E, >= 0 (0: no modulus disorder, z_E = 0)
  double correlationLength = 0.0;  // l_c [m] > 0; the paper's block is defaultCorrelationLength(L)
  SurfaceKind kind = SurfaceKind::Cells;
  std::uint64_t seed = 0;
  bool dispersed() const { return sigmaStatic > 0.0 || sigmaKinetic > 0.0 || sigmaModulus > 0.0; }
};

// -surface_kind's names, in SurfaceKind's order.
const char* surfaceKindName(SurfaceKind kind);

// The effects line both models print for a dispersed field (not the Blocks kind): "random
// surface: sigma_s = ..., sigma_k = ..., <kind> of l_c = ... m (<l_c / spacing> <sites>)"; each
// model adds how its sites sample the field.
std::string describeSurfaceField(const SurfaceSettings& settings, double siteSpacing, const std::string& sites);

// L / 120: the paper's block, so the paper's scenes (N_b = 120) keep their statistics.
inline double defaultCorrelationLength(double plateLength) { return plateLength / 120.0; }

// Standard-normal deviations of the three properties (averaged over a region).
struct SurfaceDeviations {
  double zStatic = 0.0, zKinetic = 0.0, zModulus = 0.0;
  bool operator==(const SurfaceDeviations& o) const {
    return zStatic == o.zStatic && zKinetic == o.zKinetic && zModulus == o.zModulus;
  }
};

// A block: [x0, x1] x [y0, y1] in metres, plate corner at (0, 0); x0 < x1 and y0 < y1.
struct SurfaceRectangle {
  double x0, x1, y0, y1;
};

class RandomSurface {
public:
  // Throws std::invalid_argument on bad settings: non-finite or non-positive l_c or plate length,
  // negative or non-finite dispersions, more than 2^16 correlation lengths per plate side, the
  // Blocks kind. `stream` is 0 for the one surface of a campaign; a sweep point's index gives each
  // point its own surface (-ensemble_common_streams false).
  RandomSurface(const SurfaceSettings& settings, double plateLength, std::uint32_t realisation,
                std::uint32_t stream = 0);

  // The deviations averaged exactly over one rectangle (std::invalid_argument if it is empty,
  // non-finite or beyond 2^20 l_c of the corner).
  SurfaceDeviations averageOver(const SurfaceRectangle& rectangle) const;
  // Every block [xEdges[a], xEdges[a+1]] x [yEdges[b], yEdges[b+1]] at once (edges strictly
  // increasing), row-major: element b * (xEdges.size() - 1) + a. The same bits as averageOver of
  // each block, in any order and for any sub-lattice; cheaper, as the noise and the 1D integrals
  // are computed once per lattice.
  std::vector<SurfaceDeviations> averageOverLattice(const std::vector<double>& xEdges,
                                                    const std::vector<double>& yEdges) const;
  // The field at a point (cells: the cell holding it).
  SurfaceDeviations valueAt(double x, double y) const;
  // Cells only: the exact integrals of z_s, z_k, z_E over a rectangle in units of l_c^2, additive
  // bit for bit over any partition whose edges are on the 2^-32 l_c grid (std::logic_error for
  // the Gaussian kind).
  std::array<ExactSum, 3> integralOver(const SurfaceRectangle& rectangle) const;

  const SurfaceSettings& settings() const { return settings_; }

private:
  SurfaceSettings settings_;
  double plateLength_;
  std::uint32_t realisation_;
  std::uint32_t stream_;
};

// Coefficients of a region from its deviations (a property of the field, never a redraw):
//   mu_s = max(mean_s (1 + sigma_s z_s), f mean_s)
//   mu_k = min(max(mean_k (1 + sigma_k z_k), f mean_k), mu_s)
//   E    = max(mean_E (1 + sigma_E z_E), f mean_E)
// with the floor f = kSurfaceFloorFraction, so 0 < mu_k <= mu_s at any dispersion, and the
// identity at zero dispersion. Means must be positive and finite with mean_k <= mean_s
// (std::invalid_argument otherwise).
constexpr double kSurfaceFloorFraction = 0.01;
struct SurfaceCoefficients {
  double muStatic, muKinetic, youngsModulus;
  bool clipped = false;  // a bound (the floor, or mu_k <= mu_s) replaced the linear value
};
SurfaceCoefficients surfaceCoefficients(double meanStatic, double meanKinetic, double meanModulus,
                                        const SurfaceSettings& settings, const SurfaceDeviations& z);

}  // namespace gradfric
