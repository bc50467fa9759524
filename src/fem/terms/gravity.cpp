// The plate's own weight (-fem_gravity g [m/s^2]; 0, the default: off, the layer not built): a
// body force -m_b g on the z of every node, m_b its lumped mass (lumped_mass.hpp, rho V_cell / 8
// from each cell), so the plane carries p L^2 + rho g H L^2 at rest. It matters for a soft thick
// plate under a small dead load (rho g H = 0.59 Pa at the defaults against p = 1e4 Pa, 59 Pa at
// H = 5 mm). A dead load: it adds no stiffness, so the stable step (stable_step.cpp) is unchanged.
// The worked example of an optional term (term_registry.hpp): this file and its line in terms.def.
#include "gradfric/core/exact_sum.hpp"
#include "gradfric/fem/lumped_mass.hpp"
#include "gradfric/fem/state_view.hpp"
#include "gradfric/fem/term_registry.hpp"

#include <cstdio>
#include <vector>

namespace gradfric::fem {

namespace {

constexpr const char* kName = "gravity";  // the layer, the option -fem_gravity and its setting
constexpr double kOff = 0.0;              // the default

double gravityOf(const FemParameters& q) { return q.terms.get(kName, kOff); }
// The weight's pressure on the plane, rho g H [Pa].
double weightPressure(const FemParameters& q) { return q.plate.density * gravityOf(q) * q.plate.thickness; }

class Gravity : public Layer {
public:
  Gravity(const LumpedMass& mass, const FemParameters& q)
      : g_(gravityOf(q)), weightPressure_(weightPressure(q)), pressure_(q.plate.pressure) {
    for (double m : mass.perBlock()) weight_.push_back(m * g_);
  }

  const char* name() const override { return kName; }
  void addForce(const LayerContext& ctx, Vec X, Vec F, ContactSums& sums) override;
  void addDeadLoad(Vec F) const override { addWeight(F); }
  void postStep(double) override;
  // Minus the work of the weight: m g u_z summed (the work of a constant force along any path),
  // less half of its value at the first accepted step.
  LayerWork work() const override;
  void archive(StateArchive& a) override;
  std::string describe() const override;

private:
  void addWeight(Vec F) const;

  std::vector<double> weight_;            // m_b g per owned block [N]
  double g_, weightPressure_, pressure_;  // g [m/s^2], rho g H and p [Pa] (the description)
  // This rank's sum of m g u_z at the state of the last right-hand side (pending) and of the last
  // accepted step; -m g u_z / 2 at the first accepted step.
  ExactSum pending_, pendingHalf_, committed_, firstHalf_;
  bool started_ = false;
};

void Gravity::addWeight(Vec F) const {
  const WriteState f(F);
  for (PetscInt b = 0; b < static_cast<PetscInt>(weight_.size()); ++b) f.force(b)[2] -= weight_[b];
}

// The energy the weight put in is counted as the pressure's (energy_monitor.cpp: p = 0 before the
// first step), the trapezoid from no weight over the first accepted step: sum m g (-du_z) over the
// steps is then -(m g u_z now) + (m g u_z at the first step) / 2. In a dynamic run that first step
// moves the plate by g dt^2 / 2 (a negligible share); after the static pressure step it is the
// work of the weight loaded with the pressure, half m g u_z, as the elastic energy it holds.
void Gravity::addForce(const LayerContext&, Vec X, Vec F, ContactSums&) {
  addWeight(F);
  pending_ = ExactSum();
  pendingHalf_ = ExactSum();
  const ReadState x(X);
  for (PetscInt b = 0; b < static_cast<PetscInt>(weight_.size()); ++b) {
    const double potential = weight_[b] * x.displacement(b)[2];
    pending_.add(potential);
    if (!started_) pendingHalf_.add(-0.5 * potential);
  }
}

// The right-hand side of the accepted step saw its end state (gfverlet: one evaluation a step).
void Gravity::postStep(double) {
  committed_ = pending_;
  if (!started_) firstHalf_ = pendingHalf_;
  started_ = true;
}

void Gravity::archive(StateArchive& a) {
  a.field("gravity.pending", pending_);
  a.field("gravity.pendingHalf", pendingHalf_);
  a.field("gravity.committed", committed_);
  a.field("gravity.firstHalf", firstHalf_);
  a.field("gravity.started", started_);
}

LayerWork Gravity::work() const {
  LayerWork w;
  w.rankShare = committed_;
  w.rankShare += firstHalf_;
  return w;
}

std::string Gravity::describe() const {
  char text[200];
  std::snprintf(text, sizeof text,
                "own weight, g %.4g m/s^2: rho g H = %.4g Pa (%.3g of p) on the plane, -m g on each node (no "
                "stiffness: the stable step unchanged)",
                g_, weightPressure_, weightPressure_ / pressure_);
  return text;
}

}  // namespace

FemTerm gravityTerm() {
  FemTerm term;
  term.name = kName;
  // A non-finite value is refused by the reader, a negative one here, both naming the option.
  term.readOptions = [](OptionReader& o, FemParameters& q) {
    const double g = o.real(kName, gravityOf(q), "m/s^2",
                            "the plate's own weight: body force -m g on every node, m its lumped mass (9.81 on "
                            "Earth; 0: off)");
    o.requireNonNegative(kName, g, "m/s^2");
    q.terms.set(kName, g);
  };
  term.wanted = [](const FemParameters& q) { return gravityOf(q) > 0; };
  term.build = [](const TermInputs& in) -> std::unique_ptr<Layer> {
    return std::make_unique<Gravity>(in.mass, in.params);
  };
  term.deadLoad = {weightPressure, "rho g H", "the weight's share"};
  return term;
}

}  // namespace gradfric::fem
