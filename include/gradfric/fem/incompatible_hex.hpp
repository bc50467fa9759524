#pragma once
// The incompatible-mode hexahedron (Wilson, Taylor; Abaqus's C3D8I): the trilinear displacement
// plus the nine modes alpha_{m,c} 4 s_m (1 - s_m) (bubble along axis m, component c). They add
// the quadratic bending displacement the trilinear field lacks, so a slender element bends
// without the parasitic shear that locks Q1. Their gradients average to zero over the cell, so
// the patch test holds (on a box Taylor's centroid correction changes nothing). The modes are
// internal to the cell: minimising the energy over them for given nodal displacements gives the
// statically condensed stiffness K = K_uu - K_ua K_aa^-1 K_au, computed once at set-up, after
// which the element costs the same as Q1.
#include <array>
#include <vector>

namespace gradfric::fem {

// Condenses the 33x33 stiffness of boxStiffness(..., true) (nodal dofs 0..23, modes 24..32) to
// the 24x24 nodal stiffness (row-major, exactly symmetric).
std::array<double, 24 * 24> condenseIncompatibleModes(const std::vector<double>& stiffnessWithModes);

// The mode amplitudes (9 values, dof 3 m + c) that minimise the energy for the nodal
// displacements ue (24 values): K_aa alpha = -K_au ue.
std::array<double, 9> incompatibleModeAmplitudes(const std::vector<double>& stiffnessWithModes, const double* ue);

}  // namespace gradfric::fem
