#pragma once
// The FEM's measurement of the load-dependent contact pressure for the spring-block model
// (physics/pressure_response.hpp): g_i = (1/p) d p_c,i / d mu at every bottom node, the slope of
// a least-squares line of the nodal contact pressure against mu(t) = |F(t)| / (p L^2) over the
// loading phase. Only the loading branch is sampled (steps where mu(t) reaches a new maximum: no
// sample after the peak); the samples are kept in bins of mu (width kBinWidth) so that the window
// 0.2 mu_s ... 0.8 mu_s (bins whose centre lies inside it) can be chosen once mu_s is known.
// Written by OutputFiles into the results file as /fem/pressure_response/g, [ny+1][nx+1] on the node
// grid, with the `extent` of a property-field map (pixel centres on the nodes): the SBM reads it
// with -pressure_response fem -pressure_response_file run.h5.
#include "gradfric/fem/plate_model.hpp"
#include "gradfric/physics/pressure_response.hpp"

#include <vector>

namespace gradfric::fem {

struct PressureResponseMap {
  int nx = 0, ny = 0;                // nodes per row and rows: (fem_nx + 1) x (fem_ny + 1)
  std::vector<double> g;             // [ny][nx] row-major
  std::vector<double> nodeX, nodeY;  // the node positions along x (nx) and y (ny) [m]
  double extent[4] = {0, 0, 0, 0};   // x0, x1, y0, y1 [m]: half a cell beyond the plate
  double window[2] = {0, 0};         // the mu window of the regression
  long long samples = 0;             // steps in it
  double mean = 0.0;                 // sum A_i g_i / L^2: 0 if the total normal force holds
  double momentOverThickness = 0.0;  // sum A_i s_i g_i / (L^2 H), s along the sliding direction: 1 by the moment balance
};

class PressureResponseRecorder {
public:
  static constexpr double kBinWidth = 0.02;
  static constexpr double kWindowLow = kResponseWindowLow, kWindowHigh = kResponseWindowHigh;  // fractions of mu_s

  explicit PressureResponseRecorder(const PlateModel& model);  // collective
  // After a step of the sliding phase (collective: the total contact force over ranks).
  void observe(const PlateModel& model);
  // Collective: the regression over the window of muStatic, gathered on rank 0 (other ranks: g empty).
  // Throws std::runtime_error if fewer than 3 steps fall in the window.
  PressureResponseMap finish(const PlateModel& model, double muStatic) const;
  // Saves or restores the sums so far (checkpoints).
  void archive(StateArchive& a) {
    a.field("pressure_response.record", record_);
    a.fixedField("pressure_response.count", count_);
    a.fixedField("pressure_response.sumMu", sumMu_);
    a.fixedField("pressure_response.sumMu2", sumMu2_);
    a.fixedField("pressure_response.sumP", sumP_);
    a.fixedField("pressure_response.sumMuP", sumMuP_);
  }

private:
  int bins_ = 0;
  std::size_t nodes_ = 0;
  double record_ = 0.0;  // the largest mu(t) sampled so far
  std::vector<double> count_, sumMu_, sumMu2_;  // per bin
  std::vector<double> sumP_, sumMuP_;          // per bin and node: [bin][node]
};

}  // namespace gradfric::fem
