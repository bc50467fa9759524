#include "gradfric/fem/mesh_sites.hpp"

#include "gradfric/fem/plate_mesh.hpp"
#include "gradfric/physics/field_options.hpp"

namespace gradfric::fem {

MeshAxis meshAxisX(const FemParameters& q) { return makeMeshAxis(q.edge, q.nx, q.plate.length); }
MeshAxis meshAxisY(const FemParameters& q) { return makeMeshAxis(q.edge, q.ny, q.plate.length); }

namespace {

SiteGrid siteGrid(const MeshAxis& x, const MeshAxis& y) {
  SiteGrid grid;
  const auto fill = [](const MeshAxis& axis, std::vector<double>* centre, std::vector<double>* width) {
    for (int i = 0; i < axis.cells(); ++i) {
      centre->push_back(axis.unitCentre(i));
      width->push_back(axis.width(i) / axis.length());
    }
  };
  fill(x, &grid.u, &grid.du);
  fill(y, &grid.v, &grid.dv);
  return grid;
}

}  // namespace

PropertySampler meshSampler(const Grading& grading, const MeshAxis& x, const MeshAxis& y) {
  if (x.uniform() && y.uniform()) return PropertySampler(grading, x.cells(), y.cells());
  return PropertySampler(grading, siteGrid(x, y));
}

PropertySampler meshSampler(const Grading& grading, const PlateMesh& mesh) {
  return meshSampler(grading, mesh.axisX(), mesh.axisY());
}

PropertySampler meshSampler(const Grading& grading, const FemParameters& q) {
  return meshSampler(grading, meshAxisX(q), meshAxisY(q));
}

SiteGrid meshSiteGrid(const FemParameters& q) { return siteGrid(meshAxisX(q), meshAxisY(q)); }

std::vector<double> tributaryEdges(const MeshAxis& axis) {
  const std::vector<double>& n = axis.nodes;
  std::vector<double> edges = {n.front()};
  for (std::size_t k = 1; k < n.size(); ++k) edges.push_back(0.5 * (n[k - 1] + n[k]));
  edges.push_back(n.back());
  return edges;
}

std::vector<SurfaceDeviations> tributarySurface(const RandomSurface& surface, const MeshAxis& x, const MeshAxis& y,
                                                int i0, int i1, int j0, int j1) {
  const std::vector<double> xAll = tributaryEdges(x), yAll = tributaryEdges(y);
  const std::vector<double> xEdges(xAll.begin() + i0, xAll.begin() + i1 + 2);
  const std::vector<double> yEdges(yAll.begin() + j0, yAll.begin() + j1 + 2);
  return surface.averageOverLattice(xEdges, yEdges);
}

RandomSurface femSurface(const SurfaceSettings& settings, double plateLength, std::uint32_t realisation) {
  return RandomSurface(settings, plateLength, realisation, 0);
}

void checkMeshFields(const Grading& grading, const FemParameters& q) {
  if (!grading.fields) return;
  checkPlateFields(grading, q.plate, meshSampler(grading, q), meshSiteGrid(q));
}

}  // namespace gradfric::fem
