#!/usr/bin/env python3
"""The error bar of every FEM result (error_estimate.hpp): gradfric-fem prints it next to mu_s and
stores it in the results file. The study's rows (docs/fem_study.tsv), judged here by the ladder rule
written out on its own: the ladder refined in every direction (50x50x5/100x100x10/200x200x20) and
the time-step ladder converge, so the non-graded 50x50x5 mesh gets the bar recomputed here; the
same mesh graded (friction -0.2), whose ladder refined in every direction does not converge, gets
the bar through the edge-graded ladder's finest value, recomputed here; filtered friction +0.2,
which nothing bounds, gets none and names it; an unstudied one (6x6x2) says "not measured" naming
every term."""
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
               str(nz), "-friction_observables", "mu_s", "-output", path] + extra
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


def bound(mu, member):
    """The bound of one member of a converged ladder: GCI if monotone, the last two values' bracket
    if oscillating."""
    first, second = mu[1] - mu[0], mu[2] - mu[1]
    if first * second <= 0:
        return 1.25 * max(abs(mu[member] - mu[1]), abs(mu[member] - mu[2])) / abs(mu[2])
    p = math.log(first / second) / math.log(2)
    ext = mu[2] + second / (2 ** min(p, 2) - 1)
    return 1.25 * abs(mu[member] - ext) / ext


rows = study()
key = lambda n, nz=5, dts=0.6, contact="penalty": ("state", 2.5e-8, "none", 0.0, n, nz, "q1", dts, contact)
uniform = [rows[key(50, 5)], rows[key(100, 10)], rows[key(200, 20)]]
thickness = [rows[key(100, nz=nz)] for nz in (5, 10, 20)]
dt = [rows[key(100, dts=d)] for d in (0.6, 0.3, 0.15)]
if not converges(uniform) or not converges(dt) or converges(thickness):
    fail("the study's ladders: expected the 3D and dt ladders to converge and the thickness alone not: %r %r %r"
         % (uniform, dt, thickness))
kinematic = rows[key(100, contact="kinematic")]
bar = bound(uniform, 0) + bound(dt, 0) + 1.25 * abs(rows[key(100)] - kinematic) / kinematic

# The studied 50x50x5 mesh: the coarsest of the ladder refined in every direction, which bounds the
# thickness as well; plus the dt and contact terms.
out, path = run((50, 50, 5), [], "studied")
line = re.search(r"mu_s \(global\) +([0-9.]+) \+- ([0-9.]+) % \(discretisation: mesh [0-9.]+ %, thickness 0\.00 %", out)
if not line:
    fail("studied mesh: no measured error bar next to mu_s", out)
if abs(float(line.group(2)) - 100 * bar) > 0.006:
    fail("printed bar %s %% differs from the study's %.3f %%" % (line.group(2), 100 * bar))
if not re.search(r"mu_k \(kinetic window\) +\S+ \(discretisation error not measured: ", out):
    fail("studied mesh: mu_k without its 'not measured'", out)
with h5py.File(path, "r") as f:
    results = f["fem/results"].attrs  # the basis; the bars are /statistics columns, as in a sweep
    stored_mu_s, stored_bar = f["realisations/mu_s"][0, 0], f["statistics/mu_s_discretisation_error"][0]
    if abs(stored_mu_s - float(line.group(1))) > 1e-6:
        fail("stored mu_s %r differs from the printed %s" % (stored_mu_s, line.group(1)))
    if abs(stored_bar - bar) > 1e-9:
        fail("stored mu_s_discretisation_error %r, expected %r" % (stored_bar, bar))
    basis = results["mu_s_error_basis"]
    basis = basis.decode() if isinstance(basis, bytes) else str(basis)
    if not basis.startswith("mesh ") or "50x50x5/100x100x10/200x200x20, all directions" not in basis:
        fail("stored mu_s_error_basis %r" % basis)
    if not math.isnan(f["statistics/mu_k_discretisation_error"][0]):
        fail("stored mu_k_discretisation_error is not NaN")
    if f["statistics/mu_s_discretisation_error"].attrs["units"] not in (b"1", "1"):
        fail("mu_s_discretisation_error without its unit")

# The same mesh graded (friction -0.2): its ladder refined in every direction does not converge
# (0.809636, 0.806982, 0.799410: the differences grow), so it is bounded through the finest value of
# the ladder on the meshes graded toward the edges (60x60x5/120x120x10/240x240x20, which converges
# and whose finest mesh is nowhere coarser): |mu - f| + the bound of f, relative to the limit.
graded_rows = load(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "fem_study.tsv"),
                   edge=(4.0, 5e-4))
minus = lambda n, nz, table: table[("state", 2.5e-8, "friction", -0.2, n, nz, "q1", 0.6, "penalty")]
edge = [minus(n, nz, graded_rows) for n, nz in ((60, 5), (120, 10), (240, 20))]
if not converges(edge):
    fail("the study's edge-graded friction -0.2 ladder: expected it to converge: %r" % edge)
own, finest, b = minus(50, 5, rows), edge[2], bound(edge, 2)
through = (abs(own - finest) + b * finest) / ((1 - b) * finest)
graded_bar = through + bound(dt, 0) + 1.25 * abs(rows[key(100)] - kinematic) / kinematic
friction_minus = ["-grading_profile", "linear", "-grading_property", "friction", "-grading_delta", "-0.2"]
out, path = run((50, 50, 5), friction_minus, "graded")
line = re.search(r"mu_s \(global\) +[0-9.]+ \+- ([0-9.]+) % \(discretisation: mesh [0-9.]+ %, thickness 0\.00 %[^\n]*"
                 r"own ladders prove none \(mesh not converged: 50x50x5/100x100x10/200x200x20, all directions "
                 r"\(run 50x50x5\) give 0\.809636, 0\.806982, 0\.799410[^\n]*bounded through its finest value "
                 + re.escape("%.6f" % finest), out)
if not line:
    fail("graded studied mesh: no bar through the edge-graded ladder next to mu_s", out)
if abs(float(line.group(1)) - 100 * graded_bar) > 0.006:
    fail("graded: printed bar %s %% differs from the study's %.3f %%" % (line.group(1), 100 * graded_bar))
with h5py.File(path, "r") as f:
    if abs(f["statistics/mu_s_discretisation_error"][0] - graded_bar) > 1e-9:
        fail("graded: stored error %r, expected %r" % (f["statistics/mu_s_discretisation_error"][0], graded_bar))

# Filtered friction +0.2 (L 1e-6 m, V* 0.1 m/s) on the same mesh: its ladder refined in every
# direction does not converge (the steps grow) and no filtered graded ladder exists: no bar, and the reason.
out, path = run((50, 50, 5), ["-grading_profile", "linear", "-grading_property", "friction", "-grading_delta", "0.2",
                              "-fem_pc_length", "1e-6", "-fem_pc_speed", "0.1"], "filtered")
if not re.search(r"mu_s \(global\) +[0-9.]+ \(discretisation error not measured: mesh not converged: "
                 r"50x50x5/100x100x10/200x200x20 with the Prakash-Clifton filter", out):
    fail("filtered graded mesh: no 'not measured' naming the ladder that does not converge next to mu_s", out)
with h5py.File(path, "r") as f:
    if not math.isnan(f["statistics/mu_s_discretisation_error"][0]):
        fail("filtered graded mesh: stored error is not NaN")

out, path = run((6, 6, 2), [], "unstudied")
if not re.search(r"mu_s \(global\) +[0-9.]+ \(discretisation error not measured: mesh 6x6x2 q1 \(non-graded\) not in the mesh study; "
                 r"nz other than 5, 10 or 20 \(the thickness study: 5/10/20\)",
                 out):
    fail("unstudied mesh: no 'not measured' next to mu_s", out)
with h5py.File(path, "r") as f:
    results = f["fem/results"].attrs
    if not math.isnan(f["statistics/mu_s_discretisation_error"][0]):
        fail("unstudied mesh: stored error is not NaN")
    basis = results["mu_s_error_basis"]
    basis = basis.decode() if isinstance(basis, bytes) else str(basis)
    if not basis.startswith("not measured: mesh 6x6x2"):
        fail("unstudied mesh: stored basis %r" % basis)

shutil.rmtree(work, ignore_errors=True)
print("error bar OK")
