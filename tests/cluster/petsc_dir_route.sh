#!/usr/bin/env bash
# Configures and builds gradfric the way a cluster does: PETSc found through PETSC_DIR/PETSC_ARCH
# (its own lib/pkgconfig/PETSc.pc), with the system's pkg-config files hidden, then runs a small
# ensemble with the driver so built. Without PETSC_DIR the same configure must fail, which shows
# that the system's PETSc really was out of reach.
#   petsc_dir_route.sh <source-dir> <work-dir> <PETSC_DIR> [PETSC_ARCH]
set -euo pipefail
source=$1
work=$2
petsc_dir=$3
petsc_arch=${4:-}
fail() { echo "FAIL: $*" >&2; exit 1; }

empty=$work/empty-pkgconfig
mkdir -p "$empty"
export PKG_CONFIG_LIBDIR=$empty PKG_CONFIG_PATH=$empty
unset PETSC_DIR PETSC_ARCH
launcher=()
if command -v ccache > /dev/null; then
  # Absolute paths in the cache key: this build sits deeper than the main one, so paths made
  # relative to a base folder would differ and nothing would be shared between runs.
  export CCACHE_BASEDIR=
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
# Debug (-O0): what is tested is the route (configure, compile and link against this PETSc, run),
# not the optimiser, and -O0 builds the driver in a fraction of Release's time (no ccache in CI).
common=(-DCMAKE_BUILD_TYPE=Debug -DGRADFRIC_TESTS=OFF -DGRADFRIC_BENCHMARKS=OFF "${launcher[@]}")

rm -rf "$work/no-petsc" "$work/build"
if cmake -S "$source" -B "$work/no-petsc" "${common[@]}" > "$work/no-petsc.log" 2>&1; then
  fail "configure without PETSC_DIR succeeded: the system's PETSc was not hidden"
fi
grep -q "PETSc" "$work/no-petsc.log" || fail "configure without PETSc failed without naming PETSc"

cmake -S "$source" -B "$work/build" "${common[@]}" -DPETSC_DIR="$petsc_dir" -DPETSC_ARCH="$petsc_arch" \
  > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; fail "configure through PETSC_DIR failed"; }
grep -q "gradfric: PETSc 3\.[0-9.]* from PETSC_DIR=$petsc_dir" "$work/configure.log" \
  || { cat "$work/configure.log"; fail "configure did not report the PETSC_DIR route"; }
cmake --build "$work/build" -j 2 --target gradfric_driver > "$work/build.log" 2>&1 \
  || { tail -30 "$work/build.log"; fail "build through PETSC_DIR failed"; }

# A real run: 2 ranks, a small lattice, 2 realisations per point; the results file must complete.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpiexec --oversubscribe -n 2 "$work/build/drivers/gradfric" -options_file "$source/input/default.opts" \
  -sbm_N 12 -ensemble_realisations 2 -output "$work/run.h5" -output_overwrite > "$work/run.log" 2>&1 \
  || { tail -30 "$work/run.log"; fail "the driver built through PETSC_DIR failed to run"; }
[ -f "$work/run.h5" ] && [ ! -e "$work/run.h5.partial" ] || fail "no complete results file"
grep -q "Global static friction mu_s" "$work/run.log" || fail "run printed no mu_s table"
echo "PETSC_DIR route OK: $petsc_dir ${petsc_arch:+(PETSC_ARCH=$petsc_arch)}"
