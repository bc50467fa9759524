#include "gradfric/physics/friction_law_options.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/physics/friction_laws.hpp"

namespace gradfric {

FrictionLawSettings readFrictionLaw(MPI_Comm comm, RunParameters* record, const FrictionLawSettings& modelDefault,
                                    bool withState, double thickness) {
  const char* why = "both models read one friction law";
  refuseRenamedOption("-sbm_friction_law", "-friction_law", why);
  refuseRenamedOption("-sbm_v_c", "-friction_v_c", why);
  refuseRenamedOption("-fem_v_c", "-friction_v_c", why);
  OptionReader o(comm, "friction_", "Friction law (both models)", record);
  FrictionLawSettings s = modelDefault;
  s.name = o.choice("law", s.name, frictionLawNames(withState),
                    withState ? "local friction law: coulomb (static mu_s, kinetic mu_k), exponential (paper Eq. 1: "
                                "mu_k + (mu_s - mu_k) exp(-v/v_c)) or state (Eq. 1 as its steady state, weakening over "
                                "a slip D_c: the length that makes mu_s converge, docs/accuracy_fem.md)"
                              : "local friction law: coulomb (static mu_s, kinetic mu_k: the paper's SBM) or "
                                "exponential (paper Eq. 1: mu_k + (mu_s - mu_k) exp(-v/v_c))");
  s.criticalVelocity = o.real("v_c", s.criticalVelocity, "m/s", "critical velocity v_c of Eq. 1 (exponential, state)");
  o.requirePositive("v_c", s.criticalVelocity, "m/s");
  if (withState) {
    const char* help = "weakening length D_c of the state law: mu falls from mu_s to mu_k over this slip";
    // A model whose default law has no state (the SBM) records D_c only when its law uses it: its
    // stateless scenes keep the /scene they had (a -resume of an older file still matches).
    if (!isStateLaw(modelDefault) && !isStateLaw(s) && !o.wasSet("d_c")) {
      o.realIfSet("d_c", "m", help, formatReal(s.slipLength));  // -help lists it
      return s;
    }
    s.slipLength = o.real("d_c", s.slipLength, "m", help);
    if (o.wasSet("d_c") && !isStateLaw(s))
      throw InputError(o.fullName("d_c"), formatReal(s.slipLength), "only with -friction_law state");
    o.requirePositive("d_c", s.slipLength, "m");
    if (o.wasSet("d_c") && thickness > 0)  // the default is not checked: a bad -plate_H is refused by its own name
      o.requireRange("d_c", s.slipLength, 0.0, thickness, "0 < D_c <= H (the plate's thickness)");
  }
  return s;
}

}  // namespace gradfric
