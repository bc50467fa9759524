#pragma once
// Numbers in messages and records: %.10g (PETSc-free, part of the core).
#include <string>

namespace gradfric {

std::string formatReal(double value);

}  // namespace gradfric
