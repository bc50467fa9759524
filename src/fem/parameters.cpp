#include "gradfric/fem/parameters.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/physics/friction_laws.hpp"
#include "gradfric/physics/normal_stress_memory.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace gradfric::fem {

const char* contactMethodName(ContactMethod method) {
  return method == ContactMethod::Kinematic ? "kinematic" : "penalty";
}

double FemParameters::penaltySlopeError() const {
  if (!contact || contactMethod != ContactMethod::Penalty) return 0.0;
  const double G = shearModulus(), H = plate.thickness, L = plate.length;
  const double compliance = G / (H * kt) + 12.0 * G * H / (kn * L * L);
  return compliance / (1.0 + compliance);
}

namespace {
// Empty without a memory: a run without one shows nothing about it.
std::string describeMemory(const FemParameters& q) {
  const NormalStressMemory memory = NormalStressMemory::make(q.frictionLaw, 0);
  return memory.active() ? "; " + memory.describe() : "";
}
}  // namespace

std::string describeSurface(const SurfaceSettings& s, double elementSize) {
  if (!s.dispersed()) return "no dispersion: no random surface";
  return describeSurfaceField(s, elementSize, "elements") + ", each node its tributary area's average (seed " +
         std::to_string(s.seed) + ", realisation 0)";
}

std::string describeContact(const FemParameters& q) {
  if (!q.contact) return "none (free bottom face)";
  if (q.contactMethod == ContactMethod::Kinematic)
    return "kinematic (exact: no penetration, exact stick within mu_s p_c A)" + describeMemory(q);
  char text[200];
  std::snprintf(text, sizeof text, "penalty k_n %.3g, k_t %.3g Pa/m (loading slope %.2f %% low)", q.kn, q.kt,
                100.0 * q.penaltySlopeError());
  return text + describeMemory(q);
}

std::string describeFrictionState(const FemParameters& q) {
  if (isStateLaw(q.frictionLaw)) return describeFrictionLaw(q.frictionLaw);
  if (!(q.slipLength > 0)) return "no slip length (a stopped node is back at mu_s)";
  char text[160];
  std::snprintf(text, sizeof text, "slip state: strength follows Eq. 1 over D_c %.3g m of slip (%s)", q.slipLength,
                q.slipHealingOnly ? "weakening at once, healing over D_c" : "slip law");
  return text;
}

std::string describeDamping(const FemParameters& q) {
  std::string text;
  auto add = [&](const std::string& part) { text += (text.empty() ? "" : ", ") + part; };
  char buffer[160];
  if (q.bulkLinear > 0 || q.bulkQuadratic > 0) {
    std::snprintf(buffer, sizeof buffer, "bulk viscosity b1 %.3g, b2 %.3g", q.bulkLinear, q.bulkQuadratic);
    add(buffer);
  }
  if (q.slideDamping > 0) {
    std::snprintf(buffer, sizeof buffer, "mass-proportional %.3g 1/s", q.slideDamping);
    add(buffer);
  }
  if (q.stiffnessDamping > 0) {
    std::snprintf(buffer, sizeof buffer, "stiffness-proportional %.3g s", q.stiffnessDamping);
    add(buffer);
  }
  const char* from = q.peakDampingStart == FemParameters::DampingStart::Confirmed ? "the confirmed peak"
                     : q.peakDampingStart == FemParameters::DampingStart::Drop    ? "the first drop of mu"
                                                                                  : "the start of sliding";
  if (q.peakDamping > 0) {
    std::snprintf(buffer, sizeof buffer, "from %s: mass-proportional towards the slider %.3g 1/s", from, q.peakDamping);
    add(buffer);
  }
  if (q.peakStiffnessDamping > 0) {
    std::snprintf(buffer, sizeof buffer, "from %s: stiffness-proportional %.3g s", from, q.peakStiffnessDamping);
    add(buffer);
  }
  return text.empty() ? "none" : text;
}

double FemParameters::shearWaveSpeed() const { return std::sqrt(shearModulus() / plate.density); }

double defaultPenaltyStiffness(const Plate& plate) {
  return FemParameters::penaltyFactor * plate.shearModulus() / plate.thickness;
}

FrictionMeasurement defaultFemMeasurement(double ts) {
  // The defaults of readFrictionMeasurement (friction_options.cpp) with the FEM's steady window.
  FrictionMeasurement m;
  m.historyInterval = 1e-3 * ts;
  m.kineticDelay = 0.5 * ts;
  m.kineticWidth = 1.0 * ts;
  m.kineticSteadyTolerance = kMukSteadyTolerance;
  m.kineticLatestDelay = std::max(kMukLatestDelay * ts, m.kineticDelay);
  m.peakHold = 0.25 * ts;
  return m;
}

double defaultSlideTime(double ts, const FrictionMeasurement& m, bool withMemory) {
  // 3 t_load with the fixed window or for mu_s alone, as before the steady rule.
  const bool sliding = m.kinetic && m.kineticSteadyTolerance > 0;
  const double window = 1.5 * ts + (sliding ? std::max(m.kineticLatestDelay, m.kineticDelay) : m.kineticDelay) + m.kineticWidth;
  // With the normal-stress memory a leading high-friction patch sticks long after the peak, and
  // the peak is confirmed only once it slipped: at +0.4 its last node slipped 4.5 t_load after t0
  // on 50 x 50 x 5 and 4.8 t_load on 100 x 100 x 10 (docs/studies/fem-memory-friction-points.md),
  // where 3 t_load ended every +Delta run unconfirmed. 9 t_load confirmed every plate of Figures
  // 4 and 8; a confirmed run stops there, so the longer cap costs only runs that never confirm.
  return withMemory ? std::max(window, kMemorySlideLoadingTimes * ts) : window;
}

FemParameters::FemParameters(const Plate& given) : plate(given) {
  const double H = plate.thickness;
  kn = defaultPenaltyStiffness(plate);
  kt = kn;
  edge.band = plate.length / kGradingBands;
  surface.correlationLength = defaultCorrelationLength(plate.length);
  surface.seed = 1;
  const double cs = shearWaveSpeed();
  settleDamping = cs / H;
  peakDamping = cs / H;
  rampTime = 20 * H / cs;
  settleTime = 10 * H / cs;
  measurement = defaultFemMeasurement(eq2PeakTime());
  slideTime = defaultSlideTime(eq2PeakTime(), measurement, frictionLaw.memoryLength > 0);
}

}  // namespace gradfric::fem
