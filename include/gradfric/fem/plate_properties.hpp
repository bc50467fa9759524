#pragma once
// The plate's local properties on the mesh, built once from the plate record, the -grading_
// bands and the property fields (-field_*), and read by every layer and by the output, so the
// file stores the values the physics used:
//  - per local cell: E at the cell centre (the elastic operator, the bulk viscosity's wave speed);
//  - per owned bottom node: its area and mu_s, mu_k, the area-weighted mean of the factors at the
//    centres of its bottom faces (the contact's friction sites), times the random surface averaged
//    over the node's tributary rectangle when it is dispersed (mesh_sites.hpp, surfaceCoefficients);
//  - per owned top node: its area and the load p pushes on, the area times the pressure field's
//    factor at its faces' centres (area-weighted the same way).
// PropertySink is how layers hand these to the output (Layer::writeProperties).
#include "gradfric/fem/plate_mesh.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/physics/plate.hpp"
#include "gradfric/physics/random_surface.hpp"

#include <string>
#include <vector>

namespace gradfric::fem {

struct BottomNode {
  PetscInt block;  // owned block in the global state vector
  double x, y;     // position [m]
  double area;     // nodal area [m^2]
  double muStatic, muKinetic;
};

struct TopNode {
  PetscInt block;
  double area;  // nodal area [m^2]
  double load;  // area x the pressure factor [m^2]: the pressure's force is p load
};

class PlateProperties {
public:
  // surface: dispersed or not, its seed and l_c set (FemParameters::surface); realisation: which
  // of the seed's surfaces (FemParameters::surfaceRealisation).
  PlateProperties(const PlateMesh& mesh, const Plate& plate, const Grading& grading, const SurfaceSettings& surface,
                  std::uint32_t realisation);

  const Plate& plate() const { return plate_; }
  const SurfaceSettings& surface() const { return surface_; }
  const std::vector<double>& cellModulus() const { return cellModulus_; }  // [Pa] per local cell
  const std::vector<BottomNode>& bottomNodes() const { return bottom_; }
  const std::vector<TopNode>& topNodes() const { return top_; }

private:
  Plate plate_;
  SurfaceSettings surface_;
  std::vector<double> cellModulus_;
  std::vector<BottomNode> bottom_;
  std::vector<TopNode> top_;
};

// Where layers write the fields they read: per local cell, or per owned node (its block).
class PropertySink {
public:
  virtual ~PropertySink() = default;
  virtual void cellField(const std::string& name, const std::string& unit, const std::string& description,
                         const std::vector<double>& perLocalCell) = 0;
  virtual void nodeField(const std::string& name, const std::string& unit, const std::string& description,
                         const std::vector<PetscInt>& blocks, const std::vector<double>& values) = 0;
};

}  // namespace gradfric::fem
