#!/usr/bin/env bash
# A one-parameter design on the paper's plate (a benchmark, not a test): gradfric-design on
# input/design_friction_delta.opts (120 x 120 blocks, linear friction grading, target mu_s = 0.8
# +- 0.002) on 2 ranks. Reports the wall time, the CPU time of all ranks (less sensitive than the
# wall time to other work on a shared machine), the load average before and after (compare wall
# times only on an idle machine), the realisations spent (the verification included), the design
# and its verification; keeps the design file, its log and its search plot in the output folder.
# Usage: design_benchmark.sh <gradfric-design> [output folder (default: a temporary one)] [ranks (2)] [extra options...]
set -euo pipefail
design=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=${2:-$(mktemp -d)}
ranks=${3:-2}
shift $(($# < 3 ? $# : 3))
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
start=$(date +%s.%N)
status=0
/usr/bin/time -f "%U %S" -o "$out/cpu.txt" mpiexec --oversubscribe -n "$ranks" "$design" -options_file "$here/input/design_friction_delta.opts" \
  -output "$out/design_benchmark.h5" -output_overwrite "$@" >"$out/design_benchmark.log" 2>&1 || status=$?
end=$(date +%s.%N)
echo "load average after:  $(cut -d' ' -f1-3 /proc/loadavg)"
[ "$status" -eq 0 ] || { tail -20 "$out/design_benchmark.log"; echo "gradfric-design exited with $status"; exit 1; }
sed -n '/^Design (/,$p' "$out/design_benchmark.log"
grep -c "^  eval" "$out/design_benchmark.log" | sed 's/^/evaluations logged: /'
printf "wall time on %d rank(s): %.1f s\n" "$ranks" "$(echo "$end - $start" | bc -l)"
read -r user system < "$out/cpu.txt"
printf "CPU time (all ranks, user + system): %.1f s\n" "$(echo "$user + $system" | bc -l)"
/usr/bin/python3 "$here/scripts/plot_design.py" "$out/design_benchmark.h5" --out "$out"
