#!/usr/bin/env bash
# What -design_reuse saves (a benchmark, not a test): the 3D design of bench_design_fem run twice
# in one go, fresh and with the FEM study table's runs taken (-design_reuse study), and the
# ratio of their wall and CPU times. The two designs must agree to the table's 6 decimals.
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
x = {k: h5py.File(f"{out}/{k}/design_benchmark.h5")["design/x_grading_delta"][0] for k in ("fresh", "reuse")}
print(f"designs: fresh {x['fresh']:.6f}, with the table's runs {x['reuse']:.6f}")
assert abs(x["fresh"] - x["reuse"]) < 1e-5, "the designs differ beyond the table's precision"
for what in ("wall time", "CPU time"):
    print(f"{what}: with the table's runs / fresh = {seconds('reuse', what) / seconds('fresh', what):.2f}")
PY
