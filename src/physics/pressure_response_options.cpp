// -pressure_response options (pressure_response_options.hpp).
#include "gradfric/physics/pressure_response_options.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/io/collective_file.hpp"
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/io/hdf5_handle.hpp"
#include "gradfric/physics/field_options.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

namespace gradfric {

namespace {

std::vector<std::string> splitCommas(const std::string& text) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, ',')) parts.push_back(part);
  if (!text.empty() && text.back() == ',') parts.push_back("");
  return parts;
}

// One gradfric-fem file's g and what the file says beside it, read in one open.
struct ResponseFile {
  FieldMap map;
  std::vector<double> nodeX, nodeY;  // the node positions of g (empty when the file has none)
  double measuredUpTo = 0.0;         // the top of the window g was fitted on (0: not said)
  // The run's /scene record (every option with its resolved value), read when asked for;
  // sceneProblem says what is wrong when it could not be read.
  std::map<std::string, std::string> scene;
  std::string sceneProblem;
};

// The grading a gradfric-fem run measured its g under, from the file's /scene record; refused
// when the file has none or the plate had property fields.
ResponseGrading gradingOfFemFile(const std::string& option, const std::string& optionValue, const std::string& path,
                                 const ResponseFile& file) {
  auto refuse = [&](const std::string& what) { throw InputError(option, optionValue, path + ": " + what); };
  if (!file.sceneProblem.empty()) refuse(file.sceneProblem);
  const std::map<std::string, std::string>& scene = file.scene;
  auto value = [&](const std::string& name) {
    const auto at = scene.find(name);
    if (at == scene.end()) refuse("a /scene record with '" + name + "' (written by gradfric-fem)");
    return at->second;
  };
  auto number = [&](const std::string& name) {
    const std::string text = value(name);
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !std::isfinite(v)) refuse("a number for /scene " + name + " (it is '" + text + "')");
    return v;
  };
  for (const char* field : {"field_E_profile", "field_mu_profile", "field_mu_s_profile", "field_mu_k_profile", "field_p_profile"}) {
    const auto at = scene.find(field);
    if (at != scene.end() && at->second != "none")
      refuse(std::string("a g measured without property fields (the run set -") + field + " " + at->second + ")");
  }
  Grading g;
  const std::string profile = value("grading_profile"), property = value("grading_property");
  try {
    g.profile = parseGradingProfile(profile);
  } catch (const std::invalid_argument&) {
    refuse("a grading profile of this build for /scene grading_profile (it is '" + profile + "')");
  }
  g.property = property == "friction" ? GradedProperty::Friction : property == "both" ? GradedProperty::Both
                                                                                        : GradedProperty::YoungsModulus;
  g.delta = number("grading_delta");
  g.bands = static_cast<int>(number("grading_bands"));
  return responseGradingOf(g, number("plate_theta"));
}

// The group of g in an open file: /fem/pressure_response (format gradfric-fem-run), else the older
// /pressure_response (gradfric-fem-history files, read as they were). One level at a time: HDF5
// 1.10 fails on a path through a missing group.
std::string responseGroup(hid_t file) {
  const bool current = H5Lexists(file, "fem", H5P_DEFAULT) > 0 && H5Lexists(file, "fem/pressure_response", H5P_DEFAULT) > 0;
  return current ? kPressureResponseGroup : kOldPressureResponseGroup;
}

// The top of the loading window gradfric-fem fitted the file's g on (the attribute mu_window of
// <group>/g), or 0 when the file has none.
double measuredUpTo(hid_t file, const std::string& group) {
  double window[2] = {0.0, 0.0};
  const io::H5Dataset set(H5Dopen2(file, (group + "/g").c_str(), H5P_DEFAULT));
  if (set.valid() && H5Aexists(set, "mu_window") > 0) {
    const io::H5Attribute a(H5Aopen(set, "mu_window", H5P_DEFAULT));
    const io::H5Space space(H5Aget_space(a));
    if (H5Sget_simple_extent_npoints(space) != 2 || H5Aread(a, H5T_NATIVE_DOUBLE, window) < 0) window[1] = 0.0;
  }
  return std::isfinite(window[1]) && window[1] > 0.0 ? window[1] : 0.0;
}

// The node positions along one axis of the file's g (<group>/node_x or node_y, written since
// gradfric-fem-history format 3), empty when the file has none.
std::vector<double> nodePositions(hid_t file, const std::string& group, const char* name) {
  std::vector<double> nodes;
  const std::string dataset = group + "/" + name;
  if (H5Lexists(file, dataset.c_str(), H5P_DEFAULT) <= 0) return nodes;
  const io::H5Dataset set(H5Dopen2(file, dataset.c_str(), H5P_DEFAULT));
  if (!set.valid()) return nodes;
  const hssize_t n = H5Sget_simple_extent_npoints(io::H5Space(H5Dget_space(set)));
  if (n > 0) {
    nodes.resize(static_cast<std::size_t>(n));
    if (H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, nodes.data()) < 0) nodes.clear();
  }
  return nodes;
}

// The file's /scene attributes into r (or what is wrong with them into r->sceneProblem).
void readSceneRecord(hid_t file, ResponseFile* r) {
  if (H5Lexists(file, "scene", H5P_DEFAULT) <= 0) {
    r->sceneProblem = "a gradfric-fem results file with its /scene record (the grading g was measured under; "
                      "-pressure_response_select grading needs it)";
    return;
  }
  const io::H5Group group(H5Gopen2(file, "scene", H5P_DEFAULT));
  if (!group.valid()) {
    r->sceneProblem = "a readable /scene group";
    return;
  }
  for (const auto& [k, v] : io::readStringAttributes(group)) r->scene[k] = v;
}

ResponseFile readResponseFile(const std::string& option, const std::string& path, bool withScene) {
  const io::Hdf5PrintingOff quiet;  // missing node positions or window are not errors
  const io::H5File file = openHdf5Map(option, path);
  ResponseFile r;
  const std::string group = responseGroup(file);
  r.map = readHdf5Map(option, path, file, group + "/g", "written by gradfric-fem -output");
  r.nodeX = nodePositions(file, group, "node_x");
  r.nodeY = nodePositions(file, group, "node_y");
  r.measuredUpTo = measuredUpTo(file, group);
  if (withScene) readSceneRecord(file, &r);
  return r;
}

// One file's g, refused when it is not a finite map covering the plate (value: the option's whole text).
void checkResponseFile(const std::string& option, const std::string& value, const std::string& path,
                       const ResponseFile& file, const Plate& plate) {
  const std::string where = value == path ? "" : path + ": ";
  const FieldMap& map = file.map;
  for (std::size_t k = 0; k < map.values.size(); ++k)
    if (!std::isfinite(map.values[k])) {
      std::ostringstream text;
      text << where << "a finite g everywhere (pixel " << k % map.nx << ", " << k / map.nx << " is not)";
      throw InputError(option, value, text.str());
    }
  const double tolerance = 1e-9 * plate.length;
  if (map.x0 > tolerance || map.y0 > tolerance || map.x1 < plate.length - tolerance ||
      map.y1 < plate.length - tolerance) {
    std::ostringstream box;
    box << where << "a map covering the plate [0, " << plate.length << "]^2 m (its extent is " << map.x0 << ", "
        << map.x1 << ", " << map.y0 << ", " << map.y1 << "; -plate_L as in the FEM run)";
    throw InputError(option, value, box.str());
  }
  // The map is sampled as equal pixels centred on the nodes: a g measured on a mesh graded toward the
  // edges (unequal node spacing) would be sampled at the wrong places.
  for (const auto& [axis, nodes] : {std::pair{"node_x", &file.nodeX}, std::pair{"node_y", &file.nodeY}}) {
    if (nodes->size() < 3) continue;
    double smallest = (*nodes)[1] - (*nodes)[0], largest = smallest;
    for (std::size_t i = 1; i + 1 < nodes->size(); ++i) {
      smallest = std::min(smallest, (*nodes)[i + 1] - (*nodes)[i]);
      largest = std::max(largest, (*nodes)[i + 1] - (*nodes)[i]);
    }
    if (largest - smallest > 1e-9 * largest) {
      std::ostringstream text;
      text << where << "a g measured on a uniform mesh (this file's " << axis << " spacing runs from " << smallest
           << " to " << largest << " m: a mesh graded toward the edges; measure g with -fem_edge_ratio 1)";
      throw InputError(option, value, text.str());
    }
  }
}

}  // namespace

PressureResponse readPressureResponse(MPI_Comm comm, RunParameters* record, const Plate& plate, int nb) {
  OptionReader o(comm, "pressure_", "Load-dependent pressure of the spring-block model (docs/fields.md)", record);
  const std::string source =
      o.choice("response", "none", {"none", "moment", "fem"},
               "shape g of the block pressure p_i(t) = p_i^0 (1 + F(t)/(p L^2) g_i): none (constant), moment (the "
               "moment balance H F with edge concentration), fem (measured by gradfric-fem, -pressure_response_file)");
  PressureResponse r;
  const std::string edgeOption = o.fullName("response_edge"), fileOption = o.fullName("response_file");
  std::optional<double> edge = o.realIfSet("response_edge", "m",
                                           "moment: decay length lambda of the pressure concentration at the "
                                           "leading and trailing edges (in (0, L/2])",
                                           formatReal(kDefaultEdgeOverThickness) + " H");
  const std::string file =
      o.path("response_file", "",
             "fem: gradfric-fem results file(s) whose /fem/pressure_response/g is the shape g (comma-separated with "
             "-pressure_response_select grading; in an options file: from its folder)", true);
  const std::string select =
      o.choice("response_select", "same", {"same", "grading"},
               "fem: same (the one file's g at every sweep point) or grading (each sweep point takes the file whose "
               "FEM run had its grading: property, profile, Delta, bands, theta)");
  const std::string selectOption = o.fullName("response_select");
  if (source != "fem" && o.wasSet("response_select"))
    throw InputError(selectOption, select, "only with -pressure_response fem");
  if (source == "none") {
    if (edge) throw InputError(edgeOption, formatReal(*edge), "only with -pressure_response moment");
    if (!file.empty()) throw InputError(fileOption, file, "only with -pressure_response fem");
    return r;
  }
  std::string blameOption, blameValue;
  if (source == "moment") {
    if (!file.empty()) throw InputError(fileOption, file, "only with -pressure_response fem");
    r.source = PressureResponseSource::MomentBalance;
    if (edge) {
      r.edgeLength = *edge;
      if (!(r.edgeLength > 0.0 && r.edgeLength <= 0.5 * plate.length))
        throw InputError(edgeOption, formatReal(r.edgeLength),
                         "0 < lambda <= L/2 = " + formatReal(0.5 * plate.length) + " [m]");
    } else {
      r.edgeLength = kDefaultEdgeOverThickness * plate.thickness;
      o.recordDerived("response_edge", r.edgeLength, "m", "moment: edge decay length lambda = " +
                                                              formatReal(kDefaultEdgeOverThickness) + " H");
    }
    blameOption = edgeOption;
    blameValue = formatReal(r.edgeLength);
  } else {
    if (edge) throw InputError(edgeOption, formatReal(*edge), "only with -pressure_response moment");
    if (file.empty()) throw InputError(fileOption, "(not set)", "a gradfric-fem results file with -pressure_response fem");
    r.source = PressureResponseSource::Fem;
    const std::vector<std::string> files = splitCommas(file);
    r.perGrading = select == "grading";
    if (!r.perGrading && files.size() != 1)
      throw InputError(fileOption, file,
                       "one file with -pressure_response_select same (several with -pressure_response_select grading)");
    for (const std::string& path : files) {
      if (path.empty()) throw InputError(fileOption, file, "comma-separated file names, none empty");
      MeasuredResponse m;
      m.file = path;
      ResponseFile read = readResponseFile(fileOption, path, r.perGrading);
      checkResponseFile(fileOption, file, path, read, plate);
      if (r.perGrading) {
        m.grading = gradingOfFemFile(fileOption, file, path, read);
        for (const MeasuredResponse& earlier : r.measured)
          if (sameGrading(earlier.grading, m.grading))
            throw InputError(fileOption, file,
                             "one file per grading (" + earlier.file + " and " + path + " both hold " +
                                 m.grading.describe() + ")");
      }
      m.measuredUpTo = read.measuredUpTo;
      m.map = std::make_shared<const FieldMap>(std::move(read.map));
      r.measured.push_back(std::move(m));
    }
    if (!r.perGrading) r.map = r.measured.front().map;
    blameOption = fileOption;
    blameValue = file;
  }
  // The trailing edge unloads: its pressure must stay positive at least up to the top of the window
  // the FEM measures g on, 0.8 mu_s (beyond, a block whose factor would turn negative lifts off:
  // strength zero, counted by the coupling's record).
  // Every file's shape under -pressure_response_select grading; a measured g up to the top of the
  // window the FEM fitted it on (its own mu_s times 0.8), when the file says.
  std::vector<std::pair<PressureResponse, double>> shapes;
  for (const MeasuredResponse& m : r.measured) {
    PressureResponse one = r;
    one.perGrading = false;
    one.map = m.map;
    shapes.push_back({one, m.measuredUpTo > 0.0 ? m.measuredUpTo : kResponseWindowHigh * plate.muStatic});
  }
  if (r.measured.empty()) shapes.push_back({r, kResponseWindowHigh * plate.muStatic});
  for (const auto& [one, muChecked] : shapes) {
    const std::vector<double> g = pressureResponseShape(one, nb, plate.length, plate.thickness, plate.slidingAngle);
    const auto smallest = std::min_element(g.begin(), g.end());
    if (1.0 + muChecked * *smallest <= 0.0) {
      const std::size_t i = std::size_t(smallest - g.begin());
      std::ostringstream allowed;
      if (r.perGrading) allowed << one.map->source << ": ";
      allowed << "a shape whose pressure stays positive up to mu = "
              << (r.measured.empty() ? formatReal(kResponseWindowHigh) + " -plate_mu_s = " : std::string("")) << muChecked
              << (r.measured.empty() ? "" : " (the top of the FEM's loading window; 0.8 -plate_mu_s without one)")
              << " (g = " << *smallest << " at the block x = "
              << (i % nb + 0.5) * plate.length / nb << " m, y = " << (i / nb + 0.5) * plate.length / nb
              << " m: 1 + " << muChecked << " g <= 0)";
      throw InputError(blameOption, blameValue, allowed.str());
    }
  }
  return r;
}

}  // namespace gradfric
