#pragma once
// The FEM as a design's model (-design_model fem, docs/design.md), and the FEM check of a
// spring-block design (-design_verify_fem): each run is one gradfric-fem run of the family's plate
// at x on the -fem_* mesh, to its confirmed static peak, over all ranks. On an undispersed surface
// a run is deterministic: it has no sampling error (an exact Evaluation that holds the target
// within the tolerance). A variation target is against the FEM's own non-graded plate, run once
// and kept; a parameter value already run, or known from -design_reuse, is not run again.
#include "gradfric/design/evaluator.hpp"
#include "gradfric/design/fem_check.hpp"
#include "gradfric/design/known_runs.hpp"

#include <mpi.h>

#include <array>
#include <map>
#include <optional>
#include <vector>

namespace gradfric::design {

class FemEvaluator : public DesignModel {
public:
  // mesh: the FEM's options to run (the problem's -fem_* ones, or its coarse copy); acceptance: a
  // run holds the target within this (-design_tolerance, or -design_coarse on the coarse mesh,
  // whose own error exceeds the tolerance anyway).
  FemEvaluator(MPI_Comm comm, const Problem& problem, const FemCheck& mesh, double acceptance)
      : comm_(comm), problem_(problem), mesh_(mesh), acceptance_(acceptance) {}

  // Collective. CollectiveError if the run, or a variation's non-graded run, does not confirm its
  // peak.
  Evaluation evaluate(const std::vector<double>& x, double halfWidth, const std::string& phase,
                      std::uint32_t stream = 0, int atLeast = 0) override;
  // Collective: the plate at x and, for a variation target, the non-graded plate, as they came out
  // (an unconfirmed peak is reported, not thrown): -design_verify_fem.
  FemVerification check(const std::vector<double>& x);
  long realisationsRun() const override { return runs_; }  // FEM runs run, not those taken
  // Takes the known runs on this evaluator's mesh: an evaluation there is not run again.
  void know(const std::vector<KnownFemRun>& runs);
  long runsReused() const { return reused_; }  // known runs an evaluation took (the reference included)
  std::array<int, 3> mesh() const;

private:
  struct Known {
    FemRun run;
    bool taken = false;  // counted once in runsReused
  };
  FemRun& at(const std::vector<double>& x);  // the run at x: known, or run now
  FemRun& reference();                      // the non-graded plate

  MPI_Comm comm_;
  const Problem& problem_;
  const FemCheck& mesh_;
  double acceptance_;
  std::map<std::vector<double>, Known> runsAt_;  // per x
  std::optional<Known> reference_;
  long runs_ = 0, reused_ = 0;
};

}  // namespace gradfric::design
