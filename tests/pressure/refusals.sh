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
s "-pressure_response_file" "dataset '/pressure_response/g'" "gradfric-fem -fem_output" -- -pressure_response fem -pressure_response_file "$source_dir/input/fields/linear_ramp.h5"
s "-pressure_response_file" "finite g everywhere (pixel 1, 4" -- -pressure_response fem -pressure_response_file "$scratch/nan.h5"
s "-pressure_response_file" "covering the plate" -- -pressure_response fem -pressure_response_file "$scratch/small.h5"
# The unloaded trailing edge: a concentration so sharp that a block's pressure turns negative
# before mu(t) reaches -plate_mu_s (120 blocks, lambda = H / 10: g = -1.17 at the trailing edge).
s "-pressure_response_edge = 5e-06" "pressure stays positive up to mu = -plate_mu_s = 1" "x = 2.08333e-05 m" -- -sbm_N 120 -pressure_response moment -pressure_response_edge 5e-6
s "-pressure_respons" "did you mean -pressure_response" -- -pressure_respons moment
# Every rank refuses (no hang, no file).
sbm_expect 2 "-pressure_response_file = (not set)" -- -pressure_response fem
sbm_expect 2 "-pressure_response_edge = 5e-06" "pressure stays positive" -- -sbm_N 120 -pressure_response moment -pressure_response_edge 5e-6

if [ $failures -ne 0 ]; then echo "$failures refusal(s) wrong"; exit 1; fi
echo "all pressure-response refusals correct"
