#!/usr/bin/env bash
# FEM ensemble throughput (a benchmark, not a test): R realisations (default 20) of the random
# surface (sigma 2.8 %, l_c L/120) on the default plate meshed 50 x 50 x 5, run three ways in one
# benchmark run:
#   serial      1 rank                     (the reference)
#   groups      n groups of 1 rank         (-fem_sweep_ranks_per_run 1: realisations side by side)
#   one group   1 group of n ranks         (-fem_sweep_ranks_per_run n: each run domain-decomposed)
# and reports each wall time, the speed-up and the parallel efficiency E = T_serial / (n T), the
# share of rank-seconds inside runs ("busy": start-up and the file's writes leave the rest), and
# that the three files are the same (h5diff without /run). E needs an otherwise idle machine; the
# load average before each run is printed.
# Usage: fem_ensemble.sh <gradfric-fem> [realisations (20)] [ranks (2)] [extra options...]
set -euo pipefail
driver=$1
R=${2:-20}
n=${3:-2}
shift $(($# < 3 ? $# : 3))
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene=(-fem_nx 50 -fem_ny 50 -fem_nz 5 -surface_sigma_s 0.028 -surface_sigma_k 0.028 -ensemble_realisations "$R" "$@")
echo "scene: ${scene[*]}"
printf "%-10s %6s %8s %9s %9s %11s %8s\n" layout ranks groups wall[s] speed-up efficiency busy
serial=""
run() {  # name, ranks, ranks per run
  local name=$1 ranks=$2 per=$3 load start end
  load=$(cut -d' ' -f1 /proc/loadavg)
  start=$(date +%s.%N)
  mpiexec --oversubscribe -n "$ranks" "$driver" "${scene[@]}" -fem_sweep_ranks_per_run "$per" -output "$work/$name.h5" \
    >"$work/$name.log" 2>&1
  end=$(date +%s.%N)
  local wall inside
  wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
  # Rank-seconds inside runs: each run's wall (its group's leader) times the group's ranks.
  inside=$(/usr/bin/python3 -c "import h5py,sys; f=h5py.File(sys.argv[1],'r'); print(float(f['run/wall_seconds'][...].sum()))" \
    "$work/$name.h5")
  [ -n "$serial" ] || serial=$wall
  awk -v name="$name" -v r="$ranks" -v g=$((ranks / per)) -v w="$wall" -v s="$serial" -v i="$inside" -v p="$per" -v l="$load" \
    'BEGIN { printf "%-10s %6d %8d %9.1f %9.2f %10.1f%% %7.1f%%   (load before %s)\n", name, r, g, w, s / w, 100 * s / (r * w), 100 * i * p / (r * w), l }'
}
run serial 1 1
run groups "$n" 1
run one_group "$n" "$n"
for name in groups one_group; do
  h5diff --exclude-path /run "$work/serial.h5" "$work/$name.h5" >/dev/null && echo "serial.h5 == $name.h5 (h5diff, /run excluded)" ||
    echo "serial.h5 and $name.h5 DIFFER"
done
grep -A4 "^FEM sweep results" "$work/groups.log"
