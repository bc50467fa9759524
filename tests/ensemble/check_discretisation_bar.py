"""The default scene prints and stores the discretisation bar its study proves (docs/accuracy.md,
"The discretisation bar"): at N_b = 120 the mu_s ladder does not converge (no bar, the ladder named),
the graded plate's mu_k does (a bar: lattice + dt terms); the file holds the same numbers, NaN where
not measured, and the basis of each point. Two realisations per point keep it short."""
import math
import os
import re
import subprocess
import sys
import tempfile

import h5py
import numpy as np

driver, src = sys.argv[1:3]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
out = os.path.join(tempfile.mkdtemp(prefix="gradfric_bar_"), "default.h5")
r = subprocess.run(["mpiexec", "--oversubscribe", "-n", "2", driver, "-options_file", os.path.join(src, "input", "default.opts"),
                    "-plot", "false", "-ensemble_realisations", "2", "-ensemble_history", "false", "-output", out],
                   env=env, capture_output=True, text=True)
assert r.returncode == 0, r.stdout + r.stderr
text = r.stdout
# mu_s: both points without a bar, the ladder and its verdict named.
for point in (0, 1):
    assert re.search(rf"point {point}: discretisation error not measured: lattice N_b 120/240/480: .*not converged", text), text
bar = re.search(r"point 1: discretisation \+- ([0-9.]+) % \(lattice ([0-9.]+) %, dt ([0-9.]+) %\): lattice N_b 120/240/480", text)
assert bar, text
total, lattice, step = (float(g) / 100 for g in bar.groups())
assert abs(total - lattice - step) <= 0.0001 and lattice > 0 and step > 0, bar.groups()
row = re.search(r"\n  1 +Delta=0\.2 +2 +0\.6[0-9]+ .*\+- ([0-9.]+)\n", text[text.index("Global kinetic"):])
assert row and abs(float(row.group(1)) / 100 - total) < 1e-4, row
with h5py.File(out, "r") as f:
    st = f["statistics"]
    assert np.isnan(st["mu_s_discretisation_error"][:]).all() and np.isnan(st["mu_s_discretisation_lattice"][:]).all()
    assert np.isfinite(st["mu_s_discretisation_dt"][:]).all()  # the step's term is measured; the lattice's is not
    stored = st["mu_k_discretisation_error"][:]
    assert math.isnan(stored[0]) and abs(stored[1] - total) < 6e-5, stored
    assert abs(st["mu_k_discretisation_lattice"][1] + st["mu_k_discretisation_dt"][1] - stored[1]) < 1e-15
    basis = st["mu_k_discretisation_error"].attrs["basis"].split("\n")
    assert basis[1].startswith("point 1: lattice N_b 120/240/480") and "GCI" in basis[1], basis
    assert "not converged" in basis[0], basis
print("discretisation bar OK")
