#include "gradfric/sbm/log_events.hpp"

#include "gradfric/core/petsc_call.hpp"
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
    PetscClassId id;
    GF_CALL(PetscClassIdRegister("SpringBlock", &id));
    GF_CALL(PetscLogEventRegister("SbmSetup", id, &events[int(Phase::Setup)]));
    GF_CALL(PetscLogEventRegister("SbmStep", id, &events[int(Phase::Step)]));
    GF_CALL(PetscLogEventRegister("SbmSnapshot", id, &events[int(Phase::Snapshot)]));
    return true;
  }();
  (void)registered;
  setPhaseTimer({begin, end});
}

}  // namespace gradfric::sbm
