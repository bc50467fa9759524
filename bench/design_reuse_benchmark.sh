#!/usr/bin/env bash
# What -design_reuse saves (a benchmark, not a test): the 3D design of bench_design_fem run twice
# in one go, fresh and with the FEM study table's runs taken (-design_reuse study), and the
# ratio of their wall and CPU times, and the two designs side by side. Both must be found; where
# the FEM's mu_s is smooth in the parameter they agree to the table's 6 decimals, where it is not
# (a friction-graded -Delta plate without the memory) the 7th decimal can move the search.
# Usage: design_reuse_benchmark.sh <gradfric-design> <output folder> [design options...]
set -euo pipefail
design=$1
out=$2
shift 2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$out"
for kind in fresh reuse; do
  extra=()
  [ "$kind" = reuse ] && extra=(-design_reuse study)
  echo "== $kind"
  bash "$here/design_benchmark.sh" "$design" "$out/$kind" 2 "$@" "${extra[@]}" | tee "$out/$kind.txt" |
    grep -E "^(Design|  [0-9]+ FEM runs|wall time|CPU time|load average)"
done
/usr/bin/python3 - "$out" <<'PY'
import re, sys, h5py
out = sys.argv[1]
def seconds(kind, what):
    return float(re.search(what + r"[^:]*: ([0-9.]+) s", open(f"{out}/{kind}.txt").read()).group(1))
for k in ("fresh", "reuse"):
    d = h5py.File(f"{out}/{k}/design_benchmark.h5")["design"]
    print(f"design {k}: grading_delta {d['x_grading_delta'][0]:.6f}, value {d['value'][0]:.6f}")
for what in ("wall time", "CPU time"):
    print(f"{what}: with the table's runs / fresh = {seconds('reuse', what) / seconds('fresh', what):.2f}")
PY
