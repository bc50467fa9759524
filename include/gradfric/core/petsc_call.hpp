#pragma once
// One throwing wrapper around PETSc calls. PETSc here is built as C, so PetscCallThrow does not
// exist; GF_CALL turns a non-zero PetscErrorCode into a gradfric::PetscCallError carrying PETSc's
// own message, the failing expression and where it was called.
#include <petscsys.h>

#include <stdexcept>
#include <string>

namespace gradfric {

class PetscCallError : public std::runtime_error {
public:
  PetscCallError(PetscErrorCode code, const std::string& what) : std::runtime_error(what), code_(code) {}
  PetscErrorCode code() const { return code_; }

private:
  PetscErrorCode code_;
};

[[noreturn]] void throwPetscCallError(PetscErrorCode code, const char* expression, const char* file, int line);

}  // namespace gradfric

#define GF_CALL(...)                                                                   \
  do {                                                                                 \
    PetscErrorCode gf_ierr_ = (__VA_ARGS__);                                           \
    if (PetscUnlikely(gf_ierr_)) ::gradfric::throwPetscCallError(gf_ierr_, #__VA_ARGS__, __FILE__, __LINE__); \
  } while (0)

#define GF_CALL_MPI(...)                                                               \
  do {                                                                                 \
    int gf_mpierr_ = (__VA_ARGS__);                                                    \
    if (PetscUnlikely(gf_mpierr_ != MPI_SUCCESS))                                      \
      ::gradfric::throwPetscCallError(PETSC_ERR_MPI, #__VA_ARGS__, __FILE__, __LINE__);    \
  } while (0)
