#!/usr/bin/env bash
# A cluster without GoogleTest or Google Benchmark still configures gradfric: the C++ tests and the
# benchmarks are skipped with a warning, the script tests still register (cmake/GradfricDependencies.cmake).
# Configures the source tree into a fresh folder with both packages hidden (configure only, nothing
# built) and checks the warnings, and the test list: script tests present, GoogleTest ones absent.
#   optional_dependencies.sh <source-dir> <work-dir> [cmake -D arguments: compilers, PETSC_DIR ...]
set -euo pipefail
source_dir=$1
work=$2
shift 2
build=$work/build
rm -rf "$build"
mkdir -p "$work"

fail() { echo "FAIL: $*" >&2; exit 1; }
log=$work/configure.log
if ! cmake -S "$source_dir" -B "$build" -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON \
     -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON -DGRADFRIC_REQUIRE_ALL=OFF "$@" > "$log" 2>&1; then
  cat "$log" >&2
  fail "configure without GoogleTest and Google Benchmark failed (output above, kept in $log)"
fi
grep -q "GoogleTest not found: the C++ tests are skipped" "$log" || fail "no warning that the C++ tests are skipped ($log)"
grep -q "Google Benchmark not found: the benchmarks are not built" "$log" || fail "no warning that the benchmarks are skipped ($log)"

tests=$(cd "$build" && ctest -N)
grep -qE "Test +#[0-9]+: cluster_install_tree$" <<< "$tests" || fail "script test cluster_install_tree not registered"
grep -qE "Test +#[0-9]+: ensemble_help$" <<< "$tests" || fail "script test ensemble_help not registered"
if grep -qE "Test +#[0-9]+: (test_unit|test_core_unit|test_core_links_no_petsc_mpi)$" <<< "$tests"; then
  fail "a GoogleTest test registered without GoogleTest"
fi
[ ! -e "$build/bench" ] || fail "bench/ configured without Google Benchmark"
count=$(grep -cE "Test +#[0-9]+:" <<< "$tests" || true)
rm -rf "$build"
echo "optional dependencies OK: configured without GoogleTest and Google Benchmark, $count script tests"
