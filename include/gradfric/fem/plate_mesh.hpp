#pragma once
// The plate's mesh: a DMPlex box of nx x ny x nz hexahedra over L x L x H, distributed by the
// chosen partitioner, with the state layout of the explicit scheme (Q1 fields "displacement" and
// "velocity", per vertex [u_x u_y u_z v_x v_y v_z]). Geometry only: no material, no loads. With an
// edge grading the box's x and y coordinates go through its map (edge_grading.hpp) before the
// distribution: the cells stay axis-aligned boxes, of a few distinct shapes.
#include "gradfric/core/petsc_handle.hpp"
#include "gradfric/fem/edge_grading.hpp"
#include "gradfric/fem/ordered_assembly.hpp"

#include <petscdmplex.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace gradfric::fem {

struct MeshSize {
  int nx = 1, ny = 1, nz = 1;
  double length = 1, thickness = 1;  // L (x and y), H (z) [m]
  EdgeGrading edge;                  // in-plane cells graded toward the edges (ratio 1: uniform)
};

// An owned vertex of the state vector: its block (6 values) and its position.
struct OwnedVertex {
  PetscInt block;
  double x, y, z;
};

enum class FaceSet { Bottom = 1, Top = 2 };  // DMPlex "Face Sets" values of the z- and z+ faces

class PlateMesh {
public:
  PlateMesh(MPI_Comm comm, const MeshSize& size, const std::string& partitioner);
  PlateMesh(const PlateMesh&) = delete;
  PlateMesh& operator=(const PlateMesh&) = delete;

  MPI_Comm comm() const { return comm_; }
  DM dm() const { return dm_; }  // the state DM
  const MeshSize& size() const { return size_; }
  // The interior element sizes (every cell's on a uniform mesh: L/nx, L/ny, H/nz exactly).
  double hx() const { return axisX_.classWidth.back(); }
  double hy() const { return axisY_.classWidth.back(); }
  double hz() const { return size_.thickness / size_.nz; }
  bool graded() const { return !size_.edge.uniform(); }
  const MeshAxis& axisX() const { return axisX_; }
  const MeshAxis& axisY() const { return axisY_; }
  // The distinct cell boxes (hx, hy, hz; one on a uniform mesh) and each local cell's box.
  const std::vector<std::array<double, 3>>& shapes() const { return shapes_; }
  const std::vector<int>& cellShape() const { return cellShape_; }
  const std::array<double, 3>& cellSize(PetscInt cell) const { return shapes_[cellShape_[cell]]; }
  double cellVolume(PetscInt cell) const {
    const std::array<double, 3>& h = cellSize(cell);
    return h[0] * h[1] * h[2];
  }
  PetscInt localCells() const { return numCells_; }
  PetscInt globalCells() const { return globalCells_; }
  PetscInt ownedBlocks() const { return ownedBlocks_; }
  PetscInt firstVertex() const { return vStart_; }

  // Per local cell, in element node order (a = i + 2 j + 4 k): vertex points minus firstVertex(),
  // offsets into the local state vector; and the cell centres.
  const std::vector<PetscInt>& cellVertices() const { return cellVertices_; }
  const std::vector<PetscInt>& cellStateOffsets() const { return cellStateOff_; }
  const std::vector<std::array<double, 3>>& cellCentres() const { return cellCentre_; }
  const std::vector<OwnedVertex>& ownedVertices() const { return owned_; }
  // The sums at the vertices shared with other ranks, redone in the global cell order.
  const OrderedAssembly& orderedAssembly() const { return *ordered_; }

  // Per owned block, the sum over the cells around the vertex of cellShare[cell] (each cell adds
  // its value to its 8 vertices), assembled over ranks.
  std::vector<double> sumOverCells(const std::vector<double>& cellShare) const;
  // Per owned block, the sum over the faces of `set` around the vertex of a quarter of the face's
  // area times weight(x, y of the face centre) (weight 1 if empty), assembled over ranks.
  std::vector<double> sumOverFaces(FaceSet set, const std::function<double(double, double)>& weight = {}) const;

private:
  void build(const std::string& partitioner);
  void mapCoordinates(DM serial) const;
  void viewAndCheck() const;  // -dm_view, -dm_plex_check_all
  void buildCells();
  void buildShapes();
  void buildOwnedVertices();
  // Per owned block, the sum over the cells around the vertex of share(cell, a) for the cell's
  // corner a on it (in the global cell order, whatever the partition).
  std::vector<double> assemble(const std::function<double(PetscInt, int)>& share) const;

  MPI_Comm comm_;
  MeshSize size_;
  MeshAxis axisX_, axisY_;
  OwnedDM dm_;
  PetscInt numCells_ = 0, globalCells_ = 0, vStart_ = 0, vEnd_ = 0, ownedBlocks_ = 0;
  std::vector<PetscInt> cellVertices_, cellStateOff_;
  std::vector<std::array<double, 3>> cellCentre_;
  std::vector<std::array<double, 3>> shapes_;
  std::vector<int> cellShape_;
  std::vector<long> cellGlobal_;  // per local cell: its index in the serial mesh, x fastest
  std::vector<OwnedVertex> owned_;
  std::vector<PetscInt> blockOfVertex_;  // per local vertex (minus vStart): its owned block or -1
  std::unique_ptr<OrderedAssembly> ordered_;
};

// Reads -dm_view and -dm_plex_check_all before any work (PlateMesh applies them once built), so
// that checkUnusedOptions does not report them.
void readPlateMeshOptions();

}  // namespace gradfric::fem
