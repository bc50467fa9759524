#!/usr/bin/env bash
# The FEM accuracy study (-study_model fem) runs from its reduced scene on 2 ranks and writes the
# layout plot_accuracy.py reads: every ladder with its reference rung at zero error, errors finite
# where the run was stable, the SSP rung that blows up recorded as failed (NaN, stopped by the
# monitor) rather than as a number, the mesh estimate, and a plot.
set -eu
driver=$1; source_dir=$2; scratch=$3
mkdir -p "$scratch"; out="$scratch/study_fem.h5"; rm -f "$out"
mpiexec --oversubscribe -n 2 "$driver" -options_file "$source_dir/input/study_fem_reduced.opts" -output "$out" >"$scratch/study_fem.log" 2>&1
grep -q "FAILED: FEM run unstable" "$scratch/study_fem.log"
/usr/bin/python3 - "$out" <<'PY'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
assert f.attrs["format"] == b"gradfric-accuracy-study" or f.attrs["format"] == "gradfric-accuracy-study"
for name in ("dt_gfverlet", "dt_rk4", "dt_ssp", "kn", "kt", "mesh"):
    g = f[name]
    for d in ("setting", "mu_s_error", "mu_k_error", "wall_seconds", "mu_s", "mu_k"):
        assert g[d].shape == g["setting"].shape, (name, d)
    for a in ("knob", "unit", "error_meaning"):
        assert a in g.attrs, (name, a)
v = f["dt_gfverlet"]
assert v["mu_s_error"][0] == 0 and np.all(np.isfinite(v["mu_s_error"][:]))
assert np.all(v["mu_s_error"][1:] < 0.02), v["mu_s_error"][:]
assert np.isfinite(f["dt_rk4"]["mu_s_error"][0]) and f["dt_rk4"]["mu_s_error"][0] < 0.02
assert np.isnan(f["dt_ssp"]["mu_s"][0]), "SSP at 0.9 of the stable step must be stopped by the monitor"
for name in ("kn", "kt", "mesh"):
    e = f[name]["mu_s_error"][:]
    assert e[-1] == 0 and np.all(np.isfinite(e)) and np.all(e < 0.1), (name, e)
assert "estimates" in f["mesh"].attrs
print("fem study checks passed")
PY
/usr/bin/python3 "$source_dir/scripts/plot_accuracy.py" "$out" "$scratch/study_fem.png"
test -s "$scratch/study_fem.png"
