#!/usr/bin/env bash
# Ensemble throughput on 1 and 2 ranks (a benchmark, not a test): runs a scene -- by default the
# reduced Figure 4 scene, 90 tasks of a 60 x 60 lattice -- with mpiexec -n 1 and -n 2 and reports
# tasks per second, the mean cost of one task and the parallel efficiency
#   E = (tasks/s on n ranks) / (n x tasks/s on 1 rank),
# the share of rank-seconds spent inside tasks ("busy": what start-up, the scheduler and the file
# writes leave idle), the CPU time per task, and E(CPU) = busy x (CPU per task on 1 rank) / (CPU
# per task on n ranks), an estimate of E that other work on the machine does not distort (E
# itself needs an otherwise idle machine; the load average before each run is printed).
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
printf "%6s %7s %9s %9s %11s %10s %14s %12s\n" ranks tasks wall[s] tasks/s efficiency busy "CPU/task[s]" "E(CPU)"
base=""
for n in $(seq 1 "$max"); do
  load=$(cut -d' ' -f1 /proc/loadavg)
  start=$(date +%s.%N)
  /usr/bin/time -f "%U %S" -o "$work/cpu$n.txt" \
    mpiexec --oversubscribe -n "$n" "$driver" -options_file "$scene" -ensemble_monitor 0 -output "$work/r$n.h5" "$@" \
    >"$work/r$n.log"
  end=$(date +%s.%N)
  line=$(grep "task(s) run in" "$work/r$n.log")
  tasks=$(sed -n 's/^\([0-9]*\) task(s) run in.*/\1/p' <<<"$line")
  busy=$(sed -n 's/.*ranks busy \([0-9.]*\) %.*/\1/p' <<<"$line")
  rate=$(sed -n 's/.*: \([0-9.e+-]*\) tasks\/s.*/\1/p' <<<"$line")
  mean=$(sed -n 's/.*mean task \([0-9.e+-]*\) s.*/\1/p' <<<"$line")
  cpu=$(awk -v t="$tasks" '{ printf "%.4f", ($1 + $2) / t }' "$work/cpu$n.txt")  # CPU s per task, all ranks
  [ -n "$base" ] || { base=$rate; basecpu=$cpu; }
  # Efficiency on a dedicated machine, estimated from CPU time (robust to other load): the busy
  # share times the CPU cost of a task on 1 rank over its cost on n ranks.
  ecpu=$(awk -v b="$busy" -v c1="$basecpu" -v c="$cpu" 'BEGIN { printf "%.1f %%", b * c1 / c }')
  eff=$(awk -v r="$rate" -v b="$base" -v n="$n" 'BEGIN { printf "%.1f %%", 100 * r / (n * b) }')
  wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
  printf "%6d %7d %9s %9s %11s %9s%% %14s %12s   (mean task wall %s s, load before %s)\n" "$n" "$tasks" "$wall" \
    "$rate" "$eff" "$busy" "$cpu" "$ecpu" "$mean" "$load"
done
# The files of all rank counts are the same (apart from /run).
for n in $(seq 2 "$max"); do
  h5diff --exclude-path /run "$work/r1.h5" "$work/r$n.h5" >/dev/null && echo "r1.h5 == r$n.h5 (h5diff, /run excluded)"
done
