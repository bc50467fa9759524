#pragma once
// The property sites of the FEM mesh (cell and bottom-face centres) for the PropertySampler: the
// uniform nx x ny grid as always, or the unequal cells of a mesh graded toward the edges.
#include "gradfric/fem/edge_grading.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/property_sampler.hpp"

namespace gradfric::fem {

class PlateMesh;

// The mesh's axes along x and y from the parameters (no mesh needed).
MeshAxis meshAxisX(const FemParameters& q);
MeshAxis meshAxisY(const FemParameters& q);

// The sampler over these axes: PropertySampler(grading, nx, ny) on a uniform mesh (bit for bit
// what it always was), else normalised over the graded cells, area weighted.
PropertySampler meshSampler(const Grading& grading, const MeshAxis& x, const MeshAxis& y);
PropertySampler meshSampler(const Grading& grading, const PlateMesh& mesh);
PropertySampler meshSampler(const Grading& grading, const FemParameters& q);

// The bottom cells' centres and widths (over L) of the mesh the parameters describe.
SiteGrid meshSiteGrid(const FemParameters& q);

// Refuses a property field out of range at a cell of this mesh (checkPlateFields at the cells the
// run samples: on an edge-graded mesh, not the uniform grid's centres).
void checkMeshFields(const Grading& grading, const FemParameters& q);

}  // namespace gradfric::fem
