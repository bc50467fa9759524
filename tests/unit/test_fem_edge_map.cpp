// The coordinate map of a mesh graded toward the edges (fem/edge_grading.hpp), without PETSc:
// ratio 1 is the uniform mesh bit for bit; the graded map nests under doubling, puts every
// grading band's boundary on a node and is symmetric. The mesh built on it: tests/fem/test_fem_graded_mesh.cpp.
#include "gradfric/fem/edge_grading.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

using namespace gradfric::fem;

namespace {
constexpr double kL = 5e-3;
}  // namespace

TEST(FemEdgeMap, RatioOneIsTheUniformMeshExactly) {
  const MeshAxis axis = makeMeshAxis(EdgeGrading{}, 37, kL);
  ASSERT_TRUE(axis.uniform());
  ASSERT_EQ(axis.nodes.size(), 38u);
  for (int i = 0; i <= 37; ++i) EXPECT_EQ(axis.nodes[i], i * (kL / 37));
  EXPECT_EQ(axis.classWidth[0], kL / 37);
  for (int i = 0; i < 37; ++i) EXPECT_EQ(axis.unitCentre(i), (i + 0.5) / 37);
}

TEST(FemEdgeMap, DoublingNestsBandsLieOnFacesAndTheMapIsSymmetric) {
  for (const double ratio : {1.5, 2.0, 4.0, 8.0, 16.0})
    for (int bands = 1; bands <= kEdgeBandsMax; ++bands) {
      const EdgeMap map(ratio, bands);
      const int unit = map.cellsPerUnit();
      SCOPED_TRACE("ratio " + std::to_string(ratio) + ", " + std::to_string(bands) + " band(s), unit " +
                   std::to_string(unit));
      const std::vector<double> coarse = map.nodes(2 * unit, kL), fine = map.nodes(4 * unit, kL);
      for (int i = 0; i <= 2 * unit; ++i) EXPECT_EQ(fine[2 * i], coarse[i]) << "node " << i;  // nested, bit for bit
      for (int i = 0; i < 4 * unit; ++i) ASSERT_GT(fine[i + 1], fine[i]) << "monotone at " << i;
      for (int i = 0; i <= 2 * unit; ++i) EXPECT_EQ(fine[4 * unit - i], kL - fine[i]) << "symmetric at " << i;
      int node = 0;  // every band boundary is a node
      for (int k = 0; k < kGradingBands; ++k) {
        EXPECT_NEAR(fine[node], k * kL / kGradingBands, 1e-15 * kL) << "band " << k;
        node += map.cellsInBand(k, 4 * unit);
      }
      EXPECT_EQ(node, 4 * unit);
      // Refined bands: the cell size grows smoothly from about h_i / ratio at the edge to h_i.
      const MeshAxis axis = makeMeshAxis(EdgeGrading{ratio, bands * kL / kGradingBands}, 8 * unit, kL);
      const double interior = axis.classWidth.back(), edge = axis.width(0);
      EXPECT_NEAR(interior / edge, ratio, 0.15 * ratio);
      EXPECT_LE(interior / edge, ratio * (1 + 1e-12));
      for (int i = 0; i + 1 < axis.cells(); ++i) {
        const double step = axis.width(i + 1) / axis.width(i);
        EXPECT_LT(std::max(step, 1 / step), 1.6) << "between cells " << i << " and " << i + 1;
      }
      for (int i = 0; i < axis.cells(); ++i)  // the class widths are the cells' own
        EXPECT_NEAR(axis.width(i), axis.nodes[i + 1] - axis.nodes[i], 1e-12 * kL);
    }
  EXPECT_THROW(EdgeMap(1.05, 1), std::invalid_argument);
  EXPECT_THROW(EdgeMap(4.0, 5), std::invalid_argument);
  EXPECT_THROW(EdgeMap(4.0, 1).nodes(13, kL), std::invalid_argument);
}
