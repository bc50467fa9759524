#!/usr/bin/env bash
# Every refusal of the -pressure_response options, before any work: exit code 2, one message
# naming the option, its value and what is allowed, no results file left; on 2 ranks as well.
# Usage: refusals.sh <gradfric driver> <source dir> <scratch folder>
set -u
sbm=$1
source_dir=$2
scratch=$3
mkdir -p "$scratch"
out="$scratch/refused.h5"
failures=0
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1

# Bad pressure-response maps: a NaN node, an extent short of the plate.
/usr/bin/python3 - "$scratch" <<'PY'
import sys
import h5py, numpy as np
d, L = sys.argv[1], 5e-3
def h5(name, data, extent):
    with h5py.File(f"{d}/{name}", "w") as f:
        ds = f.create_dataset("/pressure_response/g", data=data)
        ds.attrs["extent"] = np.array(extent, dtype=float)
nan = np.zeros((6, 6)); nan[4, 1] = np.nan
h5("nan.h5", nan, (0, L, 0, L))
h5("small.h5", np.zeros((6, 6)), (0, L / 2, 0, L))
# A g on a mesh graded toward the edges: its node positions (format 3) unequally spaced along x.
h5("graded.h5", np.zeros((6, 6)), (-L / 10, L * 1.1, -L / 10, L * 1.1))
with h5py.File(f"{d}/graded.h5", "a") as f:
    f["/pressure_response/node_x"] = np.array([0, 0.5, 1.5, 3.5, 4.5, 5]) * 1e-3
    f["/pressure_response/node_y"] = np.linspace(0, L, 6)
PY

source "$source_dir/tests/common/expect_refusal.sh"
# sbm_expect <ranks> <text the message must contain ...> -- <arguments...>: the spring-block
# driver on a 16 x 16 plate (the arguments may override it).
sbm_expect() {
  local ranks=$1 needles=(); shift
  while [ "$1" != "--" ]; do needles+=("$1"); shift; done
  shift
  expect "$ranks" "$sbm" -output "${needles[@]}" -- -sbm_N 16 "$@"
}
s() { sbm_expect 1 "$@"; }

s "-pressure_response = linear" "none, moment, fem" -- -pressure_response linear
s "-pressure_response_edge = 0" "0 < lambda <= L/2 = 0.0025 [m]" -- -pressure_response moment -pressure_response_edge 0
s "-pressure_response_edge = 0.01" "0 < lambda <= L/2" -- -pressure_response moment -pressure_response_edge 0.01
s "-pressure_response_edge" "inf" -- -pressure_response moment -pressure_response_edge inf
s "-pressure_response_edge = 5e-05" "only with -pressure_response moment" -- -pressure_response_edge 5e-5
s "-pressure_response_edge = 5e-05" "only with -pressure_response moment" -- -pressure_response fem -pressure_response_edge 5e-5 -pressure_response_file "$scratch/nan.h5"
s "-pressure_response_file = $scratch/nan.h5" "only with -pressure_response fem" -- -pressure_response moment -pressure_response_file "$scratch/nan.h5"
s "-pressure_response_file = $scratch/nan.h5" "only with -pressure_response fem" -- -pressure_response_file "$scratch/nan.h5"
s "-pressure_response_file = (not set)" "gradfric-fem results file" -- -pressure_response fem
s "-pressure_response_file = $scratch/missing.h5" "cannot open" -- -pressure_response fem -pressure_response_file "$scratch/missing.h5"
s "-pressure_response_file" "dataset '/pressure_response/g'" "gradfric-fem -output" -- -pressure_response fem -pressure_response_file "$source_dir/input/fields/linear_ramp.h5"
s "-pressure_response_file" "finite g everywhere (pixel 1, 4" -- -pressure_response fem -pressure_response_file "$scratch/nan.h5"
s "-pressure_response_file" "covering the plate" -- -pressure_response fem -pressure_response_file "$scratch/small.h5"
s "-pressure_response_file" "a g measured on a uniform mesh" "node_x spacing runs from 0.0005 to 0.002 m" -- -pressure_response fem -pressure_response_file "$scratch/graded.h5"
# The unloaded trailing edge: a concentration so sharp that a block's pressure turns negative
# before mu(t) reaches 0.8 -plate_mu_s, the top of the FEM's regression window (200 blocks,
# lambda = H / 10: g = -2.0 at the trailing edge).
s "-pressure_response_edge = 5e-06" "pressure stays positive up to mu = 0.8 -plate_mu_s = 0.8" "x = 1.25e-05 m" -- -sbm_N 200 -pressure_response moment -pressure_response_edge 5e-6
s "-pressure_respons" "did you mean -pressure_response" -- -pressure_respons moment
# -pressure_response_select grading: a g for every sweep point's grading, each file once, with its
# /scene record (tests/pressure/make_response_files.py writes the stand-ins).
/usr/bin/python3 "$source_dir/tests/pressure/make_response_files.py" "$scratch" || exit 1
d=$scratch
pair="$d/none.h5,$d/E+0.2.h5"
s "-pressure_response_select = delta" "same, grading" -- -pressure_response fem -pressure_response_file "$d/none.h5" -pressure_response_select delta
s "-pressure_response_select = grading" "only with -pressure_response fem" -- -pressure_response moment -pressure_response_select grading
s "-pressure_response_file = $pair" "one file with -pressure_response_select same" -- -pressure_response fem -pressure_response_file "$pair"
s "-pressure_response_file = $pair," "comma-separated file names, none empty" -- -pressure_response fem -pressure_response_select grading -pressure_response_file "$pair,"
s "-pressure_response_file = $d/noscene.h5" "/scene record" -- -pressure_response fem -pressure_response_select grading -pressure_response_file "$d/noscene.h5"
s "-pressure_response_file = $d/fields.h5" "without property fields" "-field_E_profile power" -- -pressure_response fem -pressure_response_select grading -pressure_response_file "$d/fields.h5"
s "-pressure_response_file = $pair,$d/E+0.2-copy.h5" "one file per grading" -- -pressure_response fem -pressure_response_select grading -pressure_response_file "$pair,$d/E+0.2-copy.h5"
missing=(-grading_profile linear -grading_property E -ensemble_delta 0,0.2,-0.2 -pressure_response fem
         -pressure_response_select grading -pressure_response_file "$pair")
s "-pressure_response_file = $pair" "sweep point 2 (E linear Delta = -0.2, 10 bands, theta = 0) has none" \
  "the files hold non-graded, theta = 0 ($d/none.h5); E linear Delta = 0.2, 10 bands, theta = 0 ($d/E+0.2.h5)" -- "${missing[@]}"
s "sweep point 0 (friction linear Delta = 0.2" "has none" -- -grading_profile linear -grading_property friction -grading_delta 0.2 -pressure_response fem -pressure_response_select grading -pressure_response_file "$pair"
s "sweep point 1 (non-graded, theta = 90) has none" -- -ensemble_theta 0,90 -pressure_response fem -pressure_response_select grading -pressure_response_file "$pair"
sbm_expect 2 "-pressure_response_file = $pair" "sweep point 2 (E linear Delta = -0.2" "has none" -- "${missing[@]}"

# Every rank refuses (no hang, no file).
sbm_expect 2 "-pressure_response_file = (not set)" -- -pressure_response fem
sbm_expect 2 "-pressure_response_edge = 5e-06" "pressure stays positive" -- -sbm_N 200 -pressure_response moment -pressure_response_edge 5e-6

if [ $failures -ne 0 ]; then echo "$failures refusal(s) wrong"; exit 1; fi
echo "all pressure-response refusals correct"
