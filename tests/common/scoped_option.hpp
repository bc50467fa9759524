#pragma once
// A PETSc option set for the lifetime of a test scope, then cleared.
#include <petscsys.h>

#include <string>

namespace gradfric::testing {

struct ScopedOption {
  std::string name;
  ScopedOption(const char* n, const char* value) : name(n) { PetscOptionsSetValue(nullptr, n, value); }
  ~ScopedOption() { PetscOptionsClearValue(nullptr, name.c_str()); }
};

}  // namespace gradfric::testing
