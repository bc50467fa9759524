#include "gradfric/fem/plate_properties.hpp"

#include "gradfric/fem/mesh_sites.hpp"

#include <algorithm>

namespace gradfric::fem {

// One sampler for every property; the rules are the ones each layer used before (bit for bit).
PlateProperties::PlateProperties(const PlateMesh& mesh, const Plate& plate, const Grading& grading,
                                 const SurfaceSettings& surface, std::uint32_t realisation)
    : plate_(plate), surface_(surface) {
  const double length = mesh.size().length;
  const PropertySampler sampler = meshSampler(grading, mesh);
  cellModulus_.resize(mesh.localCells());
  for (PetscInt c = 0; c < mesh.localCells(); ++c) {
    const std::array<double, 3>& centre = mesh.cellCentres()[c];
    cellModulus_[c] = plate.youngsModulus * sampler.modulus(centre[0] / length, centre[1] / length);
  }
  // The bottom faces: mu_k has its own sum only when a field gives it its own factor.
  const std::vector<double> area = mesh.sumOverFaces(FaceSet::Bottom);
  const std::vector<double> graded = mesh.sumOverFaces(
      FaceSet::Bottom, [&](double x, double y) { return sampler.muStatic(x / length, y / length); });
  const bool ownKinetic = grading.fields && grading.fields->muKinetic != grading.fields->muStatic;
  const std::vector<double> gradedKinetic =
      ownKinetic ? mesh.sumOverFaces(FaceSet::Bottom,
                                     [&](double x, double y) { return sampler.muKinetic(x / length, y / length); })
                 : graded;
  // The random surface on top: one lattice of tributary rectangles over this rank's span of
  // bottom nodes (a node's bits depend on its rectangle alone). Without dispersion nothing is drawn.
  const MeshAxis& axisX = mesh.axisX();
  const MeshAxis& axisY = mesh.axisY();
  int i0 = axisX.cells(), i1 = 0, j0 = axisY.cells(), j1 = 0;
  for (const OwnedVertex& v : mesh.ownedVertices())
    if (area[v.block] > 0) {
      const int i = axisX.nearestNode(v.x), j = axisY.nearestNode(v.y);
      i0 = std::min(i0, i);
      i1 = std::max(i1, i);
      j0 = std::min(j0, j);
      j1 = std::max(j1, j);
    }
  const bool dispersed = surface.dispersed() && i0 <= i1;
  const std::vector<SurfaceDeviations> z =
      dispersed ? tributarySurface(femSurface(surface, length, realisation), axisX, axisY, i0, i1, j0, j1)
                : std::vector<SurfaceDeviations>{};
  for (const OwnedVertex& v : mesh.ownedVertices()) {
    if (!(area[v.block] > 0)) continue;
    const double factor = graded[v.block] / area[v.block];  // area-weighted face factor
    double muStatic = plate.muStatic * factor;
    double muKinetic = plate.muKinetic * (gradedKinetic[v.block] / area[v.block]);
    if (dispersed) {
      const std::size_t node = std::size_t(axisY.nearestNode(v.y) - j0) * (i1 - i0 + 1) + (axisX.nearestNode(v.x) - i0);
      const SurfaceCoefficients c = surfaceCoefficients(muStatic, muKinetic, 1.0, surface, z[node]);
      muStatic = c.muStatic;
      muKinetic = c.muKinetic;
    }
    bottom_.push_back({v.block, v.x, v.y, area[v.block], muStatic, muKinetic});
  }
  // The top faces: a static pressure field (-field_p_*) weighs each face's share.
  const bool shaped = grading.fields && grading.fields->pressure;
  const std::vector<double> topArea = mesh.sumOverFaces(FaceSet::Top);
  const std::vector<double> load =
      shaped ? mesh.sumOverFaces(FaceSet::Top,
                                 [&](double x, double y) { return sampler.pressure(x / length, y / length); })
             : topArea;
  for (const OwnedVertex& v : mesh.ownedVertices())
    if (load[v.block] > 0) top_.push_back({v.block, topArea[v.block], load[v.block]});
}

}  // namespace gradfric::fem
