#include "gradfric/fem/xdmf.hpp"

#include "gradfric/io/file_room.hpp"
#include "gradfric/io/hdf5_attributes.hpp"

#include <sstream>
#include <stdexcept>
#include <vector>

namespace gradfric::fem {

namespace {

struct FieldInfo {
  const char* name;         // dataset name in /vertex_fields or /cell_fields
  const char* units;        // of every component
  const char* description;
  std::vector<std::string> components;  // names; empty for a vector or the tensor
};

// What the FEM writes (src/fem/output.cpp); a field not listed is declared by its width alone.
const std::vector<FieldInfo>& knownFields() {
  static const std::vector<FieldInfo> fields = {
      {"state_displacement", "m", "displacement (u_x, u_y, u_z) of each node", {}},
      {"state_velocity", "m/s", "velocity (v_x, v_y, v_z) of each node", {}},
      {"bottom_contact", "Pa (state: 1)",
       "contact on the bottom face: pressure, tangential tractions t_x, t_y, state 0 open 1 stick 2 slip; 0 off the "
       "bottom face",
       {"pressure", "tx", "ty", "state"}},
      {"cell_stress", "Pa", "cell-averaged Cauchy stress, components xx, xy, xz, yy, yz, zz (XDMF Tensor6 order)",
       {"xx", "xy", "xz", "yy", "yz", "zz"}},
  };
  return fields;
}

const FieldInfo* findField(const std::string& name) {
  for (const auto& f : knownFields())
    if (name == f.name) return &f;
  return nullptr;
}

std::vector<hsize_t> shapeOf(hid_t file, const std::string& path) {
  io::H5Dataset d(GF_H5(H5Dopen2(file, path.c_str(), H5P_DEFAULT)));
  io::H5Space space(GF_H5(H5Dget_space(d)));
  const int rank = GF_H5(H5Sget_simple_extent_ndims(space));
  std::vector<hsize_t> dims(static_cast<size_t>(rank));
  GF_H5(H5Sget_simple_extent_dims(space, dims.data(), nullptr));
  return dims;
}

std::vector<std::string> datasetsIn(hid_t file, const char* group) {
  if (GF_H5(H5Lexists(file, group, H5P_DEFAULT)) <= 0) return {};
  io::H5Group g(GF_H5(H5Gopen2(file, group, H5P_DEFAULT)));
  return io::linkNames(g);
}

// A hyperslab of a [T, n, width] dataset: step t, components [first, first + count).
void writeSlab(std::ostream& x, const std::string& file, const std::string& path, hsize_t steps, hsize_t n,
               hsize_t width, hsize_t t, hsize_t first, hsize_t count) {
  x << "          <DataItem ItemType=\"HyperSlab\" Dimensions=\"" << n << " " << count << "\" Type=\"HyperSlab\">\n"
    << "            <DataItem Dimensions=\"3 3\" Format=\"XML\">" << t << " 0 " << first << "  1 1 1  1 " << n << " "
    << count << "</DataItem>\n"
    << "            <DataItem Dimensions=\"" << steps << " " << n << " " << width
    << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << file << ":" << path << "</DataItem>\n"
    << "          </DataItem>\n";
}

}  // namespace

void describeFieldsAndWriteXdmf(const std::string& fieldsFile, const std::string& heavy, const std::string& xmfPath) {
  struct Field {
    std::string path, name, center;
    std::vector<hsize_t> shape;
    const FieldInfo* info;
  };
  std::string geometry;
  std::vector<hsize_t> vertices, cells;
  std::vector<double> times;
  std::vector<Field> fields;
  // A few attributes per dataset: the room reserved is HDF5's own minimum.
  io::changeHdf5File(fieldsFile, io::withMetadataRoom(0), [&](hid_t file) {
    geometry = GF_H5(H5Lexists(file, "viz", H5P_DEFAULT)) > 0 && GF_H5(H5Lexists(file, "viz/geometry", H5P_DEFAULT)) > 0
                   ? "/viz/geometry/vertices"
                   : "/geometry/vertices";
    vertices = shapeOf(file, geometry);
    cells = shapeOf(file, "/viz/topology/cells");
    {
      io::H5Dataset d(GF_H5(H5Dopen2(file, "/time", H5P_DEFAULT)));
      io::H5Space space(GF_H5(H5Dget_space(d)));
      times.resize(static_cast<size_t>(H5Sget_simple_extent_npoints(space)));
      if (!times.empty()) GF_H5(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, times.data()));
      io::describe(d, "s", "time of each snapshot since the start of sliding");
    }
    {  // The mesh and PETSc's own copies of the fields (global vector order, not the VIZ order).
      auto describePath = [&](const char* path, const char* units, const char* description) {
        if (GF_H5(H5Lexists(file, path, H5P_DEFAULT)) <= 0) return;
        io::H5Dataset d(GF_H5(H5Dopen2(file, path, H5P_DEFAULT)));
        io::describe(d, units, description);
      };
      if (GF_H5(H5Lexists(file, "geometry", H5P_DEFAULT)) > 0)
        describePath("/geometry/vertices", "m", "node coordinates x, y, z");
      describePath("/viz/topology/cells", "1", "the 8 nodes (rows of the vertices) of each hexahedral cell, VTK order");
      if (GF_H5(H5Lexists(file, "fields", H5P_DEFAULT)) > 0) {
        describePath("/fields/state", "m, m/s", "PETSc's layout of the state: u_x, u_y, u_z, v_x, v_y, v_z per node");
        describePath("/fields/bottom", "Pa (state: 1)", "PETSc's layout of bottom_contact (see there)");
        describePath("/fields/cell", "Pa", "PETSc's layout of cell_stress (see there)");
      }
    }
    if (vertices.size() != 2 || cells.size() != 2 || cells[1] != 8)
      throw std::runtime_error("xdmf: " + fieldsFile + " is not a hexahedral mesh in PETSc's VIZ layout");
    for (const auto& [group, center] : {std::pair<const char*, const char*>{"/vertex_fields", "Node"},
                                        std::pair<const char*, const char*>{"/cell_fields", "Cell"}}) {
      for (const auto& name : datasetsIn(file, group)) {
        Field f{std::string(group) + "/" + name, name, center, shapeOf(file, std::string(group) + "/" + name),
                findField(name)};
        if (f.shape.size() == 2) f.shape.push_back(1);  // a scalar field: [T, n]
        if (f.shape.size() != 3 || f.shape[0] != times.size())
          throw std::runtime_error("xdmf: unexpected shape of " + f.path);
        if (f.info) {
          io::H5Dataset d(GF_H5(H5Dopen2(file, f.path.c_str(), H5P_DEFAULT)));
          io::describe(d, f.info->units, f.info->description);
          std::string components;
          for (const auto& c : f.info->components) components += (components.empty() ? "" : ",") + c;
          if (!components.empty()) io::writeStringAttribute(d, "components", components);
        }
        fields.push_back(std::move(f));
      }
    }
  });

  std::ostringstream x;
  x.precision(17);
  x << "<?xml version=\"1.0\" ?>\n<!-- Written by gradfric-fem (src/fem/xdmf.cpp) -->\n"
    << "<Xdmf Version=\"2.0\">\n  <Domain Name=\"domain\">\n"
    << "    <Grid Name=\"TimeSeries\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (size_t t = 0; t < times.size(); ++t) {
    x << "      <Grid Name=\"plate\" GridType=\"Uniform\">\n"
      << "        <Time Value=\"" << times[t] << "\"/>\n"
      << "        <Topology TopologyType=\"Hexahedron\" NumberOfElements=\"" << cells[0] << "\">\n"
      << "          <DataItem Dimensions=\"" << cells[0] << " 8\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
      << heavy << ":/viz/topology/cells</DataItem>\n"
      << "        </Topology>\n"
      << "        <Geometry GeometryType=\"XYZ\">\n"
      << "          <DataItem Dimensions=\"" << vertices[0] << " " << vertices[1]
      << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << heavy << ":" << geometry << "</DataItem>\n"
      << "        </Geometry>\n";
    for (const auto& f : fields) {
      const hsize_t n = f.shape[1], width = f.shape[2];
      const char* type = width == 1 ? "Scalar" : width == 3 ? "Vector" : width == 6 ? "Tensor6" : width == 9 ? "Tensor" : nullptr;
      const bool named = f.info && !f.info->components.empty() && f.info->components.size() == width;
      if (type && !(named && width != 6)) {
        x << "        <Attribute Name=\"" << f.name << "\" AttributeType=\"" << type << "\" Center=\"" << f.center
          << "\">\n";
        writeSlab(x, heavy, f.path, f.shape[0], n, width, t, 0, width);
        x << "        </Attribute>\n";
        continue;
      }
      for (hsize_t c = 0; c < width; ++c) {  // one named scalar per component
        const std::string component = named ? f.info->components[c] : std::to_string(c);
        x << "        <Attribute Name=\"" << f.name << "_" << component << "\" AttributeType=\"Scalar\" Center=\""
          << f.center << "\">\n";
        writeSlab(x, heavy, f.path, f.shape[0], n, width, t, c, 1);
        x << "        </Attribute>\n";
      }
    }
    x << "      </Grid>\n";
  }
  x << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  io::writeWholeFile(xmfPath, x.str());
}

}  // namespace gradfric::fem
