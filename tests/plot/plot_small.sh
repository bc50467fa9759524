#!/usr/bin/env bash
# The plotting tool draws a small results file: a Delta sweep with snapshots and first-slip maps,
# asked for by the run itself (-plot). Checks every figure exists and is not blank, that the
# first-slip map it read shows the front starting at the low-friction edge, and that a file that
# is not a results file is refused with a message.
set -eu
driver=$1; source_dir=$2; scratch=$3
rm -rf "$scratch"; mkdir -p "$scratch"
mpiexec --oversubscribe -n 2 "$driver" -grading_profile linear -grading_property friction -sbm_N 16 \
  -ensemble_delta 0,0.3 -ensemble_realisations 2 -sbm_snapshot_times 1.0e-4,1.2e-4,1.4e-4 \
  -output "$scratch/small.h5" -plot -plot_dir "$scratch/figures" >"$scratch/run.log"
for figure in small_mu_t.png small_variation.png small_first_slip.png small_sigma_x.png small_detachment.gif; do
  test -s "$scratch/figures/$figure" || { echo "missing $figure"; exit 1; }
done
/usr/bin/python3 - "$scratch" <<'PY'
import sys, matplotlib.image as image, numpy as np, h5py
scratch = sys.argv[1]
for name in ("small_mu_t", "small_variation", "small_first_slip", "small_sigma_x"):
    pixels = image.imread(f"{scratch}/figures/{name}.png")[..., :3]
    assert pixels.std() > 0.05, f"{name} looks blank"
f = h5py.File(f"{scratch}/small.h5", "r")
first = f["maps/first_slip_time"][1, 0]            # Delta = 0.3: mu grows with x
assert np.nanmean(first[:, :4]) < np.nanmean(first[:, -4:])
print("plot checks passed")
PY
echo "not a results file" > "$scratch/bogus.h5"
if /usr/bin/python3 "$source_dir/scripts/gradfric_plot.py" "$scratch/bogus.h5" 2>"$scratch/err.txt"; then
  echo "a bogus file was accepted"; exit 1
fi
grep -q "bogus.h5" "$scratch/err.txt"
# A FEM sweep without a non-graded point is drawn as single runs against the non-graded run given
# with it: its points must join the FEM curve with their own values (a tiny plate: seconds).
fem_driver=${4:-}
if [ -n "$fem_driver" ]; then
  fem=(-fem_nx 6 -fem_ny 6 -fem_nz 2 -friction_observables mu_s -grading_property friction)
  mpiexec --oversubscribe -n 1 "$fem_driver" "${fem[@]}" -grading_profile none -output "$scratch/fem0.h5" >"$scratch/fem0.log"
  mpiexec --oversubscribe -n 2 "$fem_driver" "${fem[@]}" -grading_profile linear -ensemble_delta 0.3 -output "$scratch/fem_sweep.h5" >"$scratch/fem_sweep.log"
  /usr/bin/python3 "$source_dir/scripts/gradfric_plot.py" "$scratch/small.h5" --fem "$scratch/fem0.h5" "$scratch/fem_sweep.h5" \
    --out "$scratch/figures" --prefix mixed >"$scratch/mixed.log"
  grep -q "mixed_variation.png" "$scratch/mixed.log" || { echo "no variation figure with the FEM sweep"; exit 1; }
  /usr/bin/python3 - "$source_dir" "$scratch" <<'PY'
import sys, h5py, numpy as np
sys.path.insert(0, f"{sys.argv[1]}/scripts")
from gradfric_plot_data import SweepPoint, load, sweep_without_reference
scratch = sys.argv[2]
sweep = load(f"{scratch}/fem_sweep.h5")
assert sweep_without_reference(sweep), "a sweep without a non-graded point has no relative variation"
point = SweepPoint(sweep, 0)
stored = h5py.File(f"{scratch}/fem_sweep.h5", "r")["realisations/mu_s"][0, 0]
assert point.delta == 0.3 and point.results["mu_s"] == stored, (point.delta, point.results["mu_s"], stored)
print("FEM sweep points checked")
PY
fi
