#pragma once
// The property sites of the FEM mesh (cell and bottom-face centres) for the PropertySampler: the
// uniform nx x ny grid as always, or the unequal cells of a mesh graded toward the edges.
#include "gradfric/fem/edge_grading.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/property_sampler.hpp"
#include "gradfric/physics/random_surface.hpp"

#include <vector>

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

// The random surface over the bottom nodes: node (i, j) takes the surface averaged over its
// tributary rectangle, in x from the midpoint to the previous node to the midpoint to the next
// (the plate's edge at the first and last node), the same in y, on the mesh's actual (possibly
// edge-graded) node lines. The rectangles tile the plate, and a rectangle's bits depend on it
// alone (random_surface.hpp): the same on any number of ranks.
// The n + 2 edges of an axis's tributary intervals: node k spans [edges[k], edges[k + 1]].
std::vector<double> tributaryEdges(const MeshAxis& axis);
// The nodes i0..i1 x j0..j1 (inclusive) of the surface (dispersed, its seed and
// l_c set), row-major with i fastest, as one lattice (the cost of one query per row, not per node).
std::vector<SurfaceDeviations> tributarySurface(const RandomSurface& surface, const MeshAxis& x, const MeshAxis& y,
                                                int i0, int i1, int j0, int j1);
// The FEM's surface: a realisation of the settings' seed, the same at every sweep point (stream
// 0): realisation r is the spring blocks' realisation r of the same seed under
// -ensemble_common_streams.
RandomSurface femSurface(const SurfaceSettings& settings, double plateLength, std::uint32_t realisation);

// Refuses a property field out of range at a cell of this mesh (checkPlateFields at the cells the
// run samples: on an edge-graded mesh, not the uniform grid's centres).
void checkMeshFields(const Grading& grading, const FemParameters& q);

}  // namespace gradfric::fem
