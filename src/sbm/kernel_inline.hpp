#pragma once
// Private to the fast spring-block kernel (fast_lattice.cpp, kernel_step.hpp): its row
// functions are forced inline so that each per-ISA entry (kernel_entries.hpp) compiles them for
// its own instruction set.
#define GF_ALWAYS_INLINE __attribute__((always_inline)) inline
