#pragma once
// A slip (state) length D_c for a velocity-dependent friction law, as the state variable of
// rate-and-state friction (Ruina's slip law): each site carries its current strength psi, which
// relaxes towards the law's steady value mu_ss(v) (Eq. 1 for the exponential law) over a slip D_c,
//   d psi / d s = -(psi - mu_ss(v)) / D_c     (s the site's slip, v its slip rate),
// integrated exactly over a step of slip ds at speed v:
//   psi' = mu_ss(v) + (psi - mu_ss(v)) exp(-ds / D_c).
// So steady sliding at v gives exactly the law's mu_ss(v); a site that never slipped keeps mu_s
// (psi starts at the static strength); a velocity step relaxes over D_c of slip; a site that stops
// keeps the strength it had (no slip, no change) and heals only by slipping slowly (mu_ss -> mu_s
// as v -> 0). Without a slip length (D_c = 0, the default of the settings) a site that stops is at
// mu_s again at once, which makes steady sliding with a velocity-weakening law unstable at the
// scale of one site at every mesh size (docs/accuracy_fem.md, "The defaults and why").
// D_c = 0 is the underlying law itself, the same arithmetic bit for bit.
//
// Healing only (healingOnly = true): the strength drops to the law's value at once, as the law
// itself (the static peak and every first slip are the law's), and only its rise back towards
// mu_s as a site slows down takes the slip D_c: psi' = mu_ss(v) if mu_ss(v) <= psi, else the
// relaxation above. A site that stops keeps its strength in both forms.
//
// The state is per site and is pending until commit() (a model may evaluate its forces more than
// once per step). The wrapped law is the base: its sites and its sliding strength are the
// wrapper's, and the wrapper answers the questions every law with a per-site state answers
// (friction_law.hpp, "Laws with a per-site state"). Pure arithmetic, no PETSc.
#include "gradfric/core/state_archive.hpp"
#include "gradfric/physics/friction_law.hpp"

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace gradfric {

template <class Law>
struct WithSlipLength : Law {  // Law: the law whose sliding strength at v is the steady value mu_ss(v)
  double slipLength = 0.0;  // D_c [m]; 0: no state, the law itself
  bool healingOnly = false;  // weakening at once (the law's), only healing over D_c
  std::vector<double> strength;  // per site: committed psi (starts at the site's static strength)
  std::vector<double> pending;   // per site: psi after the last evaluation

  // The per-site state saved or restored (checkpoints).
  void archive(StateArchive& a) {
    a.fixedField("law.strength", strength);
    a.fixedField("law.pending", pending);
  }

  static WithSlipLength make(Law law, double slipLength, std::size_t siteCount, bool healingOnly = false) {
    WithSlipLength w{std::move(law), slipLength, healingOnly, {}, {}};
    w.strength.resize(siteCount);
    for (std::size_t i = 0; i < siteCount; ++i) w.strength[i] = w.staticOf(static_cast<int>(i));
    w.pending = w.strength;
    return w;
  }

  bool hasState() const { return slipLength > 0.0; }
  // The strength of a site at its committed state (mu_s without a slip length).
  double committedStrength(int site) const { return hasState() ? strength[site] : staticOf(site); }
  // One evaluation of a site in contact (friction_law.hpp): its strength after strengthAfter(),
  // kept pending.
  double contactStrength(int site, double speed, double slip, double /*dt*/, bool sliding) {
    const double value = strengthAfter(site, speed, slip, sliding);
    if (hasState()) pending[site] = value;
    return value;
  }
  // A site out of contact keeps its committed state.
  void keepOpen(int site) {
    if (hasState()) pending[site] = strength[site];
  }

  // The strength of a site (in the law's units) once it has slipped `slip` [m] at speed `speed`
  // [m/s] since the last commit. sliding = false: the site sticks (no slip; without a slip length
  // it holds up to its static strength, as the law's static threshold).
  double strengthAfter(int site, double speed, double slip, bool sliding) const {
    const int slot = this->sites.slotOfSite(site);
    const double staticStrength = this->sites.staticAt(slot);
    if (!hasState())
      return sliding ? this->slidingStrength(staticStrength, this->sites.kineticAt(slot), speed) : staticStrength;
    if (!sliding) return strength[site];
    const double target = this->slidingStrength(staticStrength, this->sites.kineticAt(slot), speed);
    if (healingOnly && target <= strength[site]) return target;
    if (!(slip > 0.0)) return strength[site];
    return target + (strength[site] - target) * std::exp(-slip / slipLength);
  }
  void commit() {
    if (hasState()) strength = pending;
  }

private:
  double staticOf(int site) const { return this->sites.staticAt(this->sites.slotOfSite(site)); }
};

}  // namespace gradfric
