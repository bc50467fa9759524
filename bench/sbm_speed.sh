#!/usr/bin/env bash
# The spring-block model's speed figures in one run (a benchmark, not a test; issue "a
# spring-block model that pays only for blocks that move"): the kernels' ns per block per step and
# whole realisations stepped from t = 0 against idle work skipped (bench_sbm_kernel), then the
# paper's Figure 4 sweep (input/sbm_fig4.opts: 9 Delta x 20 realisations = 180 tasks of the
# 120 x 120 plate) with -friction_observables mu_s on 2 ranks, idle work skipped (the default)
# and stepped (-sbm_skip_idle 0), with the wall time of each and a check that both files hold the
# same statistics bit for bit. Compare ratios: the machines are shared (the load is printed).
# Usage: sbm_speed.sh <bench_sbm_kernel> <gradfric driver> [ranks (2)] [extra driver options...]
set -euo pipefail
bench=$1
driver=$2
ranks=${3:-2}
shift $(($# < 3 ? $# : 3))
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "== kernels and realisations (load $(cut -d' ' -f1-3 /proc/loadavg))"
"$bench" --benchmark_color=false

sweep() {  # name, extra options: prints the wall time [s]
  local name=$1
  shift
  local start end
  start=$(date +%s.%N)
  mpiexec --oversubscribe -n "$ranks" "$driver" -options_file "$here/input/sbm_fig4.opts" \
    -friction_observables mu_s -ensemble_monitor 0 -output "$work/$name.h5" "$@" >"$work/$name.log"
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }'
}
echo
echo "== Figure 4 sweep, 180 tasks, mu_s only, $ranks ranks (load $(cut -d' ' -f1-3 /proc/loadavg))"
skipped=$(sweep skipped "$@")
echo "idle work skipped: $skipped s wall"
stepped=$(sweep stepped -sbm_skip_idle 0 "$@")
echo "stepped:           $stepped s wall"
awk -v a="$stepped" -v b="$skipped" 'BEGIN { printf "Figure 4 sweep: %.2fx faster with idle work skipped\n", a / b }'
if command -v h5diff >/dev/null; then
  if h5diff -q "$work/skipped.h5" "$work/stepped.h5" /statistics /statistics; then
    echo "/statistics: identical in both files"
  else
    echo "/statistics: the two files differ" >&2
    exit 1
  fi
fi
