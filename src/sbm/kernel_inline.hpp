#pragma once
// Private to the fast spring-block kernel (fast_lattice*.hpp, kernel_dispatch.cpp): its row
// functions are forced inline so that each per-ISA entry point (kernel_dispatch.cpp) compiles
// them for its own instruction set.
#define GF_ALWAYS_INLINE __attribute__((always_inline)) inline
