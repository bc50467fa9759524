#!/usr/bin/env bash
# -pressure_response_select grading through the driver: a Delta sweep with one g per grading gives
# (common random streams, so a point draws as a run of its Delta alone),
# point for point and bit for bit, the runs of each Delta alone with that one file; the same sweep
# with the non-graded g everywhere differs at the graded points (the selection matters); and files
# gradfric-fem writes (10 x 10 x 2, non-graded and E +0.2) are matched on their /scene record.
# Usage: per_grading.sh <gradfric driver> <gradfric-fem driver> <source dir> <scratch folder>
set -u
sbm=$1
fem=$2
source_dir=$3
scratch=$4
mkdir -p "$scratch"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
/usr/bin/python3 "$source_dir/tests/pressure/make_response_files.py" "$scratch" || exit 1
common=(-sbm_N 16 -grading_property E -ensemble_realisations 2 -ensemble_common_streams true -friction_observables mu_s -pressure_response fem
        -output_overwrite)
run() {  # run <log name> <arguments...>
  local log="$scratch/$1.log"; shift
  if ! timeout 300 "$sbm" "${common[@]}" "$@" > "$log" 2>&1; then
    echo "FAIL: gradfric $* exited with $?"; cat "$log"; exit 1
  fi
}
s=$scratch
run sweep -grading_profile linear -ensemble_delta -0.2,0,0.2 -pressure_response_select grading \
    -pressure_response_file "$s/none.h5,$s/E+0.2.h5,$s/E-0.2.h5" -output "$s/sweep.h5"
run same -grading_profile linear -ensemble_delta -0.2,0,0.2 -pressure_response_file "$s/none.h5" -output "$s/same.h5"
run minus -grading_profile linear -grading_delta -0.2 -pressure_response_file "$s/E-0.2.h5" -output "$s/minus.h5"
# the same time step as the sweep (its stiffest band, E x 1.2): a Delta = 0 run beside a graded point
run zero -grading_profile linear -ensemble_delta 0,0.2 -pressure_response_file "$s/none.h5" -output "$s/zero.h5"
run plus -grading_profile linear -grading_delta 0.2 -pressure_response_file "$s/E+0.2.h5" -output "$s/plus.h5"
grep -q "pressure response g on the blocks (E linear Delta = -0.2, 10 bands, theta = 0)" "$s/sweep.log" ||
  { echo "FAIL: the sweep does not print the shape of its strongest point"; cat "$s/sweep.log"; exit 1; }

# Real gradfric-fem files: their /scene record is the key.
for d in 0 0.2; do
  g=(-grading_profile none); [ "$d" = 0 ] || g=(-grading_profile linear -grading_property E -grading_delta "$d")
  if ! timeout 300 "$fem" "${g[@]}" -fem_nx 10 -fem_ny 10 -fem_nz 2 -friction_observables mu_s \
      -output "$s/fem_$d.h5" -output_overwrite > "$s/fem_$d.log" 2>&1; then
    echo "FAIL: gradfric-fem Delta $d exited with $?"; cat "$s/fem_$d.log"; exit 1
  fi
done
run fem -grading_profile linear -ensemble_delta 0,0.2 -pressure_response_select grading \
    -pressure_response_file "$s/fem_0.2.h5,$s/fem_0.h5" -output "$s/fem_sweep.h5"
run fem_one -grading_profile linear -grading_delta 0.2 -pressure_response_file "$s/fem_0.2.h5" -output "$s/fem_one.h5"

/usr/bin/python3 - "$s" <<'PY' || exit 1
import sys
import h5py, numpy as np
d = sys.argv[1]
def mu(name):
    with h5py.File(f"{d}/{name}.h5", "r") as f:
        return f["/realisations/mu_s"][...]
sweep, same = mu("sweep"), mu("same")
ok = True
def check(cond, what):
    global ok
    print(("ok   " if cond else "FAIL ") + what)
    ok = ok and bool(cond)
for k, (name, delta) in enumerate([("minus", -0.2), ("zero", 0.0), ("plus", 0.2)]):
    alone = mu(name)[0]
    check(np.array_equal(sweep[k], alone), f"Delta {delta:+}: sweep point {sweep[k]} = its own run {alone} bit for bit")
check(np.array_equal(sweep[1], same[1]), "the non-graded point is the same with either selection")
check(not np.array_equal(sweep[0], same[0]) and not np.array_equal(sweep[2], same[2]),
      f"the graded points differ from the non-graded g's ({sweep[[0, 2]].ravel()} against {same[[0, 2]].ravel()})")
check(np.array_equal(mu("fem_sweep")[1], mu("fem_one")[0]), "gradfric-fem files: the E +0.2 point takes the E +0.2 run's g")
sys.exit(0 if ok else 1)
PY
echo "each sweep point ran with the g of its grading"
