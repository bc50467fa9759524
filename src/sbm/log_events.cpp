#include "gradfric/sbm/log_events.hpp"

#include "gradfric/core/log_event.hpp"
#include "gradfric/sbm/model.hpp"

#include <petsclog.h>

namespace gradfric::sbm {

namespace {

PetscLogEvent events[3] = {0, 0, 0};  // indexed by Phase

void begin(Phase phase) { GF_CALL(PetscLogEventBegin(events[int(phase)], 0, 0, 0, 0)); }
void end(Phase phase) { GF_CALL(PetscLogEventEnd(events[int(phase)], 0, 0, 0, 0)); }

}  // namespace

void installLogEvents() {
  static const bool registered = [] {
    events[int(Phase::Setup)] = registerLogEvent("gradfric spring-block", "GfSbmSetup");
    events[int(Phase::Step)] = registerLogEvent("gradfric spring-block", "GfSbmStep");
    events[int(Phase::Snapshot)] = registerLogEvent("gradfric spring-block", "GfSbmSnapshot");
    return true;
  }();
  (void)registered;
  setPhaseTimer({begin, end});
}

}  // namespace gradfric::sbm
