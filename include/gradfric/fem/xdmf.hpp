#pragma once
// The .xmf beside the FEM field snapshots (PETSc's HDF5 VIZ layout), so that ParaView reads every
// field with its real shape: vectors as vectors, cell_stress as a symmetric tensor (stored in
// XDMF's Tensor6 order xx, xy, xz, yy, yz, zz), and fields of other widths (bottom_contact) as one
// named scalar per component. Serial: rank 0 calls it once the fields file is closed.
#include <string>

namespace gradfric::fem {

// Adds units, description and components attributes to the field datasets of fieldsPath and
// writes xmfPath describing them. Throws std::runtime_error on failure.
void describeFieldsAndWriteXdmf(const std::string& fieldsPath, const std::string& xmfPath);

}  // namespace gradfric::fem
