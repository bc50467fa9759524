#include "gradfric/fem/plate_mesh.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/partition.hpp"
#include "gradfric/fem/state_view.hpp"

#include <petscfe.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gradfric::fem {

namespace {

struct FE {
  PetscFE fe = nullptr;
  ~FE() { PetscFEDestroy(&fe); }
};

void createQ1(MPI_Comm comm, const char* name, PetscFE* fe) {
  GF_CALL(PetscFECreateLagrange(comm, 3, 3, PETSC_FALSE, 1, 1, fe));
  GF_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(*fe), name));
}

}  // namespace

PlateMesh::PlateMesh(MPI_Comm comm, const MeshSize& size, const std::string& partitioner)
    : comm_(comm),
      size_(size),
      axisX_(makeMeshAxis(size.edge, size.nx, size.length)),
      axisY_(makeMeshAxis(size.edge, size.ny, size.length)) {
  build(partitioner);
  buildCells();
  buildOwnedVertices();
  ordered_ = std::make_unique<OrderedAssembly>(dm_, size_.nx, size_.ny, vStart_, vEnd_, cellVertices_, cellGlobal_,
                                               blockOfVertex_);
}

void PlateMesh::build(const std::string& partitioner) {
  const PetscInt faces[3] = {size_.nx, size_.ny, size_.nz};
  const PetscReal lower[3] = {0, 0, 0};
  const PetscReal upper[3] = {size_.length, size_.length, size_.thickness};
  OwnedDM serial;
  GF_CALL(DMPlexCreateBoxMesh(comm_, 3, PETSC_FALSE, faces, lower, upper, nullptr, PETSC_TRUE, serial.out()));
  if (graded()) mapCoordinates(serial);
  DM distributed = distributeMesh(serial, partitioner);
  if (distributed) {
    dm_ = OwnedDM(distributed);
  } else {
    dm_ = std::move(serial);
  }
  GF_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(dm_.get()), "plate"));
  FE feU, feV;
  createQ1(comm_, "displacement", &feU.fe);
  createQ1(comm_, "velocity", &feV.fe);
  GF_CALL(DMSetField(dm_, 0, nullptr, reinterpret_cast<PetscObject>(feU.fe)));
  GF_CALL(DMSetField(dm_, 1, nullptr, reinterpret_cast<PetscObject>(feV.fe)));
  GF_CALL(DMCreateDS(dm_));
  viewAndCheck();
}

// PETSc's mesh diagnostics on the mesh as the run uses it (box, edge map, partition): the box is
// not built through DMSetFromOptions, which would distribute it by its own partitioner and
// renumber it, so these two options are applied here.
void PlateMesh::viewAndCheck() const {
  GF_CALL(DMViewFromOptions(dm_, nullptr, "-dm_view"));
  PetscBool check = PETSC_FALSE;
  GF_CALL(PetscOptionsGetBool(nullptr, nullptr, "-dm_plex_check_all", &check, nullptr));
  if (check) GF_CALL(DMPlexCheck(dm_));
}

void readPlateMeshOptions() {
  PetscBool given = PETSC_FALSE;  // read here: not reported unused before the mesh exists
  GF_CALL(PetscOptionsHasName(nullptr, nullptr, "-dm_view", &given));
  GF_CALL(PetscOptionsHasName(nullptr, nullptr, "-dm_plex_check_all", &given));
}

// The box's vertex at x = i L/nx (and y) moves to the map's node i: the serial mesh, before the
// distribution, so every rank sees the mapped coordinates (and the partition is the uniform one's).
void PlateMesh::mapCoordinates(DM serial) const {
  Vec coords = nullptr;
  GF_CALL(DMGetCoordinatesLocal(serial, &coords));
  OwnedVec mapped;
  GF_CALL(VecDuplicate(coords, mapped.out()));
  GF_CALL(VecCopy(coords, mapped));
  PetscInt n = 0;
  GF_CALL(VecGetLocalSize(mapped, &n));
  PetscScalar* x = nullptr;
  GF_CALL(VecGetArray(mapped, &x));
  const auto node = [](const MeshAxis& axis, double v) {
    return axis.nodes[std::lround(v / axis.length() * axis.cells())];
  };
  for (PetscInt i = 0; i < n; i += 3) {
    x[i] = node(axisX_, x[i]);
    x[i + 1] = node(axisY_, x[i + 1]);
  }
  GF_CALL(VecRestoreArray(mapped, &x));
  GF_CALL(DMSetCoordinatesLocal(serial, mapped));
}

// Every cell is an axis-aligned box: its vertices are put in element order by their position
// relative to the centre.
void PlateMesh::buildCells() {
  PetscInt cStart = 0, cEnd = 0;
  GF_CALL(DMPlexGetHeightStratum(dm_, 0, &cStart, &cEnd));
  GF_CALL(DMPlexGetDepthStratum(dm_, 0, &vStart_, &vEnd_));
  numCells_ = cEnd - cStart;
  PetscInt n = numCells_;
  GF_CALL_MPI(MPI_Allreduce(&n, &globalCells_, 1, MPIU_INT, MPI_SUM, comm_));

  Vec coords = nullptr;
  PetscSection coordSection = nullptr, section = nullptr;
  GF_CALL(DMGetCoordinatesLocal(dm_, &coords));
  GF_CALL(DMGetCoordinateSection(dm_, &coordSection));
  GF_CALL(DMGetLocalSection(dm_, &section));
  const PetscScalar* x = nullptr;
  GF_CALL(VecGetArrayRead(coords, &x));
  cellVertices_.assign(8 * numCells_, 0);
  cellStateOff_.assign(8 * numCells_, 0);
  cellCentre_.assign(numCells_, {0, 0, 0});
  for (PetscInt c = cStart; c < cEnd; ++c) {
    PetscInt np = 0;
    PetscInt* pts = nullptr;
    GF_CALL(DMPlexGetTransitiveClosure(dm_, c, PETSC_TRUE, &np, &pts));
    PetscInt verts[8];
    int nv = 0;
    double centre[3] = {0, 0, 0};
    for (PetscInt i = 0; i < np; ++i) {
      const PetscInt p = pts[2 * i];
      if (p < vStart_ || p >= vEnd_) continue;
      if (nv < 8) verts[nv] = p;
      ++nv;
      PetscInt off = 0;
      GF_CALL(PetscSectionGetOffset(coordSection, p, &off));
      for (int d = 0; d < 3; ++d) centre[d] += x[off + d] / 8.0;
    }
    GF_CALL(DMPlexRestoreTransitiveClosure(dm_, c, PETSC_TRUE, &np, &pts));
    if (nv != 8) throw std::runtime_error("plate mesh: a cell without 8 vertices");
    const PetscInt cell = c - cStart;
    bool seen[8] = {};
    for (int k = 0; k < 8; ++k) {
      PetscInt off = 0;
      GF_CALL(PetscSectionGetOffset(coordSection, verts[k], &off));
      const int a = (x[off] > centre[0] ? 1 : 0) + (x[off + 1] > centre[1] ? 2 : 0) + (x[off + 2] > centre[2] ? 4 : 0);
      if (seen[a]) throw std::runtime_error("plate mesh: a cell is not an axis-aligned box");
      seen[a] = true;
      cellVertices_[8 * cell + a] = verts[k] - vStart_;
      PetscInt soff = 0, uoff = 0, voff = 0;  // StateView's constant offsets are the section's
      GF_CALL(PetscSectionGetOffset(section, verts[k], &soff));
      GF_CALL(PetscSectionGetFieldOffset(section, verts[k], 0, &uoff));
      GF_CALL(PetscSectionGetFieldOffset(section, verts[k], 1, &voff));
      if (uoff != soff + StateLayout::kDisplacement || voff != soff + StateLayout::kVelocity)
        throw std::runtime_error("plate mesh: unexpected state layout");
      cellStateOff_[8 * cell + a] = soff;
    }
    cellCentre_[cell] = {centre[0], centre[1], centre[2]};
  }
  GF_CALL(VecRestoreArrayRead(coords, &x));
  buildShapes();
}

// The cell's place in the serial mesh (x fastest), from its centre; its box from the width
// classes of its column and row.
void PlateMesh::buildShapes() {
  const int classesY = static_cast<int>(axisY_.classWidth.size());
  for (std::size_t cx = 0; cx < axisX_.classWidth.size(); ++cx)
    for (int cy = 0; cy < classesY; ++cy) shapes_.push_back({axisX_.classWidth[cx], axisY_.classWidth[cy], hz()});
  cellShape_.resize(numCells_);
  cellGlobal_.resize(numCells_);
  for (PetscInt c = 0; c < numCells_; ++c) {
    const std::array<double, 3>& centre = cellCentre_[c];
    const int i = axisX_.cellAt(centre[0]), j = axisY_.cellAt(centre[1]);
    const long k = std::lround(centre[2] / hz() - 0.5);
    cellShape_[c] = axisX_.widthClass[i] * classesY + axisY_.widthClass[j];
    cellGlobal_[c] = (k * size_.ny + j) * size_.nx + i;
  }
}

void PlateMesh::buildOwnedVertices() {
  PetscSection gsection = nullptr, coordSection = nullptr;
  GF_CALL(DMGetGlobalSection(dm_, &gsection));
  GF_CALL(DMGetCoordinateSection(dm_, &coordSection));
  Vec coords = nullptr;
  GF_CALL(DMGetCoordinatesLocal(dm_, &coords));
  OwnedVec global;
  GF_CALL(DMCreateGlobalVector(dm_, global.out()));
  PetscInt localSize = 0, rStart = 0, rEnd = 0;
  GF_CALL(VecGetLocalSize(global, &localSize));
  GF_CALL(VecGetOwnershipRange(global, &rStart, &rEnd));
  ownedBlocks_ = localSize / StateLayout::kBlock;
  const PetscScalar* x = nullptr;
  GF_CALL(VecGetArrayRead(coords, &x));
  blockOfVertex_.assign(vEnd_ - vStart_, -1);
  for (PetscInt p = vStart_; p < vEnd_; ++p) {
    PetscInt goff = 0;
    GF_CALL(PetscSectionGetOffset(gsection, p, &goff));
    if (goff < 0) continue;  // not owned
    blockOfVertex_[p - vStart_] = (goff - rStart) / StateLayout::kBlock;
    PetscInt off = 0;
    GF_CALL(PetscSectionGetOffset(coordSection, p, &off));
    owned_.push_back({(goff - rStart) / StateLayout::kBlock, x[off], x[off + 1], x[off + 2]});
  }
  GF_CALL(VecRestoreArrayRead(coords, &x));
}

std::vector<double> PlateMesh::assemble(const std::function<double(PetscInt, int)>& share) const {
  OwnedVec local, global;
  GF_CALL(DMCreateLocalVector(dm_, local.out()));
  GF_CALL(VecZeroEntries(local));
  PetscScalar* f = nullptr;
  GF_CALL(VecGetArray(local, &f));
  for (PetscInt c = 0; c < numCells_; ++c)
    for (int a = 0; a < 8; ++a) f[cellStateOff_[8 * c + a]] += share(c, a);
  GF_CALL(VecRestoreArray(local, &f));
  GF_CALL(DMCreateGlobalVector(dm_, global.out()));
  GF_CALL(VecZeroEntries(global));
  GF_CALL(DMLocalToGlobal(dm_, local, ADD_VALUES, global));
  PetscScalar* g = nullptr;
  GF_CALL(VecGetArray(global, &g));
  ordered_->redo(
      1, [&](PetscInt c, double* values) {
        for (int a = 0; a < 8; ++a) values[a] = share(c, a);
      },
      g, StateLayout::kBlock, 0);
  std::vector<double> sums(ownedBlocks_);
  const StateView<PetscScalar> state(g);
  for (PetscInt b = 0; b < ownedBlocks_; ++b) sums[b] = state.displacement(b)[0];
  GF_CALL(VecRestoreArray(global, &g));
  return sums;
}

std::vector<double> PlateMesh::sumOverCells(const std::vector<double>& cellShare) const {
  return assemble([&](PetscInt c, int) { return cellShare[c]; });
}

// A face of the set is a cell's bottom (corners a < 4) or top (a >= 4) in the bottom or top
// layer; its centre has the cell centre's x and y.
std::vector<double> PlateMesh::sumOverFaces(FaceSet set, const std::function<double(double, double)>& weight) const {
  const bool top = set == FaceSet::Top;
  const double layerZ = top ? size_.thickness - 0.5 * hz() : 0.5 * hz();
  std::vector<double> faceShare(numCells_, 0.0);
  for (PetscInt c = 0; c < numCells_; ++c) {
    const std::array<double, 3>& centre = cellCentre_[c];
    if (!(std::fabs(centre[2] - layerZ) < 0.25 * hz())) continue;
    const double quarter = cellSize(c)[0] * cellSize(c)[1] / 4.0;
    faceShare[c] = weight ? quarter * weight(centre[0], centre[1]) : quarter;
  }
  return assemble([&](PetscInt c, int a) { return (a >= 4) == top ? faceShare[c] : 0.0; });
}

}  // namespace gradfric::fem
