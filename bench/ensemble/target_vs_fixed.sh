#!/usr/bin/env bash
# Precision on demand against a fixed count (a benchmark, not a test). Runs a scene -- by default
# the reduced Figure 4 scene on a 30 x 30 lattice, 5 Delta points -- once with -ensemble_target
# and once with the smallest fixed count per point that reaches the same precision at every point
# (found from a fixed run's own data: the first R realisations of every point, the smallest R for
# which each point's 95 % CI half-width meets the target; the fixed run is extended with
# -ensemble_extend until that R exists). Reports realisations, summed task time and wall time of
# both on 2 ranks. Decision rule and options: docs/ensemble.md, "Precision on demand".
# Usage: target_vs_fixed.sh <gradfric driver> [target (default 0.0015)] [absolute|relative|variation]
#        [extra options (default: -sbm_N 30 -ensemble_delta -0.4,-0.2,0,0.2,0.4)...]
set -euo pipefail
driver=$1
target=${2:-0.0015}
kind=${3:-absolute}
shift $(($# < 3 ? $# : 3))
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python=/usr/bin/python3
[ $# -gt 0 ] || set -- -sbm_N 30 -ensemble_delta -0.4,-0.2,0,0.2,0.4
scene=(-options_file "$here/input/sbm_fig4_reduced.opts" -ensemble_monitor 0 "$@")
timed() {  # timed <log> <args...>: runs on 2 ranks, prints the wall seconds
  local log=$1
  shift
  local start end
  start=$(date +%s.%N)
  mpiexec -n 2 "$driver" "${scene[@]}" "$@" >"$log"
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
echo "scene: ${scene[*]}; target $target ($kind); load average $(cut -d' ' -f1 /proc/loadavg)"
wall_target=$(timed "$work/target.log" -ensemble_target "$target" -ensemble_target_type "$kind" -output "$work/target.h5")
grep -E "Target batch|Target met|NOT met" "$work/target.log"
# The smallest fixed count that meets the target at every point, from a fixed run's data.
smallest() {
  "$python" - "$1" "$target" "$kind" <<'PY'
import math, sys
import h5py
import numpy as np
path, target, kind = sys.argv[1], float(sys.argv[2]), sys.argv[3]

def t975(dof):  # Student t quantile by bisection on the regularised incomplete beta (series-free: numeric)
    lo, hi = 0.0, 50.0
    log_c = math.lgamma((dof + 1) / 2) - math.lgamma(dof / 2) - 0.5 * math.log(dof * math.pi)
    def cdf(t):
        xs = np.linspace(0.0, t, 4001)
        pdf = np.exp(log_c - (dof + 1) / 2 * np.log1p(xs * xs / dof))
        return 0.5 + np.trapz(pdf, xs)
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if cdf(mid) < 0.975 else (lo, mid)
    return 0.5 * (lo + hi)

with h5py.File(path, "r") as f:
    mu = f["realisations/mu_s"][()]
    ref = f["sweep/reference_point"][()]
    common = f["scene"].attrs.get("ensemble_common_streams", b"false")
    common = (common.decode() if isinstance(common, bytes) else str(common)) == "true"
P, R = mu.shape
def half(p, n):
    x = mu[p, :n]
    if kind == "variation":
        q = ref[p]
        if q == p:
            return 0.0
        y = mu[q, :n]
        if common:
            z = x / y.mean() - x.mean() * y / y.mean() ** 2
            err = z.std(ddof=1) / math.sqrt(n)
        else:
            err = math.hypot(x.std(ddof=1) / math.sqrt(n) / y.mean(), x.mean() * y.std(ddof=1) / math.sqrt(n) / y.mean() ** 2)
        return t975(n - 1) * err
    h = t975(n - 1) * x.std(ddof=1) / math.sqrt(n)
    return h / abs(x.mean()) if kind == "relative" else h
for n in range(2, R + 1):
    if all(half(p, n) <= target for p in range(P)):
        print(n)
        sys.exit(0)
print(0)
PY
}
counts=$("$python" -c "import h5py,sys; f=h5py.File('$work/target.h5','r'); print(' '.join(map(str,f['statistics/finished'][()])))")
most=$(echo "$counts" | tr ' ' '\n' | sort -n | tail -1)
fixed=$most
wall_probe=$(timed "$work/probe.log" -ensemble_realisations "$fixed" -output "$work/probe.h5")
need=$(smallest "$work/probe.h5")
while [ "$need" -eq 0 ]; do  # not met yet: extend the fixed run by a quarter
  fixed=$((fixed + (fixed + 3) / 4))
  mpiexec -n 2 "$driver" "${scene[@]}" -ensemble_realisations "$fixed" -ensemble_extend -output "$work/probe.h5" >/dev/null
  need=$(smallest "$work/probe.h5")
done
if [ "$need" -eq "$most" ]; then  # the probe was the fixed run: time it as it is
  wall_fixed=$wall_probe
  mv "$work/probe.h5" "$work/fixed.h5"
else
  wall_fixed=$(timed "$work/fixed.log" -ensemble_realisations "$need" -output "$work/fixed.h5")
fi
sum() { "$python" -c "
import h5py, numpy as np
f = h5py.File('$1', 'r'); d = f['realisations/done'][()] != 0
print(int(d.sum()), '%.1f' % np.nansum(np.where(d, f['run/wall_seconds'][()], 0.0)))"; }
read -r tasks_target seconds_target <<<"$(sum "$work/target.h5")"
read -r tasks_fixed seconds_fixed <<<"$(sum "$work/fixed.h5")"
points=$(echo "$counts" | wc -w)
echo "target run:  realisations per point: $counts"
echo "fixed count: $need per point (the smallest meeting the target at every point, same seed)"
printf "%-12s %12s %16s %10s\n" run realisations "task time [s]" "wall [s]"
printf "%-12s %12d %16s %10.1f\n" target "$tasks_target" "$seconds_target" "$wall_target"
printf "%-12s %12d %16s %10.1f\n" fixed "$tasks_fixed" "$seconds_fixed" "$wall_fixed"
echo "ratio fixed/target: realisations $(echo "scale=2; $tasks_fixed / $tasks_target" | bc), wall $(echo "scale=2; $wall_fixed / $wall_target" | bc) ($points points)"
