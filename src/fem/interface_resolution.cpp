#include "gradfric/fem/interface_resolution.hpp"

#include "gradfric/fem/plate_model.hpp"
#include "gradfric/physics/friction_laws.hpp"
#include "gradfric/physics/sliding_dispersion.hpp"

#include <cstdio>

namespace gradfric::fem {

InterfaceResolution checkInterfaceResolution(const PlateModel& model, double peakTime) {
  const FemParameters& q = model.params();
  InterfaceResolution r;
  r.applies = isStateLaw(q.frictionLaw) && q.contact;
  if (!r.applies) return r;
  const Plate& plate = q.plate;
  r.slipLength = q.frictionLaw.slipLength;
  r.kappa = plate.shearModulus() * r.slipLength / (plate.thickness * plate.pressure * (plate.muStatic - plate.muKinetic));
  r.largestStaticCoefficient = model.contact().largestStaticCoefficient();
  if (q.contactMethod == ContactMethod::Penalty) r.elasticSlip = r.largestStaticCoefficient * plate.pressure / q.kt;
  r.largestStepSlip = model.contact().largestSlipPerStep(peakTime);
  r.zone = model.contact().processZone(peakTime);
  char text[300];
  if (r.elasticSlip > r.slipLength / 10) {
    std::snprintf(text, sizeof text, "penalty elastic slip %.3g m > D_c/10 (raise -fem_kt or use -fem_contact kinematic)",
                  r.elasticSlip);
    r.violations.push_back(text);
  }
  if (r.largestStepSlip > r.slipLength / 5) {
    std::snprintf(text, sizeof text, "slip per step up to %.3g m > D_c/5 by the peak (lower -fem_dt_safety)", r.largestStepSlip);
    r.violations.push_back(text);
  }
  // A body sliding on a rigid plane with mu > 1 has a growing interface mode (flutter, contact loss)
  // whose growth rate rises with the wavenumber: every finer mesh admits faster modes
  // (docs/flutter.md). What decides is the mu of the nodes that slide, mu(theta), not their mu_s: a
  // node whose mu_s is above 1 but that sticks until the peak, or weakens below 1 within a fast
  // front, does not feed it. So the flag counts the nodes that slid at mu(theta) > 1 by the peak.
  // The law's normal-stress memory bounds that growth (physics/normal_stress_memory.hpp) where the
  // mesh resolves it: named, and the rule checked below.
  const NormalStressMemory& memory = model.contact().law().normalStress;
  r.withMemory = memory.active();
  // The nodes' own mu_s: a dispersed surface lifts some above the mean (by sigma_s z), so say so.
  r.randomSurface = model.properties().surface().dispersed();
  r.aboveOne = model.contact().slidAboveOne(peakTime, model.mesh().axisX(), model.mesh().axisY());
  if (r.aboveOne.nodes > 0 && r.withMemory && r.aboveOne.fastestRate + memory.speed > 0) {
    const double shearSpeed = std::sqrt(plate.shearModulus() / plate.density);
    r.memoryTime = memory.relaxationTime(r.aboveOne.fastestRate);
    r.cutoffWavelength = memoryCutoffWavelength(r.largestStaticCoefficient, plate.poissonRatio, shearSpeed, r.memoryTime);
    r.baseLayer = model.mesh().hz();
    r.timeStep = model.timeStep();
    const double allowed = r.cutoffWavelength / 8;
    const double element = std::max(r.aboveOne.largestElement, r.baseLayer);
    if (element > allowed) {
      std::snprintf(text, sizeof text,
                    "memory not resolved: elements up to %.3g m (in-plane) and %.3g m (base layer) where nodes slid at "
                    "mu > 1, above lambda_c/8 = %.3g m (refine there, or raise -friction_memory_length to %.3g)",
                    r.aboveOne.largestElement, r.baseLayer, allowed, q.frictionLaw.memoryLength * element / allowed);
      r.violations.push_back(text);
    }
    if (r.timeStep > r.memoryTime / 10) {
      std::snprintf(text, sizeof text, "time step %.3g s > T/10 = %.3g s of the memory (lower -fem_dt_safety)", r.timeStep,
                    r.memoryTime / 10);
      r.violations.push_back(text);
    }
  }
  if (r.aboveOne.nodes > 0 && !r.withMemory) {
    std::snprintf(text, sizeof text,
                  "%ld nodes (%.3g %% of the area) slid at mu > 1 before the peak: there sliding flutters and the onset "
                  "depends on the mesh (lead with the high-friction edge, keep mu_s <= 1, or -friction_memory_length)",
                  r.aboveOne.nodes, 100 * r.aboveOne.areaFraction);
    r.violations.push_back(text);
  }
  if (r.zone.nodes == 0) {
    r.violations.push_back("no process zone measured (no node weakened through a front by the peak)");
  } else if (r.zone.medianElements < 4) {
    std::snprintf(text, sizeof text, "process zone %.2g elements (median) < 4 (refine the mesh)", r.zone.medianElements);
    r.violations.push_back(text);
  }
  return r;
}

std::string InterfaceResolution::describe() const {
  if (!applies) return measures();
  return measures() + ": " + verdict();
}

std::string InterfaceResolution::verdict() const {
  if (!applies) return "no weakening length";
  if (violations.empty()) return "resolved";
  std::string line = "NOT resolved:";
  for (const std::string& v : violations) line += " " + v + ";";
  return line;
}

std::string InterfaceResolution::measures() const {
  if (!applies) return "no weakening length (law without D_c): mu_s does not converge under refinement";
  char text[400];
  std::snprintf(text, sizeof text,
                "D_c %.3g m, kappa %.3g; elastic slip %.2g D_c, slip per step <= %.2g D_c (to the peak), process zone %.3g m "
                "(median, %.2g elements; 10th percentile %.2g elements, %d nodes)",
                slipLength, kappa, elasticSlip / slipLength, largestStepSlip / slipLength, zone.median,
                zone.medianElements, zone.lowElements, zone.nodes);
  std::string line = text;
  if (largestStaticCoefficient > 1.0 + 1e-9) {
    std::snprintf(text, sizeof text, "; local mu_s up to %.3g%s, %ld nodes (%.3g %% of the area) slid at mu > 1 by the peak%s",
                  largestStaticCoefficient, randomSurface ? " (with the random surface)" : "", aboveOne.nodes,
                  100 * aboveOne.areaFraction,
                  withMemory && aboveOne.nodes > 0 ? ", their flutter bounded by the normal-stress memory" : "");
    line += text;
    if (withMemory && aboveOne.nodes > 0) {
      std::snprintf(text, sizeof text, " (T %.3g s at %.3g m/s, lambda_c %.3g m; elements there %.3g m in-plane, %.3g m base layer)",
                    memoryTime, aboveOne.fastestRate, cutoffWavelength, aboveOne.largestElement, baseLayer);
      line += text;
    }
  }
  return line;
}

}  // namespace gradfric::fem
