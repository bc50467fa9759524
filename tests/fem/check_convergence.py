#!/usr/bin/env python3
"""mu_s converges under mesh refinement with the state law, and does not with Eq. 1 alone.

A half-size paper plate (L = 2.5 mm, H = 50 um: the paper's element sizes 100/50/25 um on
25/50/100 x 5 hexahedra) on 2 ranks, mu_s only, with each law. The verdict is the one procedure
of the error bars (core/verification.hpp), asked of gradfric-study -study_judge on a small study
table of the three runs (meshes written as the in-plane size alone, since nz stays 5). The state
law (D_c 2.5e-8 m) must be bounded (monotone or oscillatory, a finite relative uncertainty); Eq. 1
without a weakening length (the old law) must not be, so removing the length fails this test.
Measured: state 0.938065, 0.918270, 0.916344 (order 3.4); Eq. 1 0.900384, 0.861412, 0.819194
(differences -4.3 %, -4.9 %).

    check_convergence.py <gradfric-fem> <gradfric-study>"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

driver, judge = sys.argv[1:3]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
work = tempfile.mkdtemp(prefix="gradfric_convergence_")
SIZES = (25, 50, 100)


def fail(message):
    shutil.rmtree(work, ignore_errors=True)
    sys.exit(message)


def mu_s(law, n):
    command = ["mpiexec", "--oversubscribe", "-n", "2", driver, "-plate_L", "2.5e-3", "-fem_nx", str(n), "-fem_ny",
               str(n), "-friction_law", law, "-friction_observables", "mu_s", "-fem_verbose", "false"]
    r = subprocess.run(command, env=env, capture_output=True, text=True)
    found = re.search(r"mu_s \(global\) +([0-9.]+)", r.stdout)
    if r.returncode != 0 or not found:
        fail("run failed (%d): %s\n%s" % (r.returncode, " ".join(command), r.stdout + r.stderr))
    return found.group(1)


def verdicts(ladders):
    """{law: [rows of the -study_judge TSV, coarse to fine]}: each law's ladder as the study table's
    observable (mu_s_<law>), scene "-", one-number meshes."""
    table, tsv = os.path.join(work, "convergence.tsv"), os.path.join(work, "verdicts.tsv")
    with open(table, "w") as f:
        f.write("# observable\tmesh\tvalue\tstd_error\tsamples\tscene\n")
        for law, values in ladders.items():
            for n, value in zip(SIZES, values):
                f.write("mu_s_%s\t%d\t%s\t0\t0\t-\n" % (law, n, value))
    r = subprocess.run([judge, "-study_judge", table, "-output", tsv], env=env, capture_output=True, text=True)
    if r.returncode != 0 or not os.path.exists(tsv):
        fail("gradfric-study -study_judge failed (%d):\n%s" % (r.returncode, r.stdout + r.stderr))
    print(r.stdout)
    with open(tsv) as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    return {law: sorted((row for row in rows if row["observable"] == "mu_s_" + law), key=lambda row: int(row["mesh"]))
            for law in ladders}


ladders = {law: [mu_s(law, n) for n in SIZES] for law in ("state", "exponential")}
judged = verdicts(ladders)
for law, rows in judged.items():
    if [row["mesh"] for row in rows] != [str(n) for n in SIZES] or any(row["members"] != "3" for row in rows):
        fail("%s: the judge did not see one ladder of three: %r" % (law, rows))
    print("%-11s mu_s %s: %s, observed order %s, relative uncertainty %s" % (
        law, ", ".join(ladders[law]), rows[0]["convergence"], rows[0]["order"],
        ", ".join(row["relative_uncertainty"] for row in rows)))
state, exponential = judged["state"], judged["exponential"]
if state[0]["convergence"] not in ("monotone", "oscillatory") or \
        not all(math.isfinite(float(row["relative_uncertainty"])) for row in state):
    fail("the state law's mu_s is not bounded: %s" % state[0]["convergence"])
if exponential[0]["convergence"] in ("monotone", "oscillatory", "no signal") or \
        any(math.isfinite(float(row["relative_uncertainty"])) for row in exponential):
    fail("Eq. 1 without a weakening length is bounded (%s): the test no longer tells the laws apart"
         % exponential[0]["convergence"])
shutil.rmtree(work, ignore_errors=True)
print("convergence OK")
