#!/usr/bin/env bash
# The accuracy study runs from its reduced scene on 2 ranks and finds what it must: the time-step
# error shrinks with dt for both integrators, the realisations ladder's error falls as 1/sqrt(R),
# and the plot script draws the file.
set -eu
driver=$1; source_dir=$2; scratch=$3
mkdir -p "$scratch"; out="$scratch/study.h5"; rm -f "$out"
mpiexec --oversubscribe -n 2 "$driver" -options_file "$source_dir/input/study_sbm_reduced.opts" -output "$out" >"$scratch/study.log"
/usr/bin/python3 - "$out" <<'PY'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
for name in ("dt_rk4", "dt_verlet"):
    e = f[name]["mu_s_error"][:]; k = f[name]["mu_k_error"][:]; dt = f[name]["setting"][:]
    assert np.all(np.diff(dt) > 0), dt
    assert e[-1] > e[1] > 0 and k[-1] > k[1] > 0, (name, e, k)      # coarser step, larger error
    assert e[1] < 1e-3 and k[1] < 1e-3, (name, e, k)                 # 5e-8 s: within 0.1 %
w_rk4, w_verlet = f["dt_rk4"]["wall_seconds"][:], f["dt_verlet"]["wall_seconds"][:]
assert w_verlet.sum() < w_rk4.sum(), (w_verlet, w_rk4)                # one force sweep a step, not four
r = f["R"]; e = r["mu_s_error"][:]; R = r["setting"][:]
assert np.allclose(e * np.sqrt(R), e[0], rtol=1e-12), e               # statistical error ~ 1/sqrt(R)
n = f["N"]; assert n["mu_s_error"][-1] == 0 and n["setting"][-1] == 20
print("study checks passed")
PY
/usr/bin/python3 "$source_dir/scripts/plot_accuracy.py" "$out" "$scratch/study.png"
test -s "$scratch/study.png"
