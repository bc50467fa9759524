#!/usr/bin/env python3
"""The error bar of every FEM result (error_estimate.hpp): gradfric-fem prints it next to mu_s and
stores it in the results file. A studied mesh (50x50x5 at the defaults) gets the bar that the
study's rows (docs/fem_study.tsv) give, recomputed here independently (GCI of its ladder plus the
thickness, dt and contact pairs); an unstudied one (6x6x2) says "not measured"."""
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


sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from fem_study_table import load  # the study's rows, as the docs' tables read them


def study():
    return load(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "fem_study.tsv"))


def expected_bar(n):
    rows = study()
    key = lambda n, nz=5, dts=0.6, contact="penalty": ("state", 2.5e-8, "none", 0.0, n, nz, "q1", dts, contact)
    f3, f2, f1 = rows[key(50)], rows[key(100)], rows[key(200)]
    p = math.log((f2 - f3) / (f1 - f2)) / math.log(2)
    ext = f1 + (f1 - f2) / (2 ** min(p, 2) - 1)
    mesh = 1.25 * abs(rows[key(n)] - ext) / ext
    ref = rows[key(100)]
    thickness = 1.25 * abs(ref - rows[key(100, nz=10)]) / rows[key(100, nz=10)]
    dt = 1.25 * abs(ref - rows[key(100, dts=0.3)]) / rows[key(100, dts=0.3)]
    contact = 1.25 * abs(ref - rows[key(100, contact="kinematic")]) / rows[key(100, contact="kinematic")]
    return mesh + thickness + dt + contact


bar = expected_bar(50)
out, path = run((50, 50, 5), [], "studied")
line = re.search(r"mu_s \(global\) +([0-9.]+) \+- ([0-9.]+) % \(discretisation: mesh [0-9.]+ %, thickness", out)
if not line:
    fail("studied mesh: no measured error bar next to mu_s", out)
if abs(float(line.group(2)) - 100 * bar) > 0.006:
    fail("printed bar %s %% differs from the study's %.3f %%" % (line.group(2), 100 * bar))
if not re.search(r"mu_k \(kinetic window\) +\S+ \(discretisation error not measured: ", out):
    fail("studied mesh: mu_k without its 'not measured'", out)
with h5py.File(path, "r") as f:
    results = f["results"].attrs
    if abs(results["mu_s"] - float(line.group(1))) > 1e-6:
        fail("stored mu_s %r differs from the printed %s" % (results["mu_s"], line.group(1)))
    if abs(results["mu_s_discretisation_error"] - bar) > 1e-9:
        fail("stored mu_s_discretisation_error %r, expected %r" % (results["mu_s_discretisation_error"], bar))
    basis = results["mu_s_error_basis"]
    basis = basis.decode() if isinstance(basis, bytes) else str(basis)
    if not basis.startswith("mesh ") or "50x50/100/200 x 5" not in basis:
        fail("stored mu_s_error_basis %r" % basis)
    if not math.isnan(results["mu_k_discretisation_error"]):
        fail("stored mu_k_discretisation_error is not NaN")
    if f["results/units"].attrs["mu_s_discretisation_error"] not in (b"1", "1"):
        fail("mu_s_discretisation_error without its unit")

out, path = run((6, 6, 2), [], "unstudied")
if not re.search(r"mu_s \(global\) +[0-9.]+ \(discretisation error not measured: mesh 6x6x2 q1 \(non-graded\) not in the mesh study\)",
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
