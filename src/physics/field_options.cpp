#include "gradfric/physics/field_options.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/io/collective_file.hpp"
#include "gradfric/physics/property_sampler.hpp"

#include <hdf5.h>
#include <png.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace gradfric {

namespace {

const std::vector<std::string> kShapes = {"none",  "constant", "linear",  "triangular", "exponential",
                                          "power", "step",     "stripes", "bands",      "map"};

FieldShape shapeOf(const std::string& name) {
  for (int s = 0; s <= static_cast<int>(FieldShape::Map); ++s)
    if (name == toString(static_cast<FieldShape>(s))) return static_cast<FieldShape>(s);
  return FieldShape::Constant;
}

bool endsWith(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

io::H5File openHdf5Map(const std::string& option, const std::string& path) {
  const io::Hdf5PrintingOff quiet;  // our own message instead of HDF5's stack
  {
    std::ifstream probe(path);
    if (!probe) throw InputError(option, path, "a readable HDF5 file (cannot open it)");
  }
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) throw InputError(option, path, "a readable HDF5 file (not HDF5)");
  return io::H5File(file);
}

FieldMap readHdf5Map(const std::string& option, const std::string& path, const std::string& dataset,
                     const std::string& datasetOption) {
  const io::H5File file = openHdf5Map(option, path);
  return readHdf5Map(option, path, file, dataset, datasetOption);
}

FieldMap readHdf5Map(const std::string& option, const std::string& path, hid_t file, const std::string& dataset,
                     const std::string& datasetOption) {
  const io::Hdf5PrintingOff quiet;
  auto refuse = [&](const std::string& what) { throw InputError(option, path, what); };
  struct Closer {  // the file is the caller's
    hid_t d = -1, s = -1, a = -1;
    ~Closer() {
      if (a >= 0) H5Aclose(a);
      if (s >= 0) H5Sclose(s);
      if (d >= 0) H5Dclose(d);
    }
  } c;
  c.d = H5Dopen2(file, dataset.c_str(), H5P_DEFAULT);
  if (c.d < 0)
    refuse("an HDF5 file with a dataset '" + dataset + "'" +
           (datasetOption.empty() ? " (-" + option.substr(1) + "_dataset)" : " (" + datasetOption + ")"));
  c.s = H5Dget_space(c.d);
  const int rank = H5Sget_simple_extent_ndims(c.s);
  if (rank != 2) refuse("a rank-2 dataset [ny][nx] ('" + dataset + "' has rank " + std::to_string(rank) + ")");
  hsize_t dims[2] = {0, 0};
  H5Sget_simple_extent_dims(c.s, dims, nullptr);
  if (dims[0] < 1 || dims[1] < 1 || dims[0] > 16384 || dims[1] > 16384)
    refuse("a dataset of 1 to 16384 pixels a side");
  FieldMap m;
  m.ny = static_cast<int>(dims[0]);
  m.nx = static_cast<int>(dims[1]);
  m.values.resize(static_cast<std::size_t>(m.nx) * m.ny);
  if (H5Dread(c.d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, m.values.data()) < 0)
    refuse("a numeric dataset '" + dataset + "'");
  if (H5Aexists(c.d, "extent") <= 0) refuse("a dataset with an attribute 'extent' = x0, x1, y0, y1 [m]");
  c.a = H5Aopen(c.d, "extent", H5P_DEFAULT);
  const hid_t space = H5Aget_space(c.a);
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  H5Sclose(space);
  if (count != 4) refuse("an 'extent' attribute of 4 values x0, x1, y0, y1 [m] (it has " + std::to_string(count) + ")");
  double extent[4];
  if (H5Aread(c.a, H5T_NATIVE_DOUBLE, extent) < 0) refuse("a numeric 'extent' attribute");
  m.x0 = extent[0];
  m.x1 = extent[1];
  m.y0 = extent[2];
  m.y1 = extent[3];
  m.source = path + ":" + dataset;
  return m;
}

namespace {

// A greyscale PNG through libpng: row 0 is the top of the image (y = y1); grey g in [0, 255]
// maps linearly onto [lo, hi].
FieldMap readPngMap(const std::string& option, const std::string& path, double lo, double hi) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str()))
    throw InputError(option, path, std::string("a readable PNG image (libpng: ") + image.message + ")");
  if (image.format & PNG_FORMAT_FLAG_COLOR) {
    png_image_free(&image);
    throw InputError(option, path, "a greyscale PNG image (this one has colour)");
  }
  if (image.width > 16384 || image.height > 16384) {
    png_image_free(&image);
    throw InputError(option, path, "an image of at most 16384 pixels a side");
  }
  image.format = PNG_FORMAT_GRAY;
  std::vector<png_byte> pixels(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr))
    throw InputError(option, path, std::string("a readable PNG image (libpng: ") + image.message + ")");
  FieldMap m;
  m.nx = static_cast<int>(image.width);
  m.ny = static_cast<int>(image.height);
  m.values.resize(pixels.size());
  for (int j = 0; j < m.ny; ++j)
    for (int i = 0; i < m.nx; ++i)
      m.values[static_cast<std::size_t>(j) * m.nx + i] =
          lo + (hi - lo) * pixels[static_cast<std::size_t>(m.ny - 1 - j) * m.nx + i] / 255.0;
  m.source = path;
  return m;
}

std::shared_ptr<const PropertyField> readField(MPI_Comm comm, RunParameters* record, const std::string& property,
                                               const std::string& what, const Plate& plate) {
  const std::string prefix = "field_" + property + "_";
  OptionReader o(comm, prefix, "Property field of " + what + " (docs/fields.md): the plate's value times f(x, y)", record);
  const std::string shapeName = o.choice("profile", "none", kShapes, "profile f of the field (none: the -grading_* options)");
  if (shapeName == "none" && !helpRequested()) {
    // The other options are read (and listed) only with a profile; one set without it is a mistake.
    for (const char* name : {"delta", "exponent", "bands", "angle", "centre", "position", "period", "duty", "values",
                             "map", "map_dataset", "map_extent", "map_range", "normalise"}) {
      PetscBool set = PETSC_FALSE;
      GF_CALL(PetscOptionsHasName(nullptr, nullptr, o.fullName(name).c_str(), &set));
      if (set)
        throw InputError(o.fullName("profile"), "none",
                         "a profile when " + o.fullName(name) + " is set (it would be ignored)");
    }
    return nullptr;
  }
  PropertyField f;
  f.length = plate.length;
  f.delta = o.real("delta", 0.0, "1", "relative amplitude Delta: constant 1+D; linear/power/triangular 1-D..1+D; step 1-D | 1+D; stripes 1+D in a stripe");
  f.exponent = o.real("exponent", 1.0, "1", "power law f = 1 + D (2 s^exponent - 1), > 0; exponential f = exp(exponent (s - 1/2))");
  f.bands = static_cast<int>(o.integer("bands", 0, 0, 4096, "1", "linear/triangular: 0 continuous, N >= 2 the paper's N bands"));
  f.angle = o.real("angle", 0.0, "degree", "direction of the profile from +x (0: along x, the paper's grading axis)");
  const std::vector<double> centre = o.realList("centre", {}, "m", "x,y: a radial profile of the distance to this point (empty: along -" + prefix + "angle)");
  f.position = o.real("position", 0.0, "m", "step: distance where the second material starts; stripes: offset of the first stripe");
  f.period = o.real("period", 0.0, "m", "stripes: period, > 0");
  f.duty = o.real("duty", 0.5, "1", "stripes: fraction of a period with f = 1 + Delta, 0 < duty < 1");
  f.table = o.realList("values", {}, "1", "bands: the factors of N equal bands across the plate");
  const std::string mapPath = o.path("map", "", "map: HDF5 file (.h5, .hdf5) or greyscale PNG (.png) of f (in an options file: from its folder)");
  const std::string dataset = o.text("map_dataset", "factor", "map: the HDF5 dataset [ny][nx] (attribute extent = x0,x1,y0,y1 [m])");
  const std::vector<double> extent = o.realList("map_extent", {0.0, plate.length, 0.0, plate.length}, "m", "PNG map: x0,x1,y0,y1 the image covers (an HDF5 map carries its own)");
  const std::vector<double> range = o.realList("map_range", {0.5, 1.5}, "1", "PNG map: f of black, f of white (grey values in between, linearly)");
  // The pressure field keeps its mean: mu(t) is the tangential force over -plate_p L^2, so -plate_p
  // must be the mean pressure (a higher total load is said with -plate_p, not with the field).
  const bool isPressure = property == "p";
  f.normalise = o.flag("normalise", isPressure,
                       isPressure ? "must stay true: the pressure field keeps its mean -plate_p (mu = F / (p L^2))"
                                  : "rescale f so its mean over the model's sites is 1 (the plate's value is the mean)");
  if (isPressure && !f.normalise && !helpRequested())
    throw InputError(o.fullName("normalise"), "false",
                     "true (the pressure field keeps its mean -plate_p, by which mu is measured; change the total load with -plate_p)");
  if (helpRequested() || shapeName == "none") return nullptr;
  f.shape = shapeOf(shapeName);
  f.blameOption = o.fullName("delta");
  f.blameValue = formatReal(f.delta);
  if (!centre.empty()) {
    if (centre.size() != 2) throw InputError(o.fullName("centre"), "(" + std::to_string(centre.size()) + " values)", "two values x,y [m]");
    f.radial = true;
    f.centreX = centre[0];
    f.centreY = centre[1];
  }
  switch (f.shape) {
    case FieldShape::Linear:
    case FieldShape::Triangular:
      if (f.bands == 1) throw InputError(o.fullName("bands"), "1", "0 (continuous) or 2..4096");
      break;
    case FieldShape::Exponential:
      f.blameOption = o.fullName("exponent");
      f.blameValue = formatReal(f.exponent);
      break;
    case FieldShape::Power:
      if (!(f.exponent > 0)) throw InputError(o.fullName("exponent"), formatReal(f.exponent), "> 0 for the power law");
      break;
    case FieldShape::Stripes:
      if (!(f.period > 0)) throw InputError(o.fullName("period"), formatReal(f.period), "> 0 [m] for stripes");
      if (!(f.duty > 0 && f.duty < 1)) throw InputError(o.fullName("duty"), formatReal(f.duty), "0 < duty < 1");
      break;
    case FieldShape::Bands: {
      if (f.table.empty()) throw InputError(o.fullName("values"), "(empty)", "at least one factor for -" + prefix + "profile bands");
      std::ostringstream text;
      for (std::size_t i = 0; i < f.table.size(); ++i) text << (i ? "," : "") << f.table[i];
      f.blameOption = o.fullName("values");
      f.blameValue = text.str();
      break;
    }
    case FieldShape::Map: {
      if (mapPath.empty()) throw InputError(o.fullName("map"), "(empty)", "an HDF5 or PNG file for -" + prefix + "profile map");
      FieldMap m;
      if (endsWith(mapPath, ".png")) {
        if (extent.size() != 4) throw InputError(o.fullName("map_extent"), "(" + std::to_string(extent.size()) + " values)", "four values x0,x1,y0,y1 [m]");
        if (range.size() != 2) throw InputError(o.fullName("map_range"), "(" + std::to_string(range.size()) + " values)", "two values: f of black, f of white");
        m = readPngMap(o.fullName("map"), mapPath, range[0], range[1]);
        m.x0 = extent[0];
        m.x1 = extent[1];
        m.y0 = extent[2];
        m.y1 = extent[3];
      } else if (endsWith(mapPath, ".h5") || endsWith(mapPath, ".hdf5")) {
        m = readHdf5Map(o.fullName("map"), mapPath, dataset);
      } else {
        throw InputError(o.fullName("map"), mapPath, "a file ending in .h5, .hdf5 (HDF5) or .png (greyscale image)");
      }
      std::ostringstream box;
      box << m.x0 << "," << m.x1 << "," << m.y0 << "," << m.y1;
      const double slack = 1e-9 * plate.length;
      const bool png = endsWith(mapPath, ".png");  // its extent is an option, an HDF5 map's is in the file
      if (!(m.x0 <= slack && m.x1 >= plate.length - slack && m.y0 <= slack && m.y1 >= plate.length - slack))
        throw InputError(o.fullName(png ? "map_extent" : "map"), png ? box.str() : mapPath,
                         "a map whose extent covers the plate [0, " + formatReal(plate.length) + "]^2 m (it covers x0,x1,y0,y1 = " + box.str() + ")");
      for (int j = 0; j < m.ny; ++j)
        for (int i = 0; i < m.nx; ++i)
          if (!std::isfinite(m.values[static_cast<std::size_t>(j) * m.nx + i])) {
            std::ostringstream at;
            at << "a map of finite values (pixel " << i << ", " << j << " at x = " << m.x0 + (i + 0.5) * (m.x1 - m.x0) / m.nx
               << " m, y = " << m.y0 + (j + 0.5) * (m.y1 - m.y0) / m.ny << " m is "
               << m.values[static_cast<std::size_t>(j) * m.nx + i] << ")";
            throw InputError(o.fullName("map"), mapPath, at.str());
          }
      f.map = std::make_shared<const FieldMap>(std::move(m));
      f.blameOption = o.fullName("map");
      f.blameValue = mapPath;
      break;
    }
    default: break;
  }
  return std::make_shared<const PropertyField>(std::move(f));
}

}  // namespace

std::shared_ptr<const PlateFields> readPlateFields(MPI_Comm comm, RunParameters* record, const Plate& plate,
                                                   const Grading& grading) {
  PlateFields fields;
  fields.modulus = readField(comm, record, "E", "Young's modulus E", plate);
  const auto both = readField(comm, record, "mu", "mu_s and mu_k together (their ratio kept)", plate);
  fields.muStatic = readField(comm, record, "mu_s", "the static coefficient mu_s alone", plate);
  fields.muKinetic = readField(comm, record, "mu_k", "the kinetic coefficient mu_k alone", plate);
  fields.pressure = readField(comm, record, "p", "the normal pressure p (static)", plate);
  if (both && (fields.muStatic || fields.muKinetic))
    throw InputError(std::string(fields.muStatic ? "-field_mu_s_profile" : "-field_mu_k_profile"),
                     toString((fields.muStatic ? fields.muStatic : fields.muKinetic)->shape),
                     "none when -field_mu_profile is set (it gives mu_s and mu_k together)");
  if (both) fields.muStatic = fields.muKinetic = both;
  if (fields.modulus && grading.gradesModulus())
    throw InputError("-field_E_profile", toString(fields.modulus->shape),
                     "none when -grading_property grades E (one description of E: drop one of them)");
  if ((fields.muStatic || fields.muKinetic) && grading.gradesFriction())
    throw InputError(both ? "-field_mu_profile" : fields.muStatic ? "-field_mu_s_profile" : "-field_mu_k_profile", "(set)",
                     "none when -grading_property grades the friction (one description of it: drop one of them)");
  if (!fields.any()) return nullptr;
  return std::make_shared<const PlateFields>(std::move(fields));
}

namespace {

void refuseProblem(const Grading& grading, const SiteProblem& problem) {
  const PlateFields& f = *grading.fields;
  const PropertyField* blamed = problem.property == "E"      ? f.modulus.get()
                                : problem.property == "mu_s" ? f.muStatic.get()
                                : problem.property == "p"    ? f.pressure.get()
                                                             : (f.muKinetic ? f.muKinetic.get() : f.muStatic.get());
  std::ostringstream where;
  where << problem.allowed << " (" << problem.property << " = " << problem.where.value << " at x = " << problem.where.x
        << " m, y = " << problem.where.y << " m)";
  if (!blamed) throw InputError("invalid property field: " + where.str());
  throw InputError(blamed->blameOption, blamed->blameValue, where.str());
}

}  // namespace

void checkPlateFields(const Grading& grading, const Plate& plate, int nx, int ny) {
  if (!grading.fields) return;
  const SiteProblem problem = checkSites(grading, plate, nx, ny);
  if (!problem.property.empty()) refuseProblem(grading, problem);
}

void checkPlateFields(const Grading& grading, const Plate& plate, const PropertySampler& sampler, const SiteGrid& grid) {
  if (!grading.fields) return;
  const SiteProblem problem = checkSites(sampler, plate, grid);
  if (!problem.property.empty()) refuseProblem(grading, problem);
}

void checkSpringBlockFields(const Grading& grading, const Plate& plate, int blocksPerSide) {
  if (!grading.fields) return;
  checkPlateFields(grading, plate, blocksPerSide, blocksPerSide);
}

}  // namespace gradfric
