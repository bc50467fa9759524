#pragma once
// The normal-stress memory of the friction law (-friction_memory_length, -friction_memory_speed;
// Prakash & Clifton 1993): the friction strength of a site is mu times a remembered pressure p*
// that follows the contact pressure p over a slip length L_sigma rather than at once,
//   dp*/dt = (|V| + V*) (p - p*) / L_sigma,
// with V the site's slip rate and V* a reference speed (p* follows p at rest too, over L_sigma / V*).
// Why: a deformable body sliding on a rigid plane under Coulomb friction has a growing interface
// mode at about sqrt(2) c_s when mu > 1, with a growth rate proportional to the wavenumber (the
// problem is ill-posed: every finer mesh admits faster modes). Friction grading puts the local
// mu_s above 1 on one side of the plate. The memory bounds the growth at wavelengths below
// 2 pi c_s T / K_c(mu), T = L_sigma / (|V| + V*) (docs/flutter.md; Ranjith & Rice 2001; Cochard &
// Rice 2000; Kammer et al. 2014; the slip-based form, preferred by Scala et al. 2017, is
// SEM2DPACK's), so a mesh that resolves that wavelength converges (interface_resolution.hpp).
// L_sigma is given in units of the state law's D_c: both are lengths of the interface.
// Only the FEM has a pressure that changes at the scale of a site: the spring-block model refuses
// the memory (a block's normal force is its share of the load).
//
// The law owns the memory's parameters and its per-site state, pending until commit() as the
// state law's (a model may evaluate its forces more than once per step). Pure arithmetic, no PETSc.
#include "gradfric/core/format.hpp"
#include "gradfric/core/state_archive.hpp"
#include "gradfric/physics/friction_laws_settings.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace gradfric {

struct NormalStressMemory {
  double length = 0.0;  // L_sigma [m]; 0: none, the strength follows the pressure at once
  double speed = 0.0;   // V* [m/s]
  double lengthInSlipLengths = 0.0;  // L_sigma as the user gave it [D_c]
  std::vector<double> remembered;  // per site: committed p* (in the model's units: pressure or force)
  std::vector<double> pending;     // per site: p* after the last evaluation

  static NormalStressMemory make(const FrictionLawSettings& settings, std::size_t siteCount) {
    NormalStressMemory m{settings.memoryLengthInMetres(), settings.memorySpeed, settings.memoryLength, {}, {}};
    if (m.active()) m.remembered.assign(siteCount, 0.0), m.pending.assign(siteCount, 0.0);
    return m;
  }

  bool active() const { return length > 0.0; }
  // The run's one description of the memory (the parameters printout and the result file's).
  std::string describe() const {
    if (!active()) return "strength on the present pressure (no normal-stress memory)";
    return "strength on the remembered pressure (normal-stress memory L_sigma " + formatReal(lengthInSlipLengths) +
           " D_c = " + formatReal(length) + " m, V* " + formatReal(speed) + " m/s)";
  }
  // The relaxation time T = L_sigma / (|V| + V*) at slip rate V [m/s] (infinite with neither).
  double relaxationTime(double slipRate) const { return length / (std::fabs(slipRate) + speed); }
  // p* after a step dt [s] at slip rate slipRate [m/s] under pressure p, from `from`: exact for a
  // constant slip rate and pressure over the step (so the step size does not enter the law).
  double relax(double from, double pressure, double slipRate, double dt) const {
    if (!active()) return pressure;
    const double decay = std::exp(-(std::fabs(slipRate) + speed) * dt / length);
    return pressure + (from - pressure) * decay;
  }
  // The committed p* of a site (the pressure itself without a memory: the caller's).
  double rememberedAt(int site, double pressure) const { return active() ? remembered[site] : pressure; }
  void setPending(int site, double value) {
    if (active()) pending[site] = value;
  }
  // A site pressed at rest for long: it remembers its present pressure.
  void settle(int site, double pressure) {
    if (active()) remembered[site] = pending[site] = pressure;
  }
  void commit() {
    if (active()) remembered = pending;
  }
  void archive(StateArchive& a) {
    a.fixedField("law.memory.remembered", remembered);
    a.fixedField("law.memory.pending", pending);
  }
};

}  // namespace gradfric
