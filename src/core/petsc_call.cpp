#include "gradfric/core/petsc_call.hpp"

#include <sstream>

namespace gradfric {

void throwPetscCallError(PetscErrorCode code, const char* expression, const char* file, int line) {
  const char* text = nullptr;
  char* specific = nullptr;
  PetscErrorMessage(code, &text, &specific);
  std::ostringstream message;
  message << "PETSc error " << code;
  if (text) message << " (" << text << ")";
  if (specific && specific[0]) message << ": " << specific;
  message << "\n  in " << expression << "\n  at " << file << ":" << line;
  throw PetscCallError(code, message.str());
}

}  // namespace gradfric
