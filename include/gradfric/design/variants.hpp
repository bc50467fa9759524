#pragma once
// -design_variants: the spring-block variants a designer names (a friction law, a calibration),
// each an options file of -sbm_*, -friction_* and -surface_* options laid over the scene. At the
// design each variant runs one ensemble on the verification's streams (paired with it); where the
// variants lie against the design's model is the design's variant interval (uncertainty.hpp).
#include "gradfric/physics/grading.hpp"
#include "gradfric/physics/plate.hpp"
#include "gradfric/sbm/parameters.hpp"

#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

namespace gradfric::design {

struct Problem;
struct Evaluation;

struct SpringBlockVariant {
  std::string file;     // the options file, as given
  std::string options;  // what it sets: "-friction_law state -sbm_lz 5.05e-05"
  sbm::Parameters parameters;
  sbm::Request request;
};

// Collective, before any work: reads each file's spring-block options over the scene's (the
// global options database, copied), the stable step at the family's stiffest plate. InputError
// (on every rank alike) names -design_variants and the file for a missing file, an option outside
// -sbm_*, -friction_*, -surface_*, or one nothing reads; a bad value is the option's own refusal.
std::vector<SpringBlockVariant> readVariants(MPI_Comm comm, const std::vector<std::string>& files, const Plate& plate,
                                             const Grading& stiffest);

// Collective: one ensemble per variant at x, to the design's tolerance, from stream `stream`
// (the verification's: the variants pair with it). Adds the realisations run to *realisations.
std::vector<Evaluation> evaluateVariants(MPI_Comm comm, const Problem& problem, const std::vector<double>& x,
                                         std::uint32_t stream, long* realisations);

}  // namespace gradfric::design
