#!/usr/bin/env bash
# Ensemble throughput on 1 and 2 ranks (a benchmark, not a test): runs a scene -- by default the
# reduced Figure 4 scene, 90 tasks of a 60 x 60 lattice -- with mpiexec -n 1 and -n 2 and reports
# tasks per second, the mean cost of one task and the parallel efficiency
#   E = (tasks/s on n ranks) / (n x tasks/s on 1 rank),
# the share of rank-seconds spent inside tasks ("ranks busy": what start-up, the scheduler and
# the file writes leave idle) and the load average before each run (other work on the machine
# distorts E; run it on an otherwise idle machine).
# Usage: ensemble_scaling.sh <gradfric driver> [scene.opts] [max ranks (default 2)] [extra options...]
set -euo pipefail
driver=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
scene=${2:-$here/input/sbm_fig4_reduced.opts}
max=${3:-2}
shift $(($# < 3 ? $# : 3))
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "scene: $scene $*"
printf "%6s %10s %12s %14s %11s\n" ranks tasks wall[s] tasks/s efficiency
base=""
for n in $(seq 1 "$max"); do
  load=$(cut -d' ' -f1 /proc/loadavg)
  start=$(date +%s.%N)
  mpiexec --oversubscribe -n "$n" "$driver" -options_file "$scene" -ensemble_monitor 0 -output "$work/r$n.h5" "$@" \
    >"$work/r$n.log"
  end=$(date +%s.%N)
  line=$(grep "task(s) run in" "$work/r$n.log")
  tasks=$(sed -n 's/^\([0-9]*\) task(s) run in.*/\1/p' <<<"$line")
  rate=$(sed -n 's/.*: \([0-9.e+-]*\) tasks\/s.*/\1/p' <<<"$line")
  mean=$(sed -n 's/.*mean task \([0-9.e+-]*\) s.*/\1/p' <<<"$line")
  busy=$(sed -n 's/.*ranks busy \([0-9.]*\) %.*/\1/p' <<<"$line")
  [ -n "$base" ] || base=$rate
  eff=$(awk -v r="$rate" -v b="$base" -v n="$n" 'BEGIN { printf "%.1f %%", 100 * r / (n * b) }')
  wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
  printf "%6d %10d %12s %14s %11s   (mean task %s s, ranks busy %s %%, load before %s)\n" "$n" "$tasks" "$wall" \
    "$rate" "$eff" "$mean" "$busy" "$load"
done
# The files of all rank counts are the same (apart from /run).
for n in $(seq 2 "$max"); do
  h5diff --exclude-path /run "$work/r1.h5" "$work/r$n.h5" >/dev/null && echo "r1.h5 == r$n.h5 (h5diff, /run excluded)"
done
