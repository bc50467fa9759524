#pragma once
// An inverse-design problem: a family of spring-block plates with free parameters and bounds, a
// target for the global static friction mu_s (absolute, or its relative variation against the
// non-graded plate) and a tolerance. Every -design_* option is read and checked before any work
// (docs/design.md).
#include "gradfric/core/options.hpp"
#include "gradfric/design/fem_check.hpp"
#include "gradfric/design/variants.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/sbm/parameters.hpp"

#include <mpi.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gradfric::design {

enum class TargetKind {
  Absolute,   // the plate's mean mu_s
  Variation,  // (mu_s - mu_s,0) / mu_s,0 against the non-graded plate (paired streams)
};

// One free parameter: "grading_delta" (the paper's gradings) or a property-field parameter
// "<property>_<name>" (mu_delta, E_exponent, mu_period, ...).
struct FreeParameter {
  std::string name;
  double lower = 0.0, upper = 0.0;
};

struct Problem {
  Grading grading;             // the family's base plate (-grading_*, -field_*)
  sbm::Parameters parameters;  // one time step for the whole search: the stiffest corner of the bounds
  sbm::Request request;        // mu_s only: every run stops at its confirmed peak
  std::vector<FreeParameter> free;
  TargetKind kind = TargetKind::Absolute;
  double target = 0.0;
  double tolerance = 0.002;  // the design's 95 % CI half-width must be at most this
  double coarse = 0.008;     // CI half-width of evaluations far from the target
  int firstBatch = 8;        // realisations of an evaluation's first batch
  int cap = 200;             // at most this many realisations per evaluation
  int maxEvaluations = 20;
  int scanPoints = 3;        // interior points tried when the bounds do not bracket the target
  std::string method = "root";  // root (one parameter) or tao
  std::string model = "sbm";    // what each evaluation runs: sbm (ensembles) or fem (one run, fem below)
  std::uint64_t seed = 1;
  bool verify = true;
  std::shared_ptr<FemCheck> fem;  // -design_model fem or -design_verify_fem: the FEM's options (null: no FEM run)
  // -design_model fem with -design_coarse_mesh: the same options on the coarse mesh the search
  // runs on first (null: the search runs on fem's mesh), and the runs allowed on fem's mesh after.
  std::shared_ptr<FemCheck> coarseFem;
  int fineEvaluations = 4;
  std::vector<SpringBlockVariant> variants;  // -design_variants: the spring-block variants run at the design
  std::vector<std::string> reuse;  // -design_reuse: earlier design files whose FEM runs are taken, not rerun
  bool monitor = true;
  bool plot = false;
  std::string output;
  bool overwrite = false;

  int dimension() const { return static_cast<int>(free.size()); }
  // The plate of the family at parameter values x (one per free parameter).
  Grading gradingAt(const std::vector<double>& x) const;
  // The non-graded plate of the same scene (the reference of a Variation target).
  Grading referenceGrading() const;
  std::string describe(const std::vector<double>& x) const;  // "mu_delta=0.21, ..."
};

const char* toString(TargetKind kind);

// A design's runs measure mu_s alone: each stops at its confirmed peak, with no map and a sparse history.
void measureMuStaticOnly(sbm::Request* request);

// Collective: reads and checks every option (InputError on every rank alike); nullopt after -help.
std::optional<Problem> readProblem(MPI_Comm comm, RunParameters* record);

}  // namespace gradfric::design
