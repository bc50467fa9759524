#!/usr/bin/env python3
"""The error bar of every FEM result (error_estimate.hpp): gradfric-fem prints it next to mu_s and
stores it in the results file. The study's rows (docs/fem_study.tsv), judged here by the ladder rule
written out on its own: the mesh and time-step ladders converge, the thickness ladder (nz 5/10/20)
does not, so the studied 50x50x5 mesh gets no bar and names the thickness ladder (printed and
stored, NaN); an unstudied one (6x6x2) says "not measured" naming every term it lacks."""
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


def converges(mu):
    """The error bar's ladder rule, written out on its own (src/fem/error_estimate.cpp ladderTerm):
    the second difference below 1/sqrt(2) of the first."""
    return abs(mu[2] - mu[1]) < abs(mu[1] - mu[0]) / math.sqrt(2)


rows = study()
key = lambda n, nz=5, dts=0.6: ("state", 2.5e-8, "none", 0.0, n, nz, "q1", dts, "penalty")
mesh = [rows[key(n)] for n in (50, 100, 200)]
thickness = [rows[key(100, nz=nz)] for nz in (5, 10, 20)]
dt = [rows[key(100, dts=d)] for d in (0.6, 0.3, 0.15)]
if not converges(mesh) or not converges(dt) or converges(thickness):
    fail("the study's ladders: expected mesh and dt to converge and the thickness not: %r %r %r" % (mesh, dt, thickness))

# The studied 50x50x5 mesh: its mesh and dt terms are bounded, its thickness term is not (nz 5/10/20
# grows), so it gets no bar and says why.
out, path = run((50, 50, 5), [], "studied")
line = re.search(r"mu_s \(global\) +([0-9.]+) \(discretisation error not measured: thickness not converged: "
                 r"nz 5/10/20 \(non-graded 100x100\) give 0\.936322, 0\.937429, 0\.940538", out)
if not line:
    fail("studied mesh: no 'not measured' naming the thickness ladder next to mu_s", out)
if not re.search(r"mu_k \(kinetic window\) +\S+ \(discretisation error not measured: ", out):
    fail("studied mesh: mu_k without its 'not measured'", out)
with h5py.File(path, "r") as f:
    results = f["results"].attrs
    if abs(results["mu_s"] - float(line.group(1))) > 1e-6:
        fail("stored mu_s %r differs from the printed %s" % (results["mu_s"], line.group(1)))
    if not math.isnan(results["mu_s_discretisation_error"]):
        fail("stored mu_s_discretisation_error %r, expected NaN" % results["mu_s_discretisation_error"])
    basis = results["mu_s_error_basis"]
    basis = basis.decode() if isinstance(basis, bytes) else str(basis)
    if not basis.startswith("not measured: thickness not converged: nz 5/10/20"):
        fail("stored mu_s_error_basis %r" % basis)
    if not math.isnan(results["mu_k_discretisation_error"]):
        fail("stored mu_k_discretisation_error is not NaN")
    if f["results/units"].attrs["mu_s_discretisation_error"] not in (b"1", "1"):
        fail("mu_s_discretisation_error without its unit")

out, path = run((6, 6, 2), [], "unstudied")
if not re.search(r"mu_s \(global\) +[0-9.]+ \(discretisation error not measured: mesh 6x6x2 q1 \(non-graded\) not in the mesh study; "
                 r"nz other than 5 \(the thickness study: 5/10/20\)",
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
