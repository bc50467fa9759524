#pragma once
// The registry of friction laws. A new law is one header (see coulomb_law.hpp) and one entry in
// GF_FRICTION_LAWS: the option's list of choices, the dispatch to the templated kernels and
// their explicit instantiations all follow from this list. Laws with a per-site state variable
// (state_weakening_law.hpp) are listed in GF_STATE_FRICTION_LAWS: the FEM contact takes both
// lists (fem/contact_law.hpp), and so do both spring-block kernels (the fast one keeps the
// per-block state in src/sbm/block_state.hpp).
#include "gradfric/physics/coulomb_law.hpp"
#include "gradfric/physics/exponential_law.hpp"
#include "gradfric/physics/friction_laws_settings.hpp"
#include "gradfric/physics/state_weakening_law.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#define GF_FRICTION_LAWS(X) \
  X(CoulombStickSlip)       \
  X(ExponentialVelocityWeakening)

#define GF_STATE_FRICTION_LAWS(X) \
  X(StateWeakening)

namespace gradfric {

// withState: also the laws with a per-site state (the FEM's choices).
inline std::vector<std::string> frictionLawNames(bool withState = false) {
  std::vector<std::string> names;
#define GF_LAW_NAME(Law) names.push_back(Law::name);
  GF_FRICTION_LAWS(GF_LAW_NAME)
  if (withState) {
    GF_STATE_FRICTION_LAWS(GF_LAW_NAME)
  }
#undef GF_LAW_NAME
  return names;
}

// Is the named law one with a per-site state and weakening length (GF_STATE_FRICTION_LAWS)?
inline bool isStateLaw(const FrictionLawSettings& settings) {
#define GF_LAW_IS(Law) \
  if (settings.name == Law::name) return true;
  GF_STATE_FRICTION_LAWS(GF_LAW_IS)
#undef GF_LAW_IS
  return false;
}

// Calls visit(law) with the law named in the settings, built on these sites.
template <class Visitor>
decltype(auto) withFrictionLaw(const FrictionLawSettings& settings, FrictionSites sites, Visitor&& visit) {
#define GF_LAW_VISIT(Law) \
  if (settings.name == Law::name) return visit(Law::make(std::move(sites), settings));
  GF_FRICTION_LAWS(GF_LAW_VISIT)
#undef GF_LAW_VISIT
  throw std::invalid_argument("unknown friction law '" + settings.name + "'");
}

// Calls visit(law) with the law with a per-site state named in the settings, built on these sites
// for siteCount sites; returns false (visiting nothing) when the named law has no state.
template <class Visitor>
bool withStateFrictionLaw(const FrictionLawSettings& settings, FrictionSites sites, std::size_t siteCount,
                          Visitor&& visit) {
#define GF_STATE_LAW_VISIT(Law)                                \
  if (settings.name == Law::name) {                            \
    visit(Law::make(std::move(sites), settings, siteCount));   \
    return true;                                               \
  }
  GF_STATE_FRICTION_LAWS(GF_STATE_LAW_VISIT)
#undef GF_STATE_LAW_VISIT
  return false;
}

// The law in words, with its parameters (printed among a run's active effects).
inline std::string describeFrictionLaw(const FrictionLawSettings& settings) {
#define GF_LAW_DESCRIBE(Law) \
  if (settings.name == Law::name) return Law::describe(settings);
  GF_FRICTION_LAWS(GF_LAW_DESCRIBE)
  GF_STATE_FRICTION_LAWS(GF_LAW_DESCRIBE)
#undef GF_LAW_DESCRIBE
  throw std::invalid_argument("unknown friction law '" + settings.name + "'");
}

}  // namespace gradfric
