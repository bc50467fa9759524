#pragma once
// One evaluation of a design problem: a spring-block ensemble of the family's plate at parameter
// values x, run in batches over the ranks of a communicator until the 95 % CI half-width of the
// target's quantity reaches what the search asks for (campaign::planNextBatch), or the cap.
//
// Realisation r of every evaluation draws from the stream (seed, stream, r), and so does the
// reference (non-graded) plate of a Variation target: the evaluations of a search share their
// random numbers (common streams: the differences between parameter values are not drowned in
// noise) and pair with the reference. The verification uses another stream, independent of the
// search. Realisations are kept, so refining an evaluation only runs the new ones. Every value is
// a pure function of its stream key and the decisions depend only on completed values, in a fixed
// order: the same problem and seed give the same evaluations on any number of ranks.
#include "gradfric/design/flutter_exposure.hpp"
#include "gradfric/design/problem.hpp"

#include <mpi.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace gradfric::design {

struct Evaluation {
  int index = 0;              // order in the search (0, 1, ...)
  std::string phase;          // bracket, scan, step, refine, tao, verify
  std::vector<double> x;      // the free parameters' values
  int realisations = 0;
  double value = 0.0;         // the target's quantity: mean mu_s, or the relative variation
  double ciLow = 0.0, ciHigh = 0.0;  // its 95 % CI
  double muStatic = 0.0, muStaticCiLow = 0.0, muStaticCiHigh = 0.0;  // mean mu_s and its CI
  // A deterministic run (the FEM on an undispersed surface): no sampling error, its CI is the
  // value; it holds the target when within `acceptance` (the design's tolerance) of it.
  bool exact = false;
  double acceptance = 0.0;
  FlutterExposure flutter;  // a FEM run's nodes that slid at mu > 1 before the peak
  std::array<int, 3> femMesh{};  // a FEM run's mesh nx, ny, nz (0: not a FEM run)
  bool reused = false;           // a FEM run taken from an earlier design file (-design_reuse)
  double femReference = std::nan("");  // a FEM variation: the non-graded plate's mu_s on its mesh
  double halfWidth() const { return 0.5 * (ciHigh - ciLow); }
  // Where the target lies: +1 below the CI (the value is above it), -1 above it, 0 inside.
  int side(double target) const {
    const double low = exact ? value - acceptance : ciLow, high = exact ? value + acceptance : ciHigh;
    return low > target ? 1 : high < target ? -1 : 0;
  }
};

// What a search evaluates: the spring blocks' ensembles (Evaluator) or the FEM's runs
// (FemEvaluator). Collective over the model's communicator.
class DesignModel {
public:
  virtual ~DesignModel() = default;
  // The target's quantity at x, to a CI half-width `halfWidth` where the model samples (see
  // Evaluator::evaluate); a deterministic model ignores halfWidth, stream and atLeast.
  virtual Evaluation evaluate(const std::vector<double>& x, double halfWidth, const std::string& phase,
                              std::uint32_t stream = 0, int atLeast = 0) = 0;
  virtual long realisationsRun() const = 0;  // spring-block realisations, or FEM runs
};

class Evaluator : public DesignModel {
public:
  Evaluator(MPI_Comm comm, const Problem& problem);

  // Collective. Runs (more) realisations at x from `stream` until the CI half-width is at most
  // `halfWidth` or the cap is reached, reusing the realisations already run there; at least
  // `atLeast` realisations (a search that compares evaluations at one count, whose common streams
  // then make the value a smooth function of x).
  Evaluation evaluate(const std::vector<double>& x, double halfWidth, const std::string& phase,
                      std::uint32_t stream = 0, int atLeast = 0) override;

  long realisationsRun() const override { return realisations_; }  // over all ranks, the reference included
  double taskSeconds() const { return taskSeconds_; }     // summed over the ranks

private:
  // Realisations [sink->size(), count) of one plate (x null: the reference plate).
  struct Batch {
    const std::vector<double>* x;
    std::uint32_t stream;
    int count;
    std::vector<double>* sink;
  };
  // Collective: runs every batch's missing realisations over the ranks (campaign/realisation_pool.hpp)
  // and appends their mu_s.
  void run(const std::vector<Batch>& batches);

  MPI_Comm comm_;
  const Problem& problem_;
  std::map<std::pair<std::uint32_t, std::vector<double>>, std::vector<double>> values_;  // per (stream, x)
  std::map<std::uint32_t, std::vector<double>> reference_;                              // per stream
  int count_ = 0;
  long realisations_ = 0;
  double taskSeconds_ = 0.0;
};

}  // namespace gradfric::design
