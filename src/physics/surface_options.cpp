#include "gradfric/physics/surface_options.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"

#include <petscsys.h>

#include <cmath>
#include <string>
#include <vector>

namespace gradfric {

SurfaceSettings readSurface(MPI_Comm comm, RunParameters* record, const Plate& plate, const SurfaceDefaults& defaults) {
  for (const char* name : {"sigma_s", "sigma_k"})
    refuseRenamedOption(std::string("-sbm_") + name, std::string("-surface_") + name,
                        "the dispersion is the random surface's, shared by both models (docs/surface.md)");
  OptionReader o(comm, "surface_", "Random surface (both models; docs/surface.md)", record);
  SurfaceSettings s;
  s.sigmaStatic = o.real("sigma_s", defaults.sigma, "1",
                         "relative standard deviation of the local mu_s (0: no disorder)");
  s.sigmaKinetic = o.real("sigma_k", defaults.sigma, "1",
                          "relative standard deviation of the local mu_k (0: no disorder)");
  o.requireRange("sigma_s", s.sigmaStatic, 0.0, 0.5, "0 <= sigma_s <= 0.5");
  o.requireRange("sigma_k", s.sigmaKinetic, 0.0, 0.5, "0 <= sigma_k <= 0.5");
  std::vector<std::string> kinds = {"cells", "gaussian"};
  if (defaults.blocksAllowed) kinds.push_back("blocks");
  const std::string kind = o.choice(
      "kind", "cells", kinds,
      defaults.blocksAllowed
          ? "the field: cells (independent squares of side l_c), gaussian (smooth, covariance exp(-r^2/l_c^2)) or "
            "blocks (one independent draw per block, l_c = the block: the model of files written before the surface)"
          : "the field: cells (independent squares of side l_c) or gaussian (smooth, covariance exp(-r^2/l_c^2))");
  s.kind = kind == "cells" ? SurfaceKind::Cells : kind == "gaussian" ? SurfaceKind::Gaussian : SurfaceKind::Blocks;
  if (s.kind == SurfaceKind::Blocks) {
    // The block is the correlation length: a length would have no effect.
    char value[256] = "";
    PetscBool set = PETSC_FALSE;
    GF_CALL(PetscOptionsGetString(nullptr, nullptr, o.fullName("length").c_str(), value, sizeof value, &set));
    if (set) throw InputError(o.fullName("length"), value, "not with -surface_kind blocks (l_c is the block side L/N_b)");
    return s;
  }
  // At most 2^16 cells per side (the surface's counter); any l_c above that is a field.
  if (auto length = o.realIfSet("length", "m", "correlation length l_c of the disorder", "L/120, the paper's block")) {
    s.correlationLength = *length;
    // Every realisation draws the whole plate's cells (Gaussian: noise nodes at l_c/4): at most
    // 2^26 draws per property, some seconds, instead of a run that never starts.
    const double perSide = s.kind == SurfaceKind::Gaussian ? 2048.0 : 8192.0;
    const double smallest = plate.length / perSide;
    if (!(s.correlationLength >= smallest))
      throw InputError(o.fullName("length"), formatReal(s.correlationLength),
                       "l_c >= L/" + formatReal(perSide) + " = " + formatReal(smallest) + " m for this plate and -surface_kind " +
                           kind + " (at most 2^26 random draws per realisation) [m]");
  } else {
    s.correlationLength = defaultCorrelationLength(plate.length);
    o.recordDerived("length", s.correlationLength, "m", "correlation length l_c = L/120, the paper's block");
  }
  return s;
}

}  // namespace gradfric
