#pragma once
// PETSc log events of gradfric (-log_view). Every event is named Gf<Component><What> (GfFemRHS,
// GfSbmStep, GfEnsTask), registered once per process under one PETSc class per component, and
// timed by a LogEventScope, which ends the event when the scope is left (also by an exception).
#include "gradfric/core/petsc_call.hpp"

#include <petsclog.h>

namespace gradfric {

// The event `name` of the class `className` (the class registered on its first event). After
// PetscInitialize.
PetscLogEvent registerLogEvent(const char* className, const char* name);

class LogEventScope {
public:
  explicit LogEventScope(PetscLogEvent event) : event_(event) { GF_CALL(PetscLogEventBegin(event_, 0, 0, 0, 0)); }
  ~LogEventScope() { PetscLogEventEnd(event_, 0, 0, 0, 0); }  // a destructor must not throw
  LogEventScope(const LogEventScope&) = delete;
  LogEventScope& operator=(const LogEventScope&) = delete;

private:
  PetscLogEvent event_;
};

}  // namespace gradfric
