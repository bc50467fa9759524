#include "gradfric/core/log_event.hpp"

#include <map>
#include <string>

namespace gradfric {

PetscLogEvent registerLogEvent(const char* className, const char* name) {
  static std::map<std::string, PetscClassId> classes;
  auto known = classes.find(className);
  if (known == classes.end()) {
    PetscClassId id = 0;
    GF_CALL(PetscClassIdRegister(className, &id));
    known = classes.emplace(className, id).first;
  }
  PetscLogEvent event = 0;
  GF_CALL(PetscLogEventRegister(name, known->second, &event));
  return event;
}

}  // namespace gradfric
