#pragma once
// "gfverlet": velocity Verlet (central difference) as a PETSc TS type, for a state that
// interleaves per node [position (k values), velocity (k values)] with block size 2k and a
// right-hand side [velocity ; acceleration(position, velocity)].
//   v_{n+1/2} = v_n + dt/2 a_n,  x_{n+1} = x_n + dt v_{n+1/2},
//   a_{n+1} = a(x_{n+1}, v_{n+1/2}),  v_{n+1} = v_{n+1/2} + dt/2 a_{n+1}
// One right-hand-side evaluation per step (a_{n+1} is reused as a_n of the next step); the
// velocity-dependent forces (friction, damping) see the half-step velocity. PETSc's own
// TSBASICSYMPLECTIC evaluates the momentum equation with positions only, hence this type.
#include <petscts.h>

namespace gradfric::fem {

inline constexpr const char* TSGFVERLET = "gfverlet";

// Registers the type with PETSc (idempotent). Call after PetscInitialize, before TSSetFromOptions.
void registerVerletTS();

// The acceleration of the last step is reused as the next step's first; after the solution or the
// forces were changed outside the integrator, call TSRestartStep (as for PETSc's FSAL methods).

// For checkpoints: the right-hand side the next step will reuse (null before the first step or
// with another TS type), and, on a set-up gfverlet TS, that vector restored: the next TSSolve's
// first step reuses it as the interrupted run's did, instead of evaluating it again.
Vec verletReusedRhs(TS ts);
void restoreVerletRhs(TS ts, Vec rhs);

}  // namespace gradfric::fem
