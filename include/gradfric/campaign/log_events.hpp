#pragma once
// PETSc log events of a campaign run (-log_view): the tasks, their writes, the statistics.
#include "gradfric/core/log_event.hpp"

namespace gradfric::campaign {

struct LogEvents {
  PetscLogEvent task = 0, write = 0, statistics = 0;
};

inline const LogEvents& logEvents() {
  static LogEvents events = [] {
    LogEvents e;
    e.task = registerLogEvent("gradfric ensemble", "GfEnsTask");
    e.write = registerLogEvent("gradfric ensemble", "GfEnsH5Write");
    e.statistics = registerLogEvent("gradfric ensemble", "GfEnsStatistics");
    return e;
  }();
  return events;
}

}  // namespace gradfric::campaign
