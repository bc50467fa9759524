#pragma once
// In-plane meshes graded toward the plate's edges (docs/fem.md, "Meshes graded toward the edges").
//
// A monotone map x(s) of the uniform coordinate s = i/n of the DMPlex box, the same along x and
// y (z stays uniform). It is made of one piece per grading band (x = k L/10): the `bands` outer
// bands of each side are refined, the cells shrinking smoothly from the interior size h_i to
// h_i/ratio at the edge; the bands inside keep uniform cells of size h_i. Each piece holds a
// fixed number of cells per unit of the mesh (cellsPerUnit: n must be a multiple of it), so
//  - every band boundary is a node, and so a face of the cells;
//  - the map does not depend on n: doubling n gives the nested (systematically refined) mesh;
//  - ratio 1 is the identity (no map at all: today's uniform mesh, exactly).
// Within an edge band the cell size follows h(t) = a + (c - a) t^alpha over the band's share t of
// the cells (a, c its sizes at the outer and inner end: geometric from h_i/ratio to h_i across
// the refined bands), alpha set so that the band's cells fill it exactly. PETSc-free.
#include <string>
#include <vector>

namespace gradfric::fem {

// -fem_edge_ratio and -fem_edge_band: interior element size / edge element size (1: uniform) and
// the width of the refined band at each edge [m] (a multiple of L/10; <= 0: L/10).
struct EdgeGrading {
  double ratio = 1.0;
  double band = 0.0;
  bool uniform() const { return ratio == 1.0; }
};

// The grading's allowed values, for the refusals (parameters.cpp) and the tests.
constexpr double kEdgeRatioMin = 1.1, kEdgeRatioMax = 16.0;
constexpr int kGradingBands = 10;  // the paper's stepwise gradings: bands of L/10
constexpr int kEdgeBandsMax = 4;   // refined bands per side (the middle two bands stay uniform)

class EdgeMap {
public:
  // ratio in [kEdgeRatioMin, kEdgeRatioMax] or 1; refinedBands in 1..kEdgeBandsMax. Throws
  // std::invalid_argument outside.
  EdgeMap(double ratio, int refinedBands);
  bool uniform() const { return ratio_ == 1.0; }
  double ratio() const { return ratio_; }
  int refinedBands() const { return refinedBands_; }
  // n must be a multiple of this (1 when uniform).
  int cellsPerUnit() const { return unit_; }
  // Cells in grading band k (0..9) for n cells along the axis.
  int cellsInBand(int band, int n) const;
  // The n + 1 node coordinates on [0, length]; uniform: i * (length / n). n a multiple of
  // cellsPerUnit() (else std::invalid_argument).
  std::vector<double> nodes(int n, double length) const;

private:
  double ratio_;
  int refinedBands_ = 1;
  int unit_ = 1;
  std::vector<int> bandCells_;  // per band k, per unit
  std::vector<double> alpha_;   // per refined band (outer first): the profile's exponent
};

// How many grading bands the band width covers (width <= 0: 1); 0 when it is not a multiple of
// length/10 within 1e-9.
int refinedBandsOf(double width, double length);

// The cells along one axis of the plate's mesh.
struct MeshAxis {
  std::vector<double> nodes;      // n + 1 coordinates
  std::vector<int> widthClass;    // per cell: its class (cells of one width share one; mirror cells too)
  std::vector<double> classWidth; // per class: the width (uniform: length / n, exactly)
  int cells() const { return static_cast<int>(widthClass.size()); }
  double width(int cell) const { return classWidth[widthClass[cell]]; }
  // The cell whose span holds x (clamped to the axis).
  int cellAt(double x) const;
  // The node nearest x.
  int nearestNode(double x) const;
  // The cell's centre over length (uniform: (i + 0.5) / n, as the uniform code has always sampled).
  double unitCentre(int cell) const;
  bool uniform() const { return classWidth.size() == 1; }
  double length() const { return nodes.back(); }
};

MeshAxis makeMeshAxis(const EdgeGrading& grading, int n, double length);

// One line for the run's header: edge and interior element sizes and the cells per band.
std::string describeEdgeGrading(const EdgeGrading& grading, int n, double length);

}  // namespace gradfric::fem
