#pragma once
// The .xmf beside the FEM field snapshots (PETSc's HDF5 VIZ layout), so that ParaView reads every
// field with its real shape: vectors as vectors, cell_stress as a symmetric tensor (stored in
// XDMF's Tensor6 order xx, xy, xz, yy, yz, zz), and fields of other widths (bottom_contact) as one
// named scalar per component. Serial: rank 0 calls it once the fields file is closed.
#include <string>

namespace gradfric::fem {

// Adds units, description and components attributes to the field datasets of fieldsFile (in
// room reserved first, io::changeHdf5File) and writes xmfPath describing them, naming the fields
// file `heavy` (its final name, beside the .xmf). Throws on failure (io::Hdf5Error naming the
// file, std::runtime_error).
void describeFieldsAndWriteXdmf(const std::string& fieldsFile, const std::string& heavy, const std::string& xmfPath);

}  // namespace gradfric::fem
