#pragma once
// PETSc log events of an ensemble run (-log_view): the tasks, their writes, the statistics.
#include "gradfric/core/petsc_call.hpp"

#include <petsclog.h>

namespace gradfric::ensemble {

struct LogEvents {
  PetscLogEvent task = 0, write = 0, statistics = 0;
};

inline const LogEvents& logEvents() {
  static LogEvents events = [] {
    LogEvents e;
    PetscClassId id;
    GF_CALL(PetscClassIdRegister("Ensemble", &id));
    GF_CALL(PetscLogEventRegister("EnsTask", id, &e.task));
    GF_CALL(PetscLogEventRegister("EnsH5Write", id, &e.write));
    GF_CALL(PetscLogEventRegister("EnsStatistics", id, &e.statistics));
    return e;
  }();
  return events;
}

}  // namespace gradfric::ensemble
