// The FEM's first-slip map, gathered on rank 0 (include/gradfric/fem/first_slip_map.hpp).
#include "gradfric/fem/first_slip_map.hpp"

#include "gradfric/core/gather.hpp"
#include "gradfric/core/petsc_call.hpp"

#include <cmath>

namespace gradfric::fem {

FirstSlipMap gatherFirstSlipMap(const PlateModel& model) {
  const PlateMesh& mesh = model.mesh();
  const int nx = model.params().nx + 1, ny = model.params().ny + 1;
  std::vector<double> local;  // (grid index, first slip) per node of this rank
  for (const ContactBoundary::Node& node : model.contact().nodes()) {
    const long long column = mesh.axisX().nearestNode(node.x), row = mesh.axisY().nearestNode(node.y);
    local.insert(local.end(), {double(row * nx + column), node.firstSlip});
  }
  const std::vector<double> all = gatherOnRoot(model.comm(), local);
  int rank = 0;
  GF_CALL_MPI(MPI_Comm_rank(model.comm(), &rank));
  FirstSlipMap m;
  if (rank != 0) return m;
  m.nx = nx;
  m.ny = ny;
  m.nodeX = mesh.axisX().nodes;
  m.nodeY = mesh.axisY().nodes;
  m.time.assign(std::size_t(nx) * ny, std::nan(""));
  for (std::size_t k = 0; k + 1 < all.size(); k += 2) m.time[static_cast<std::size_t>(all[k])] = all[k + 1];
  return m;
}

}  // namespace gradfric::fem
