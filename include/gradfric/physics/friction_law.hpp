#pragma once
// Friction laws as policy types: pure arithmetic, no PETSc. A law owns its per-site parameters
// (FrictionSites, structure of arrays) and answers two questions, once, for every model built
// on it (the spring-block kernels, fast and reference, and the FEM contact):
//   holds(F^2, s)             static threshold: does a site at rest, static strength s, hold
//                             against a driving force of squared magnitude F^2?
//   slidingStrength(s, k, v)  the friction force (or coefficient) of a site sliding at speed v,
//                             from its static and kinetic strengths s, k.
// "Strength" is in the model's units: the SBM stores forces (mu_s,i F_n, mu_k,i F_n [N]), the
// FEM coefficients (multiplied by the contact pressure). The laws: coulomb_law.hpp,
// exponential_law.hpp; the list the option -friction_law chooses from: friction_laws.hpp.
//
// Laws with a per-site state (the state law, state_weakening_law.hpp, and a stateless law with
// its friction memory, slip_state_law.hpp) own that state and answer, for every model:
//   hasState()                           does it carry a state (a memory of length 0 does not)
//   committedStrength(site)              the strength at the committed state
//   contactStrength(site, v, ds, dt, sliding)
//                                        one evaluation of a site in contact: sliding at v, it slid
//                                        ds [m] over the step dt, else it sticks; the new state is
//                                        pending, its strength returned
//   keepOpen(site)                       a site out of contact keeps its state
//   commit(), archive(StateArchive&)     accept the pending state; save or restore it
// The spring-block kernels also step a state law's theta per block in their rows (state, make,
// decayOver, evolveBySlip, strengthBetween, strengthAt, advance: state_weakening_law.hpp). The
// normal-stress memory of the pressure the strength multiplies is the law's too
// (normal_stress_memory.hpp; the FEM's contact composes the two, fem/contact_law.hpp).
#include <type_traits>
#include <vector>

namespace gradfric {

// Where a law's per-site parameters live: one value for all sites, one per column of a grid
// (rows share it: the SBM's graded means), or one per site. The uniform and per-column layouts
// let the kernels keep a parameter in a register or stream one row of it.
enum class SiteLayout { Uniform, PerColumn, PerSite };

struct FrictionSites {
  SiteLayout layout = SiteLayout::Uniform;
  int columns = 0;                      // sites per row of the grid (PerColumn, PerSite)
  std::vector<double> staticStrength;   // mu_s,i (x F_n for the SBM)
  std::vector<double> kineticStrength;  // mu_k,i (x F_n for the SBM)

  int slot(int row, int column) const {
    switch (layout) {
      case SiteLayout::PerSite: return row * columns + column;
      case SiteLayout::PerColumn: return column;
      default: return 0;
    }
  }
  int slotOfSite(int site) const {  // site = row * columns + column
    switch (layout) {
      case SiteLayout::PerSite: return site;
      case SiteLayout::PerColumn: return site % columns;
      default: return 0;
    }
  }
  double staticAt(int slot) const { return staticStrength[slot]; }
  double kineticAt(int slot) const { return kineticStrength[slot]; }
};

// Does Law keep a per-site state (the interface above)?
template <class Law, class = void>
struct hasSiteState : std::false_type {};
template <class Law>
struct hasSiteState<Law, std::void_t<decltype(&Law::keepOpen)>> : std::true_type {};

// The static threshold shared by the laws: a site at rest holds while |F| <= s (compared in
// squares: no square root in the kernels' stick test).
struct StaticThreshold {
  static bool holds(double drivingForceSquared, double staticStrength) {
    return drivingForceSquared <= staticStrength * staticStrength;
  }
};

}  // namespace gradfric
