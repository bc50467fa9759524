#pragma once
// The friction law of the contact boundary: its strength, any law of the registry
// (physics/friction_laws.hpp), a stateless one wrapped with its optional friction memory
// (slip_state_law.hpp) or a law with its own per-site state (state_weakening_law.hpp); and the
// normal-stress memory of the pressure it multiplies (physics/normal_stress_memory.hpp). One
// variant alternative per registered law, so a new law reaches the FEM through its registry line;
// the contact loops are compiled per law (std::visit once per evaluation, not per node). Pure
// arithmetic, no PETSc.
#include "gradfric/fem/contact_penalty.hpp"
#include "gradfric/physics/friction_laws.hpp"
#include "gradfric/physics/normal_stress_memory.hpp"
#include "gradfric/physics/slip_state_law.hpp"

#include <cstddef>
#include <stdexcept>
#include <type_traits>
#include <variant>

namespace gradfric::fem {

#define GF_CONTACT_MEMORY_LAW(Law) WithSlipLength<Law>,
#define GF_CONTACT_STATE_LAW(Law) Law,
// The trailing monostate only closes the list; it is never built.
using ContactStrength =
    std::variant<GF_FRICTION_LAWS(GF_CONTACT_MEMORY_LAW) GF_STATE_FRICTION_LAWS(GF_CONTACT_STATE_LAW) std::monostate>;
#undef GF_CONTACT_MEMORY_LAW
#undef GF_CONTACT_STATE_LAW

// The friction law of the contact: the strength with its per-site state and the normal-stress
// memory with its own, committed, archived and described as one law.
struct ContactLaw {
  ContactStrength strength;
  NormalStressMemory normalStress;

  template <class Visitor>
  void visitStrength(Visitor&& visit);
  template <class Visitor>
  void visitStrength(Visitor&& visit) const;
  void commit();
  void archive(StateArchive& a);
};

// The strength law named in settings on these sites (siteCount of them); memoryLength, healingOnly:
// the friction memory of a stateless law (-fem_slip_length, -fem_slip_evolution).
inline ContactStrength makeContactStrength(const FrictionLawSettings& settings, FrictionSites sites, std::size_t siteCount,
                                 double memoryLength, bool healingOnly) {
#define GF_MAKE_MEMORY_LAW(Law)                                                                               \
  if (settings.name == Law::name)                                                                             \
    return ContactStrength(WithSlipLength<Law>::make(Law::make(std::move(sites), settings), memoryLength, siteCount, \
                                                healingOnly));
#define GF_MAKE_STATE_LAW(Law) \
  if (settings.name == Law::name) return ContactStrength(Law::make(std::move(sites), settings, siteCount));
  GF_FRICTION_LAWS(GF_MAKE_MEMORY_LAW)
  GF_STATE_FRICTION_LAWS(GF_MAKE_STATE_LAW)
#undef GF_MAKE_MEMORY_LAW
#undef GF_MAKE_STATE_LAW
  throw std::invalid_argument("unknown friction law '" + settings.name + "'");
}

inline ContactLaw makeContactLaw(const FrictionLawSettings& settings, FrictionSites sites, std::size_t siteCount,
                                 double memoryLength, bool healingOnly) {
  return ContactLaw{makeContactStrength(settings, std::move(sites), siteCount, memoryLength, healingOnly),
                    NormalStressMemory::make(settings, siteCount)};
}

// Calls visit(law) with the law the variant holds (visitors return nothing: they write their results).
template <class Variant, class Visitor>
void visitContactLaw(Variant& law, Visitor&& visit) {
  std::visit(
      [&](auto& held) {
        if constexpr (std::is_same_v<std::decay_t<decltype(held)>, std::monostate>)
          throw std::logic_error("contact law not built");
        else
          visit(held);
      },
      law);
}

template <class Visitor>
void ContactLaw::visitStrength(Visitor&& visit) {
  visitContactLaw(strength, visit);
}
template <class Visitor>
void ContactLaw::visitStrength(Visitor&& visit) const {
  visitContactLaw(strength, visit);
}
inline void ContactLaw::commit() {
  visitStrength([](auto& law) { law.commit(); });
  normalStress.commit();
}
inline void ContactLaw::archive(StateArchive& a) {
  visitStrength([&](auto& law) { law.archive(a); });
  normalStress.archive(a);
}

}  // namespace gradfric::fem
