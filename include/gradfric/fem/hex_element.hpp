#pragma once
// Pointwise physics of the FEM, pure arithmetic, no PETSc: the trilinear (Q1) hexahedron for a
// rectangular box cell, small-strain isotropic elasticity, optionally enriched with the nine
// incompatible (Wilson-Taylor) modes, condensed into the same 24x24 matrix (incompatible_hex.hpp).
//
// Node numbering inside the element: a = i + 2 j + 4 k with (i, j, k) in {0, 1}^3 the corner at
// (i hx, j hy, k hz). Element dofs: 3 a + c, c = x, y, z.
#include <array>
#include <vector>

namespace gradfric::fem {

struct Lame {
  double lambda;
  double mu;
};
// lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = G = E / (2 (1 + nu)).
Lame lameFromYoung(double youngsModulus, double poissonRatio);

// The hexahedron of the plate: plain trilinear (q1), or trilinear with the incompatible bending
// modes condensed out once at set-up (q1i, Abaqus's C3D8I; same cost per step).
enum class ElementType { Trilinear, IncompatibleModes };
const char* elementTypeName(ElementType type);  // "q1" or "q1i"

// Element stiffness of one box cell for E = 1 (every cell of the plate is the same box, so the
// cells differ only by their E factor). Integrated with 2x2x2 Gauss points: exact for a box.
struct BoxElement {
  double hx = 0, hy = 0, hz = 0;
  double poissonRatio = 0;
  ElementType type = ElementType::Trilinear;
  std::array<double, 24 * 24> stiffness{};  // row-major, [3a+c][3b+d], for E = 1
  double volume() const { return hx * hy * hz; }
};
BoxElement makeBoxElement(double hx, double hy, double hz, double poissonRatio,
                          ElementType type = ElementType::Trilinear);

// Stiffness (E = 1, row-major) of a box cell over 8 nodal shape functions and, with bubbles, the
// 3 incompatible modes 4 s (1 - s) of the reference coordinate s in [0, 1] along x, y and z: dof
// 3 f + c for shape function f (nodes 0..7, then modes along x, y, z) and component c.
// 24x24 without bubbles, 33x33 with; 2x2x2 Gauss points, exact for a box either way.
std::vector<double> boxStiffness(double hx, double hy, double hz, double poissonRatio, bool withBubbles);

// Largest eigenvalue of the symmetric 24x24 matrix (cyclic Jacobi).
double largestEigenvalue(const std::array<double, 24 * 24>& matrix);

// Squared highest angular frequency of one element with lumped mass rho V / 8 per node:
// lambda_max(M_e^-1 K_e). The global highest frequency is bounded by the largest element one.
double elementMaxFrequencySquared(const BoxElement& element, double youngsModulus, double density);

// Stable step of the central-difference (velocity Verlet) scheme for the highest angular
// frequency omega and damping ratio xi at that frequency: (2 / omega)(sqrt(1 + xi^2) - xi).
double centralDifferenceStableStep(double omegaSquared, double dampingRatio);

// Cell-average stress (Voigt order xx, yy, zz, yz, xz, xy) of one box cell with element
// displacements ue (24 values, element numbering), for E and nu. The same for q1i: the
// incompatible modes' gradients average to zero over a box.
std::array<double, 6> cellAverageStress(const BoxElement& element, double youngsModulus, const double* ue);

}  // namespace gradfric::fem
