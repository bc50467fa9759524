// -pressure_response options (pressure_response_options.hpp).
#include "gradfric/physics/pressure_response_options.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/physics/field_options.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

namespace gradfric {

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
      o.text("response_file", "", "fem: gradfric-fem results file whose /pressure_response/g is the shape g");
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
    FieldMap map = readHdf5Map(fileOption, file, kPressureResponseDataset, "written by gradfric-fem -fem_output");
    for (std::size_t k = 0; k < map.values.size(); ++k)
      if (!std::isfinite(map.values[k])) {
        std::ostringstream where;
        where << "a finite g everywhere (pixel " << k % map.nx << ", " << k / map.nx << " is not)";
        throw InputError(fileOption, file, where.str());
      }
    const double tolerance = 1e-9 * plate.length;
    if (map.x0 > tolerance || map.y0 > tolerance || map.x1 < plate.length - tolerance ||
        map.y1 < plate.length - tolerance) {
      std::ostringstream box;
      box << "a map covering the plate [0, " << plate.length << "]^2 m (its extent is " << map.x0 << ", " << map.x1
          << ", " << map.y0 << ", " << map.y1 << "; -plate_L as in the FEM run)";
      throw InputError(fileOption, file, box.str());
    }
    r.map = std::make_shared<const FieldMap>(std::move(map));
    blameOption = fileOption;
    blameValue = file;
  }
  // The trailing edge unloads: its pressure must stay positive at least up to the plate's mean mu_s
  // (beyond, a block whose factor would turn negative lifts off: strength zero).
  const std::vector<double> g = pressureResponseShape(r, nb, plate.length, plate.thickness, plate.slidingAngle);
  const auto smallest = std::min_element(g.begin(), g.end());
  if (1.0 + plate.muStatic * *smallest <= 0.0) {
    const std::size_t i = std::size_t(smallest - g.begin());
    std::ostringstream allowed;
    allowed << "a shape whose pressure stays positive up to mu = -plate_mu_s = " << plate.muStatic << " (g = "
            << *smallest << " at the block x = " << (i % nb + 0.5) * plate.length / nb
            << " m, y = " << (i / nb + 0.5) * plate.length / nb << " m: 1 + mu_s g <= 0)";
    throw InputError(blameOption, blameValue, allowed.str());
  }
  return r;
}

}  // namespace gradfric
