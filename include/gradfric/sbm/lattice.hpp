#pragma once
// The lattice's stiffnesses and local friction, built from the parameters, the grading and a
// random stream. Blocks are indexed row-major, i = row * N_b + column, the column running along
// the grading axis x. Grading is along x only, so every stiffness depends on columns alone.
#include "gradfric/core/random_stream.hpp"
#include "gradfric/physics/friction_law.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/sbm/parameters.hpp"

#include <vector>

namespace gradfric::sbm {

struct LatticeStiffness {
  int blocksPerSide = 0;
  double spacing = 0.0;
  bool graded = false;              // false: each kind of spring has one stiffness everywhere
  bool smallStrain = false;         // springs linearised about their rest direction (Parameters)
  std::vector<double> horizontal;   // [N_b - 1] axial spring between columns c and c+1 [N/m]
  std::vector<double> vertical;     // [N_b] axial springs inside column c
  std::vector<double> diagonal;     // [N_b - 1] both diagonals between columns c and c+1
  std::vector<double> slider;       // [N_b] slider spring of a block in column c
  double largestAxial() const;
};

// Axial K_int = 3/4 E l_z, diagonal K_int / 2; a spring between blocks of different E takes the
// series (harmonic-mean) stiffness 2 k_i k_j / (k_i + k_j). Slider K_s = G l^2 / l_z.
LatticeStiffness buildStiffness(const Parameters& parameters, const Grading& grading);

// Local friction as forces, the per-site parameters of the friction law: static strength
// mu_s,i F_n and kinetic strength mu_k,i F_n [N], stored as one value, one per column or one per
// block (SiteLayout), whichever the scene needs.
struct FrictionField : FrictionSites {
  int redrawnBlocks = 0;  // blocks whose draw was repeated to keep 0 < mu_k,i <= mu_s,i
  double staticAt(int row, int column) const { return staticStrength[slot(row, column)]; }
  double kineticAt(int row, int column) const { return kineticStrength[slot(row, column)]; }
};

// Means from the grading; Gaussian dispersion (relative sigma) drawn from the stream, redrawn
// until 0 < mu_k,i <= mu_s,i. With sigma = 0 nothing is drawn.
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
