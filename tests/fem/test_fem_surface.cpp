// The random surface in the FEM (plate_properties.hpp, docs/surface.md, "In the FEM"): each
// bottom node takes the surface averaged over its tributary rectangle. Checked against the
// rectangles computed here from the node lines (also on an edge-graded mesh), against the spring
// blocks at coincident positions bit for bit, and on 2 ranks against 1 bit for bit.
#include "gradfric/core/gather.hpp"
#include "gradfric/fem/mesh_sites.hpp"
#include "gradfric/fem/plate_model.hpp"
#include "gradfric/fem/stable_step.hpp"
#include "gradfric/sbm/lattice.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

SurfaceSettings dispersed(SurfaceKind kind, double correlationLength) {
  SurfaceSettings s;
  s.sigmaStatic = 0.1;
  s.sigmaKinetic = 0.15;
  s.correlationLength = correlationLength;
  s.kind = kind;
  s.seed = 7;
  return s;
}

// Every bottom node of the model, gathered on every rank: (i, j) -> (mu_s, mu_k).
std::map<std::pair<int, int>, std::pair<double, double>> bottomCoefficients(const PlateModel& model) {
  std::vector<double> local;
  for (const BottomNode& b : model.properties().bottomNodes())
    local.insert(local.end(), {double(model.mesh().axisX().nearestNode(b.x)), double(model.mesh().axisY().nearestNode(b.y)),
                               b.muStatic, b.muKinetic});
  const std::vector<double> shared = gatherOnAll(model.comm(), local);
  std::map<std::pair<int, int>, std::pair<double, double>> nodes;
  for (std::size_t k = 0; k + 3 < shared.size(); k += 4)
    nodes[{int(shared[k]), int(shared[k + 1])}] = {shared[k + 2], shared[k + 3]};
  return nodes;
}

}  // namespace

TEST(FemSurface, EachNodeTakesItsTributaryRectanglesAverage) {
  // An edge-graded mesh (unequal neighbours) and the Gaussian field (every rectangle its own value).
  FemParameters q = test::coarse(24, 24, 2);
  q.edge.ratio = 4.0;
  const double L = q.plate.length;
  q.surface = dispersed(SurfaceKind::Gaussian, L / 10);
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  const RandomSurface surface(q.surface, L, 0, 0);
  const std::vector<double>& xs = model.mesh().axisX().nodes;
  const std::vector<double>& ys = model.mesh().axisY().nodes;
  const auto span = [](const std::vector<double>& n, int k) {
    const double lo = k == 0 ? 0.0 : 0.5 * (n[k - 1] + n[k]);
    const double hi = k + 1 == int(n.size()) ? n.back() : 0.5 * (n[k] + n[k + 1]);
    return std::make_pair(lo, hi);
  };
  ASSERT_NE(xs[1] - xs[0], xs[13] - xs[12]);  // graded: the rectangles differ
  for (const BottomNode& b : model.properties().bottomNodes()) {
    const int i = model.mesh().axisX().nearestNode(b.x), j = model.mesh().axisY().nearestNode(b.y);
    const auto [x0, x1] = span(xs, i);
    const auto [y0, y1] = span(ys, j);
    const SurfaceCoefficients c =
        surfaceCoefficients(q.plate.muStatic, q.plate.muKinetic, 1.0, q.surface, surface.averageOver({x0, x1, y0, y1}));
    EXPECT_EQ(b.muStatic, c.muStatic) << "node " << i << ", " << j;
    EXPECT_EQ(b.muKinetic, c.muKinetic) << "node " << i << ", " << j;
    EXPECT_LE(b.muKinetic, b.muStatic);
  }
  // The dispersion is there: the coefficients are not the means.
  const auto nodes = bottomCoefficients(model);
  ASSERT_EQ(nodes.size(), 25u * 25u);
  double lowest = 1e300, highest = 0;
  for (const auto& [ij, mu] : nodes) {
    lowest = std::min(lowest, mu.first);
    highest = std::max(highest, mu.first);
  }
  EXPECT_LT(lowest, 0.97 * q.plate.muStatic);
  EXPECT_GT(highest, 1.03 * q.plate.muStatic);
}

namespace {

// l_c = L/N: SBM block (r, c) is one cell; the FEM mesh 2N x 2N puts node (2c + 1, 2r + 1) at the
// block's centre, its tributary rectangle inside that cell. One realisation of one seed in both:
// the FEM sweep's realisation r and the spring blocks' realisation r under common streams.
void expectNodesEqualBlocks(std::uint32_t realisation) {
  constexpr int kBlocks = 8;
  FemParameters q = test::coarse(2 * kBlocks, 2 * kBlocks, 2);
  const double L = q.plate.length;
  q.surface = dispersed(SurfaceKind::Cells, L / kBlocks);
  q.surfaceRealisation = realisation;
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());

  sbm::Parameters p;
  p.plate = q.plate;
  p.blocksPerSide = kBlocks;
  p.surface = q.surface;
  const sbm::FrictionField blocks = sbm::buildFriction(p, Grading{}, StreamKey{q.surface.seed, 0, realisation});
  const double normal = p.normalForcePerBlock();

  const auto nodes = bottomCoefficients(model);
  ASSERT_EQ(nodes.size(), std::size_t(2 * kBlocks + 1) * (2 * kBlocks + 1));
  int compared = 0, distinct = 0;
  for (int r = 0; r < kBlocks; ++r)
    for (int c = 0; c < kBlocks; ++c) {
      const auto& [muS, muK] = nodes.at({2 * c + 1, 2 * r + 1});
      EXPECT_EQ(muS * normal, blocks.staticAt(r, c)) << "block " << r << ", " << c;
      EXPECT_EQ(muK * normal, blocks.kineticAt(r, c)) << "block " << r << ", " << c;
      distinct += muS != nodes.at({1, 1}).first;
      ++compared;
    }
  EXPECT_EQ(compared, kBlocks * kBlocks);
  EXPECT_GT(distinct, kBlocks * kBlocks / 2);  // a field, not one value
}

}  // namespace

TEST(FemSurface, NodesAtTheBlockCentresEqualTheSpringBlocksBitForBit) { expectNodesEqualBlocks(0); }

TEST(FemSurface, AnEnsemblesRealisationIsTheSpringBlocksRealisation) {
  expectNodesEqualBlocks(3);
  // ... and another surface than realisation 0.
  FemParameters q = test::coarse(8, 8, 2);
  q.surface = dispersed(SurfaceKind::Cells, q.plate.length / 4);
  const PlateModel first(PETSC_COMM_WORLD, q, test::noGrading());
  q.surfaceRealisation = 3;
  const PlateModel fourth(PETSC_COMM_WORLD, q, test::noGrading());
  EXPECT_NE(bottomCoefficients(first), bottomCoefficients(fourth));
}

TEST(FemSurface, TheSameCoefficientsOnAnyNumberOfRanks) {
  // The world's model (2 ranks under ctest) against one rank's, for both kinds of field.
  for (const SurfaceKind kind : {SurfaceKind::Cells, SurfaceKind::Gaussian}) {
    FemParameters q = test::coarse(8, 8, 2);
    q.surface = dispersed(kind, q.plate.length / 6);  // cells not aligned with the elements
    PlateModel world(PETSC_COMM_WORLD, q, test::noGrading());
    PlateModel alone(PETSC_COMM_SELF, q, test::noGrading());
    const auto spread = bottomCoefficients(world), single = bottomCoefficients(alone);
    ASSERT_EQ(spread.size(), 81u);
    EXPECT_TRUE(spread == single) << surfaceKindName(kind);
  }
}

TEST(FemSurface, NoDispersionLeavesTheMeans) {
  // sigma 0 (the default): the coefficients are the grading's, bit for bit, whatever l_c or seed.
  FemParameters q = test::coarse(8, 8, 2);
  FemParameters other = q;
  other.surface.seed = 99;
  other.surface.correlationLength = q.plate.length / 3;
  PlateModel a(PETSC_COMM_WORLD, q, test::linear(GradedProperty::Friction, 0.2));
  PlateModel b(PETSC_COMM_WORLD, other, test::linear(GradedProperty::Friction, 0.2));
  EXPECT_TRUE(bottomCoefficients(a) == bottomCoefficients(b));
  EXPECT_FALSE(q.surface.dispersed());
}

TEST(FemSurface, TheLargestStepAccountsForTheLargestNodeMuS) {
  // Friction's coupling sqrt(1 + mu^2) with the surface's largest node mu_s: a shorter largest
  // step than the flat plate's, the same stable step (the springs alone).
  const FemParameters flat = test::coarse(8, 8, 2);
  FemParameters rough = flat;
  rough.surface = dispersed(SurfaceKind::Cells, flat.plate.length / 6);
  rough.surface.sigmaStatic = 0.3;
  EXPECT_EQ(stableTimeStep(rough, Grading{}), stableTimeStep(flat, Grading{}));
  EXPECT_LT(largestTimeStep(rough, Grading{}), largestTimeStep(flat, Grading{}));
  // A bound: a flat plate whose mu_s is the largest node's allows at least the rough plate's step.
  PlateModel model(PETSC_COMM_WORLD, rough, test::noGrading());
  double largest = 0;
  for (const auto& [ij, mu] : bottomCoefficients(model)) largest = std::max(largest, mu.first);
  ASSERT_GT(largest, flat.plate.muStatic);
  Plate atLargest = flat.plate;
  atLargest.muStatic = largest;
  EXPECT_GE(largestTimeStep(test::coarse(8, 8, 2, atLargest), Grading{}), largestTimeStep(rough, Grading{}));
}
