#pragma once
// The instruction sets the fast spring-block kernel is compiled for (src/sbm/kernel_entries.hpp,
// chosen in kernel_dispatch.cpp): each kernel exists as an AVX-512, an AVX2 and a baseline x86-64
// version with the same arithmetic in the same order, so all three give the same numbers bit for
// bit. The best one the processor supports runs; a test forces each in turn to check that they
// agree.
namespace gradfric::sbm {

enum class KernelIsa { Automatic, Baseline, Avx2, Avx512 };

bool kernelIsaSupported(KernelIsa isa);
// Runs every later step on this version (Automatic: the best supported). False, and nothing
// changed, if the processor does not support it. Not thread-safe: for tests and benchmarks.
bool forceKernelIsa(KernelIsa isa);
KernelIsa kernelIsaInUse();
const char* kernelIsaName(KernelIsa isa);

}  // namespace gradfric::sbm
