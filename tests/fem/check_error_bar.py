#!/usr/bin/env python3
"""The error bar of every FEM result (error_estimate.hpp): gradfric-fem prints it next to mu_s and
mu_k and stores it in the results file. A studied mesh (25x25x5 at dt_safety 0.9: mesh 3.1 %,
dt 1.0 %, contact 0.4 %) gets the measured bar; an unstudied one (6x6x2) says "not measured"."""
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

import h5py

driver = sys.argv[1]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
work = tempfile.mkdtemp(prefix="gradfric_error_bar_")


def run(mesh, extra, name):
    path = os.path.join(work, name + ".h5")
    nx, ny, nz = mesh
    command = ["mpiexec", "--oversubscribe", "-n", "1", driver, "-fem_nx", str(nx), "-fem_ny", str(ny), "-fem_nz",
               str(nz), "-friction_observables", "mu_s", "-fem_output", path] + extra
    r = subprocess.run(command, env=env, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("run failed (%d): %s\n%s" % (r.returncode, " ".join(command), r.stdout + r.stderr))
    return r.stdout, path


def fail(message, text=""):
    shutil.rmtree(work, ignore_errors=True)
    sys.exit(message + ("\n" + text if text else ""))


out, path = run((25, 25, 5), ["-fem_dt_safety", "0.9"], "studied")
line = re.search(r"mu_s \(global\) +([0-9.]+) \+- 4\.5 % \(discretisation: mesh 3\.1 %, dt 1\.0 %, contact 0\.4 %; "
                 r"25x25x5 q1", out)
if not line:
    fail("studied mesh: no measured error bar next to mu_s", out)
if not re.search(r"mu_k \(kinetic window\) +\S+ \(discretisation error not measured: mu_k's bar is its window's spread", out):
    fail("studied mesh: mu_k without its 'not measured'", out)
with h5py.File(path, "r") as f:
    results = f["results"].attrs
    if abs(results["mu_s"] - float(line.group(1))) > 1e-6:
        fail("stored mu_s %r differs from the printed %s" % (results["mu_s"], line.group(1)))
    if abs(results["mu_s_discretisation_error"] - 0.045) > 1e-12:
        fail("stored mu_s_discretisation_error %r, expected 0.045" % results["mu_s_discretisation_error"])
    basis = results["mu_s_error_basis"]
    basis = basis.decode() if isinstance(basis, bytes) else str(basis)
    if not basis.startswith("mesh 3.1 %, dt 1.0 %, contact 0.4 %; 25x25x5 q1"):
        fail("stored mu_s_error_basis %r" % basis)
    if not math.isnan(results["mu_k_discretisation_error"]):
        fail("stored mu_k_discretisation_error is not NaN")
    if f["results/units"].attrs["mu_s_discretisation_error"] not in (b"1", "1"):
        fail("mu_s_discretisation_error without its unit")

out, path = run((6, 6, 2), [], "unstudied")
if not re.search(r"mu_s \(global\) +[0-9.]+ \(discretisation error not measured: mesh 6x6x2 q1 not in the mesh study\)",
                 out):
    fail("unstudied mesh: no 'not measured' next to mu_s", out)
with h5py.File(path, "r") as f:
    results = f["results"].attrs
    if not math.isnan(results["mu_s_discretisation_error"]):
        fail("unstudied mesh: stored error is not NaN")
    basis = results["mu_s_error_basis"]
    basis = basis.decode() if isinstance(basis, bytes) else str(basis)
    if not basis.startswith("not measured: mesh 6x6x2"):
        fail("unstudied mesh: stored basis %r" % basis)

shutil.rmtree(work, ignore_errors=True)
print("error bar OK")
