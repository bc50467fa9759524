// Regression of the bottom nodal pressure against mu(t) over the loading phase
// (pressure_response_recorder.hpp).
#include "gradfric/fem/pressure_response_recorder.hpp"

#include "gradfric/core/exact_sum.hpp"

#include "gradfric/core/gather.hpp"
#include "gradfric/core/petsc_call.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gradfric::fem {

PressureResponseRecorder::PressureResponseRecorder(const PlateModel& model) {
  // mu(t) stays below the largest local mu_s but for dynamic overshoot: bins up to 1.5 times it.
  const double ceiling = 1.5 * model.contact().largestStaticCoefficient();
  bins_ = static_cast<int>(std::ceil(ceiling / kBinWidth)) + 1;
  nodes_ = model.contact().nodes().size();
  count_.assign(bins_, 0.0);
  sumMu_.assign(bins_, 0.0);
  sumMu2_.assign(bins_, 0.0);
  sumP_.assign(std::size_t(bins_) * nodes_, 0.0);
  sumMuP_.assign(std::size_t(bins_) * nodes_, 0.0);
}

void PressureResponseRecorder::observe(const PlateModel& model) {
  const ContactTotals t = model.contactTotals();  // collective
  const FemParameters& q = model.params();
  const double mu = std::hypot(t.fx, t.fy) / q.plate.normalForce();
  if (!(mu > record_)) return;  // not on the loading branch
  record_ = mu;
  const int bin = static_cast<int>(mu / kBinWidth);
  if (bin >= bins_) return;
  count_[bin] += 1.0;
  sumMu_[bin] += mu;
  sumMu2_[bin] += mu * mu;
  const auto& nodes = model.contact().nodes();
  double* p = sumP_.data() + std::size_t(bin) * nodes_;
  double* mp = sumMuP_.data() + std::size_t(bin) * nodes_;
  for (std::size_t i = 0; i < nodes_; ++i) {
    const double pc = nodes[i].pressure / q.plate.pressure;
    p[i] += pc;
    mp[i] += mu * pc;
  }
}

PressureResponseMap PressureResponseRecorder::finish(const PlateModel& model, double muStatic) const {
  PressureResponseMap m;
  m.window[0] = kWindowLow * muStatic;
  m.window[1] = kWindowHigh * muStatic;
  double n = 0, sumMu = 0, sumMu2 = 0;
  std::vector<double> sumP(nodes_, 0.0), sumMuP(nodes_, 0.0);
  for (int b = 0; b < bins_; ++b) {
    const double centre = (b + 0.5) * kBinWidth;
    if (centre < m.window[0] || centre > m.window[1] || count_[b] == 0) continue;
    n += count_[b];
    sumMu += sumMu_[b];
    sumMu2 += sumMu2_[b];
    for (std::size_t i = 0; i < nodes_; ++i) {
      sumP[i] += sumP_[std::size_t(b) * nodes_ + i];
      sumMuP[i] += sumMuP_[std::size_t(b) * nodes_ + i];
    }
  }
  // The same samples on every rank (mu(t) is global): the same decision everywhere.
  m.samples = static_cast<long long>(n);
  const double variance = sumMu2 - sumMu * sumMu / std::max(n, 1.0);
  if (n < 3 || !(variance > 0))
    throw std::runtime_error("the pressure response needs at least 3 loading steps with mu(t) in [" +
                             std::to_string(m.window[0]) + ", " + std::to_string(m.window[1]) + "] (it has " +
                             std::to_string(m.samples) + ")");
  // This rank's nodes: grid index, slope, area, position.
  const PlateMesh& mesh = model.mesh();
  const FemParameters& q = model.params();
  const int nx = q.nx + 1, ny = q.ny + 1;
  const auto& nodes = model.contact().nodes();
  std::vector<double> local;  // (index, g, area, s) per node
  const double L = q.plate.length, H = q.plate.thickness;
  const double theta = q.plate.angleRadians();
  const double cx = std::cos(theta), cy = std::sin(theta);
  for (std::size_t i = 0; i < nodes_; ++i) {
    const auto& node = nodes[i];
    const double slope = (sumMuP[i] - sumMu * sumP[i] / n) / variance;
    const long long column = mesh.axisX().nearestNode(node.x), row = mesh.axisY().nearestNode(node.y);
    local.insert(local.end(), {double(row * nx + column), slope, node.area,
                               (node.x - 0.5 * L) * cx + (node.y - 0.5 * L) * cy});
  }
  MPI_Comm comm = model.comm();
  int rank = 0;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  const std::vector<double> all = gatherOnRoot(comm, local);
  if (rank != 0) return m;
  m.nx = nx;
  m.ny = ny;
  m.nodeX = mesh.axisX().nodes;
  m.nodeY = mesh.axisY().nodes;
  m.g.assign(std::size_t(nx) * ny, std::nan(""));
  // Exact sums: the gathered nodes come in the partition's order, and the totals must have the
  // same bits on any number of ranks.
  ExactSum mean, moment;
  for (std::size_t k = 0; k + 3 < all.size(); k += 4) {
    m.g[static_cast<std::size_t>(all[k])] = all[k + 1];
    mean.add(all[k + 2] * all[k + 1]);
    moment.add(all[k + 2] * all[k + 3] * all[k + 1]);
  }
  m.mean = mean.value() / (L * L);
  m.momentOverThickness = moment.value() / (L * L * H);
  // Half the edge cells beyond the edge nodes (the uniform mesh's pixel; a graded mesh's map is
  // on its node indices, its pixels unequal).
  const double hx = mesh.axisX().width(0), hy = mesh.axisY().width(0);
  m.extent[0] = -0.5 * hx;
  m.extent[1] = L + 0.5 * hx;
  m.extent[2] = -0.5 * hy;
  m.extent[3] = L + 0.5 * hy;
  return m;
}

}  // namespace gradfric::fem
