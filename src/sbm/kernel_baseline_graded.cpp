// The fast kernel's baseline x86-64 entries at graded stiffness, for every law (with a per-block
// state too) and friction layout (kernel_entries.hpp): a translation unit of their own, compiled in
// parallel with the others.
#include "kernel_step.hpp"

namespace gradfric::sbm {

#define GF_ENTRIES(Law) GF_KERNEL_ENTRY_LAYOUTS(stepBaseline, Law, true)
GF_FRICTION_LAWS(GF_ENTRIES)
GF_STATE_FRICTION_LAWS(GF_ENTRIES)
#undef GF_ENTRIES

}  // namespace gradfric::sbm
