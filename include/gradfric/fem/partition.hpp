#pragma once
// Partitioning the serial box mesh: METIS k-way on the cell graph (fed to DMPlex through the
// shell partitioner), or one of PETSc's own (ptscotch, simple).
#include <petscdmplex.h>

#include <string>
#include <vector>

namespace gradfric::fem {

// Owner part of every cell of `serial` (a mesh held whole on rank 0 of its communicator), for
// nparts = the communicator size. Collective; the vector is filled on rank 0 only.
std::vector<PetscInt> partitionCells(DM serial, const std::string& type);

// Interior faces of `serial` whose two cells have different owners (rank 0; 0 elsewhere).
PetscInt countCutFaces(DM serial, const std::vector<PetscInt>& owner);

// Distributes `serial` by the named partitioner; returns the distributed mesh (a new DM) or
// nullptr when nothing was distributed (one rank). Collective.
DM distributeMesh(DM serial, const std::string& type);

}  // namespace gradfric::fem
