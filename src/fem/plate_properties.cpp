#include "gradfric/fem/plate_properties.hpp"

#include "gradfric/fem/mesh_sites.hpp"

namespace gradfric::fem {

// One sampler for every property; the rules are the ones each layer used before (bit for bit).
PlateProperties::PlateProperties(const PlateMesh& mesh, const Plate& plate, const Grading& grading) : plate_(plate) {
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
  for (const OwnedVertex& v : mesh.ownedVertices()) {
    if (!(area[v.block] > 0)) continue;
    const double factor = graded[v.block] / area[v.block];  // area-weighted face factor
    bottom_.push_back({v.block, v.x, v.y, area[v.block], plate.muStatic * factor,
                       plate.muKinetic * (gradedKinetic[v.block] / area[v.block])});
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
