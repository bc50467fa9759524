#include "gradfric/fem/property_profiles.hpp"

#include "gradfric/core/gather.hpp"

#include <cmath>
#include <limits>

namespace gradfric::fem {

namespace {

// Collects (column or node index, value) pairs of the middle row on each rank, gathers them.
class MiddleRowSink : public PropertySink {
public:
  explicit MiddleRowSink(const PlateModel& model) : mesh_(model.mesh()) {
    vertexOfBlock_.assign(mesh_.ownedBlocks(), -1);
    for (std::size_t i = 0; i < mesh_.ownedVertices().size(); ++i) vertexOfBlock_[mesh_.ownedVertices()[i].block] = i;
  }

  void cellField(const std::string& name, const std::string& unit, const std::string& description,
                 const std::vector<double>& perLocalCell) override {
    std::vector<double> pairs;
    const int row = mesh_.size().ny / 2;
    for (PetscInt c = 0; c < mesh_.localCells(); ++c) {
      const std::array<double, 3>& centre = mesh_.cellCentres()[c];
      if (centre[2] > mesh_.hz() || mesh_.axisY().cellAt(centre[1]) != row) continue;  // bottom layer, middle row
      pairs.insert(pairs.end(), {double(mesh_.axisX().cellAt(centre[0])), perLocalCell[c]});
    }
    add(name, unit, description + " (bottom cells of row ny/2)", false, mesh_.size().nx, pairs);
  }

  void nodeField(const std::string& name, const std::string& unit, const std::string& description,
                 const std::vector<PetscInt>& blocks, const std::vector<double>& values) override {
    std::vector<double> pairs;
    for (std::size_t k = 0; k < blocks.size(); ++k) {
      const OwnedVertex& v = mesh_.ownedVertices()[vertexOfBlock_[blocks[k]]];
      if (mesh_.axisY().nearestNode(v.y) != mesh_.size().ny / 2) continue;
      pairs.insert(pairs.end(), {double(mesh_.axisX().nearestNode(v.x)), values[k]});
    }
    add(name, unit, description + " (nodes of row ny/2)", true, mesh_.size().nx + 1, pairs);
  }

  std::vector<PropertyProfile> profiles;

private:
  void add(const std::string& name, const std::string& unit, const std::string& description, bool perNode, int size,
           const std::vector<double>& pairs) {
    const std::vector<double> all = gatherOnRoot(mesh_.comm(), pairs);
    PropertyProfile p{name, unit, description, perNode, {}};
    if (!all.empty() || isRoot()) p.values.assign(size, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t k = 0; k + 1 < all.size(); k += 2) p.values[static_cast<std::size_t>(all[k])] = all[k + 1];
    profiles.push_back(std::move(p));
  }
  bool isRoot() const {
    int rank = 0;
    MPI_Comm_rank(mesh_.comm(), &rank);
    return rank == 0;
  }

  const PlateMesh& mesh_;
  std::vector<std::size_t> vertexOfBlock_;
};

}  // namespace

std::vector<PropertyProfile> gatherPropertyProfiles(const PlateModel& model) {
  MiddleRowSink sink(model);
  for (const Layer* layer : model.layers()) layer->writeProperties(sink);
  return std::move(sink.profiles);
}

}  // namespace gradfric::fem
