#include "gradfric/fem/plate_ts.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/verlet_ts.hpp"

#include <string>

namespace gradfric::fem {

namespace {

std::exception_ptr pendingError;  // from the last failed guarded callback

PlateModel& modelOf(TS ts) {
  void* ctx = nullptr;
  GF_CALL(TSGetRHSFunction(ts, nullptr, nullptr, &ctx));
  return *static_cast<PlateModel*>(ctx);
}

PetscErrorCode rhsCallback(TS, PetscReal t, Vec X, Vec F, void* ctx) {
  return guardedCallback([&] { static_cast<PlateModel*>(ctx)->rhs(t, X, F); });
}

}  // namespace

namespace detail {
PetscErrorCode keepCallbackError(std::exception_ptr error, const char* what) {
  pendingError = error;
  return PetscError(PETSC_COMM_SELF, __LINE__, PETSC_FUNCTION_NAME, __FILE__, PETSC_ERR_LIB, PETSC_ERROR_INITIAL, "%s",
                    what);
}
}  // namespace detail

PetscErrorCode layersPostStep(TS ts) {
  return guardedCallback([&] { modelOf(ts).postStep(); });
}

void solvePlateTS(TS ts) {
  pendingError = nullptr;
  const PetscErrorCode code = TSSolve(ts, nullptr);
  if (!code) return;
  if (pendingError) {
    std::exception_ptr error = pendingError;
    pendingError = nullptr;
    std::rethrow_exception(error);
  }
  throwPetscCallError(code, "TSSolve(ts, nullptr)", __FILE__, __LINE__);
}

namespace {

// The type the TS runs: the caller's integrator unless -fem_ts_type overrides it.
void setIntegrator(TS ts, const FemParameters& params) {
  GF_CALL(TSSetType(ts, params.integrator.c_str()));
  if (!params.rkScheme.empty()) GF_CALL(TSRKSetType(ts, params.rkScheme.c_str()));
}

// The kinematic contact predicts the next position from gfverlet's half-step velocity.
void requireGfverletWithKinematicContact(TS ts, const FemParameters& params) {
  TSType type = nullptr;
  GF_CALL(TSGetType(ts, &type));
  if (params.contact && params.contactMethod == ContactMethod::Kinematic && std::string(type) != TSGFVERLET)
    throw InputError("-" + std::string(kPlateTSPrefix) + "ts_type", type,
                     "gfverlet with -fem_contact kinematic (it predicts gfverlet's next step)");
}

}  // namespace

void readPlateTSOptions(MPI_Comm comm, const FemParameters& params) {
  registerVerletTS();
  refuseUnprefixedOptions("ts_", kPlateTSPrefix,
                          "the plate's TS reads its options with the prefix " + std::string(kPlateTSPrefix));
  OwnedTS ts;
  GF_CALL(TSCreate(comm, ts.out()));
  GF_CALL(TSSetOptionsPrefix(ts, kPlateTSPrefix));
  setIntegrator(ts, params);
  const std::string typeOption = "-" + std::string(kPlateTSPrefix) + "ts_type";
  char type[256] = "";
  PetscBool typeGiven = PETSC_FALSE;
  GF_CALL(PetscOptionsGetString(nullptr, nullptr, typeOption.c_str(), type, sizeof type, &typeGiven));
  const PetscErrorCode code = TSSetFromOptions(ts);
  if (code == PETSC_ERR_ARG_UNKNOWN_TYPE && typeGiven)
    throw InputError(typeOption, type, "gfverlet (the default) or a PETSc TS type (rk, ssp, euler, ...)");
  GF_CALL(code);
  requireGfverletWithKinematicContact(ts, params);
  // Viewers TSSolve reads at its start and end: they count as used.
  for (const char* name : {"ts_view", "ts_view_pre", "ts_view_solution"}) {
    PetscBool given = PETSC_FALSE;
    GF_CALL(PetscOptionsHasName(nullptr, kPlateTSPrefix, (std::string("-") + name).c_str(), &given));
  }
}

TS createPlateTS(PlateModel& model, Vec state) {
  registerVerletTS();
  TS ts = nullptr;
  GF_CALL(TSCreate(model.comm(), &ts));
  try {
    GF_CALL(TSSetOptionsPrefix(ts, kPlateTSPrefix));
    GF_CALL(TSSetProblemType(ts, TS_NONLINEAR));
    setIntegrator(ts, model.params());
    GF_CALL(TSSetRHSFunction(ts, nullptr, rhsCallback, &model));
    GF_CALL(TSSetPostStep(ts, layersPostStep));
    GF_CALL(TSSetTimeStep(ts, model.timeStep()));
    GF_CALL(TSSetMaxTime(ts, 1e30));  // the experiment stops itself (TS_CONVERGED_USER); -ts_max_time may stop it earlier
    GF_CALL(TSSetMaxSteps(ts, PETSC_MAX_INT));
    GF_CALL(TSSetExactFinalTime(ts, TS_EXACTFINALTIME_MATCHSTEP));
    GF_CALL(TSSetSolution(ts, state));
    GF_CALL(TSSetFromOptions(ts));
    TSAdapt adapt = nullptr;
    GF_CALL(TSGetAdapt(ts, &adapt));
    GF_CALL(TSAdaptSetType(adapt, TSADAPTNONE));  // fixed step: the stable step is a hard bound
    GF_CALL(TSSetTimeStep(ts, model.timeStep()));
    requireGfverletWithKinematicContact(ts, model.params());
    GF_CALL(TSSetUp(ts));
  } catch (...) {
    TSDestroy(&ts);
    throw;
  }
  return ts;
}

}  // namespace gradfric::fem
