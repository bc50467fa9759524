#include "gradfric/physics/friction_law_options.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/physics/friction_laws.hpp"

namespace gradfric {

namespace {

const char* const kMemoryLengthHelp =
    "normal-stress memory of the state law: slip length L_sigma, in units of D_c, over which the pressure the "
    "strength multiplies follows the contact pressure (0: none; docs/flutter.md: it makes sliding at mu > 1 well-posed)";
const char* const kMemorySpeedHelp =
    "normal-stress memory: reference speed V*, the remembered pressure follows at rest over L_sigma / V*";

// The memory: FEM only (a spring block's normal force is its share of the load, it has no fast
// pressure changes to remember), with the state law (its length is in units of D_c).
void readNormalStressMemory(OptionReader& o, FrictionLawSettings& s, bool withMemory, double thickness) {
  if (!withMemory) {
    const auto length = o.realIfSet("memory_length", "D_c", kMemoryLengthHelp, "0 (FEM only)");
    const auto speed = o.realIfSet("memory_speed", "m/s", kMemorySpeedHelp, formatReal(s.memorySpeed) + " (FEM only)");
    const char* allowed = "unset in the spring-block model (a block's normal force is its share of the load: nothing "
                          "to remember; the memory is the FEM's, docs/flutter.md)";
    if (length) throw InputError(o.fullName("memory_length"), formatReal(*length), allowed);
    if (speed) throw InputError(o.fullName("memory_speed"), formatReal(*speed), allowed);
    return;
  }
  s.memoryLength = o.real("memory_length", s.memoryLength, "D_c", kMemoryLengthHelp);
  o.requireNonNegative("memory_length", s.memoryLength, "D_c");
  if (s.memoryLength > 0 && !isStateLaw(s))
    throw InputError(o.fullName("memory_length"), formatReal(s.memoryLength),
                     "0 with -friction_law " + s.name + " (the memory's length is in units of the state law's D_c)");
  if (s.memoryLength > 0 && thickness > 0 && s.memoryLengthInMetres() > thickness)
    throw InputError(o.fullName("memory_length"), formatReal(s.memoryLength),
                     "0 <= L_sigma <= H / D_c = " + formatReal(thickness / s.slipLength) +
                         " (the memory is an interface length, at most the plate's thickness)");
  if (!(s.memoryLength > 0)) {  // no memory: a speed would change nothing
    if (const auto speed = o.realIfSet("memory_speed", "m/s", kMemorySpeedHelp, formatReal(s.memorySpeed)))
      throw InputError(o.fullName("memory_speed"), formatReal(*speed), "unset without -friction_memory_length > 0");
    return;
  }
  s.memorySpeed = o.real("memory_speed", s.memorySpeed, "m/s", kMemorySpeedHelp);
  o.requireNonNegative("memory_speed", s.memorySpeed, "m/s");
}

}  // namespace

FrictionLawSettings readFrictionLaw(MPI_Comm comm, RunParameters* record, const FrictionLawSettings& modelDefault,
                                    bool withState, double thickness, bool withMemory) {
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
      readNormalStressMemory(o, s, withMemory, thickness);
      return s;
    }
    s.slipLength = o.real("d_c", s.slipLength, "m", help);
    if (o.wasSet("d_c") && !isStateLaw(s))
      throw InputError(o.fullName("d_c"), formatReal(s.slipLength), "only with -friction_law state");
    o.requirePositive("d_c", s.slipLength, "m");
    if (o.wasSet("d_c") && thickness > 0)  // the default is not checked: a bad -plate_H is refused by its own name
      o.requireRange("d_c", s.slipLength, 0.0, thickness, "0 < D_c <= H (the plate's thickness)");
  }
  readNormalStressMemory(o, s, withMemory, thickness);
  return s;
}

}  // namespace gradfric
