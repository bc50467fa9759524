#!/usr/bin/env bash
# The FEM-written pressure response on a reduced mesh (10 x 10 x 2, 2 ranks): /fem/pressure_response/g
# is a map on the node grid with the extent of a property-field map, its area-weighted mean is
# zero (the total normal force holds) and its first moment along the sliding direction is H (the
# moment balance), recomputed here from the map itself; the leading edge gains, the trailing edge
# loses. Then the spring-block model reads it (-pressure_response fem) and runs.
# Usage: fem_response.sh <gradfric driver> <gradfric-fem driver> <scratch folder>
set -u
sbm=$1
fem=$2
scratch=$3
mkdir -p "$scratch"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
run="$scratch/fem.h5"
rm -f "$run"
if ! timeout 300 mpiexec -n 2 "$fem" -fem_nx 10 -fem_ny 10 -fem_nz 2 -friction_observables mu_s \
    -output "$run" > "$scratch/fem.log" 2>&1; then
  echo "FAIL: gradfric-fem exited with $?"; cat "$scratch/fem.log"; exit 1
fi
/usr/bin/python3 - "$run" <<'PY' || exit 1
import sys
import h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    d = f["/fem/pressure_response/g"]
    g = d[...]
    x0, x1, y0, y1 = d.attrs["extent"]
    mean_attr, moment_attr = float(d.attrs["mean"]), float(d.attrs["moment_over_H"])
    window = d.attrs["mu_window"]
    samples = int(d.attrs["samples"])
    mu_s = float(f["/realisations/mu_s"][0, 0])
L, H = 5e-3, 5e-5
ok = True
def check(cond, what):
    global ok
    print(("ok   " if cond else "FAIL ") + what)
    ok = ok and bool(cond)
check(g.shape == (11, 11), f"g on the 11 x 11 node grid (shape {g.shape})")
check(np.all(np.isfinite(g)), "g finite at every node")
h = L / 10
check(np.allclose([x0, x1, y0, y1], [-h / 2, L + h / 2, -h / 2, L + h / 2]), "extent: pixel centres on the nodes")
check(np.allclose(window, [0.2 * mu_s, 0.8 * mu_s]), f"regression window 0.2 .. 0.8 mu_s ({window})")
check(samples >= 100, f"{samples} loading steps in the window")
# Nodal areas of the bottom face (trapezoid weights), recomputed here.
w = np.ones(11); w[0] = w[-1] = 0.5
area = np.outer(w, w) * h * h
x = np.arange(11) * h - L / 2
mean = (area * g).sum() / L**2
moment = (area * g * x[None, :]).sum() / (L**2 * H)
scale = np.abs(g).max()
check(abs(mean - mean_attr) < 1e-9 * scale and abs(moment - moment_attr) < 1e-9, "the file's mean and moment_over_H")
check(abs(mean) < 0.01 * scale, f"zero area-weighted mean: {mean:.3e} (max |g| {scale:.3f})")
check(abs(moment - 1.0) < 0.05, f"first moment sum A x g / (L^2 H) = {moment:.4f}, the moment balance says 1")
check(g[:, -1].mean() > 0.1 and g[:, 0].mean() < -0.1, f"leading edge gains ({g[:, -1].mean():.3f}), trailing loses ({g[:, 0].mean():.3f})")
check(np.allclose(g, g[::-1, :], atol=0.02 * scale), "symmetric across the sliding direction (y -> L - y)")
sys.exit(0 if ok else 1)
PY
log="$scratch/sbm.log"
if ! timeout 300 "$sbm" -sbm_N 16 -ensemble_realisations 1 -pressure_response fem -pressure_response_file "$run" \
    -output "$scratch/sbm.h5" -output_overwrite > "$log" 2>&1; then
  echo "FAIL: gradfric -pressure_response fem exited with $?"; cat "$log"; exit 1
fi
grep -q "g measured by gradfric-fem ($run:/fem/pressure_response/g)" "$log" || { echo "FAIL: effect not printed"; cat "$log"; exit 1; }
grep -q "ended at or before the first slip under the rising load" "$log" || { echo "FAIL: quiet-phase effect not printed"; exit 1; }
echo "pressure response written by the FEM and read by the SBM"
