#pragma once
// The lattice's stiffnesses and local friction, built from the parameters, the grading and a
// random stream. Blocks are indexed row-major, i = row * N_b + column, the column running along
// x. The stiffnesses are per block column when E varies along x only (the paper's gradings, and
// every E field at 0 or 180 degrees), per block when it varies along y too.
#include "gradfric/core/random_stream.hpp"
#include "gradfric/physics/friction_law.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/sbm/parameters.hpp"

#include <vector>

namespace gradfric::sbm {

// The springs of row r, as pointers indexed by column c (see LatticeStiffness::row).
struct RowStiffness {
  const double* horizontal;    // [N_b - 1] (r, c) - (r, c+1)
  const double* vertical;      // [N_b] (r, c) - (r+1, c); not read for the top row
  const double* diagonal;      // [N_b - 1] (r, c) - (r+1, c+1); not read for the top row
  const double* antiDiagonal;  // [N_b - 1] (r, c+1) - (r+1, c); not read for the top row
  const double* slider;        // [N_b] slider spring of (r, c)
};

struct LatticeStiffness {
  int blocksPerSide = 0;
  double spacing = 0.0;
  bool graded = false;              // false: each kind of spring has one stiffness everywhere
  bool perBlock = false;            // false: per column (every row the same), true: per block
  bool smallStrain = false;         // springs linearised about their rest direction (Parameters)
  // Per column: horizontal [N_b - 1] between columns c and c+1, vertical [N_b] inside column c,
  // diagonal [N_b - 1] both diagonals between columns c and c+1, slider [N_b]; antiDiagonal empty.
  // Per block: row r's springs start at r (N_b - 1) (horizontal, diagonal, antiDiagonal) or r N_b
  // (vertical, slider); the springs to the row above of the top row are zero and never read.
  std::vector<double> horizontal, vertical, diagonal, antiDiagonal, slider;
  double largestAxial() const;
  RowStiffness row(int r) const {
    if (!perBlock) return {horizontal.data(), vertical.data(), diagonal.data(), diagonal.data(), slider.data()};
    const std::size_t inner = std::size_t(r) * (blocksPerSide - 1), all = std::size_t(r) * blocksPerSide;
    return {horizontal.data() + inner, vertical.data() + all, diagonal.data() + inner, antiDiagonal.data() + inner,
            slider.data() + all};
  }
  double sliderAt(int r, int c) const { return row(r).slider[c]; }
};

// E_i = E f(x_i, y_i) at the block centres; axial K_int = 3/4 E_i l_z, diagonal K_int / 2; a spring
// between blocks i and j takes the series (harmonic-mean) stiffness 2 k_i k_j / (k_i + k_j) of its
// two half-springs, and a vertical spring between blocks of the same E takes k itself (the same
// number up to round-off; exact, so that per-block stiffness of an E constant along y is the
// per-column lattice bit for bit). Slider K_s,i = G_i l^2 / l_z. Per block when the E field varies
// along y or when forcePerBlock is set (tests), per column otherwise.
LatticeStiffness buildStiffness(const Parameters& parameters, const Grading& grading, bool forcePerBlock = false);

// Local friction as forces, the per-site parameters of the friction law: static strength
// mu_s,i F_n and kinetic strength mu_k,i F_n [N], stored as one value, one per column or one per
// block (SiteLayout), whichever the scene needs.
struct FrictionField : FrictionSites {
  // Blocks whose draw was repeated (-surface_kind blocks) or whose field value was clipped
  // (cells, gaussian: random_surface.hpp) to keep 0 < mu_k,i <= mu_s,i.
  int redrawnBlocks = 0;
  double staticAt(int row, int column) const { return staticStrength[slot(row, column)]; }
  double kineticAt(int row, int column) const { return kineticStrength[slot(row, column)]; }
};

// Means from the grading, times the random surface (Parameters::surface) averaged over each
// block: realisation key.realisation of seed key.seed, the sweep point's own surface if
// key.sweepIndex > 0. The blocks kind draws per block instead, redrawn until 0 < mu_k,i <= mu_s,i.
// With sigma = 0 nothing is drawn.
FrictionField buildFriction(const Parameters& parameters, const Grading& grading, StreamKey key);

// The property fields of a grading before random dispersion, one value per block column (every
// row of a column is the same): E [Pa], mean mu_s and mu_k. Stored in the results file per point.
struct ColumnProperties {
  std::vector<double> modulus, muStatic, muKinetic;
};
ColumnProperties columnProperties(const Parameters& parameters, const Grading& grading);
// The same per block (row-major, N_b^2 each), with the normal pressure p [Pa]: the property
// fields (-field_*) may vary along y too.
struct BlockProperties {
  std::vector<double> modulus, muStatic, muKinetic, pressure;
};
BlockProperties blockProperties(const Parameters& parameters, const Grading& grading);

// Energies of a lattice state [J]: kinetic, elastic in the internal springs, elastic in the
// slider springs (slider at sliderX, sliderY, the displacement of the slider's end).
struct LatticeEnergy {
  double kinetic = 0.0, internal = 0.0, slider = 0.0;
  double total() const { return kinetic + internal + slider; }
};
LatticeEnergy latticeEnergy(const LatticeStiffness& stiffness, double mass, const double* ux, const double* uy,
                            const double* vx, const double* vy, double sliderX, double sliderY);

// sigma_x / p of every block from its springs (virial stress over the block's volume l^2 l_z,
// positive in tension). ux, uy: displacements [N_b^2].
void longitudinalStress(const LatticeStiffness& stiffness, double thickness, double pressure, const double* ux,
                        const double* uy, double* sigmaXOverP);
// The full in-plane virial stress of one block [Pa]: (sxx, syy, sxy).
void blockStress(const LatticeStiffness& stiffness, double thickness, const double* ux, const double* uy, int row,
                 int column, double stress[3]);

}  // namespace gradfric::sbm
