#!/usr/bin/env python3
"""The error bar of every FEM result (core/study_table.hpp): gradfric-fem finds the study's ladder
holding its own discretisation (docs/fem_study.tsv) and stores that ladder member's verdict in
/statistics. The studied run: 50x50x5 at the defaults, the coarsest member of the non-graded ladder
refined in every direction (50x50x5/100x100x10/200x200x20); its stored relative error, order,
safety factor and extrapolated value are those gradfric-study -study_judge gives that member (the
same procedure: this checks that the run finds its ladder and stores the fields), and the error
column's attributes name the ladder's three meshes. Unstudied runs store NaN and say "not
measured": a mesh outside every ladder (6x6x2), and the studied mesh with a setting no study row
has (-fem_gravity 9.81: the scene differs).

    check_error_bar.py <gradfric-fem> <gradfric-study> <docs/fem_study.tsv>"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

import h5py

driver, judge, table = sys.argv[1:4]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
work = tempfile.mkdtemp(prefix="gradfric_error_bar_")


def fail(message, text=""):
    shutil.rmtree(work, ignore_errors=True)
    sys.exit(message + ("\n" + text if text else ""))


def run(mesh, extra, name, ranks=2):
    path = os.path.join(work, name + ".h5")
    nx, ny, nz = mesh
    command = ["mpiexec", "--oversubscribe", "-n", str(ranks), driver, "-fem_nx", str(nx), "-fem_ny", str(ny),
               "-fem_nz", str(nz), "-friction_observables", "mu_s", "-fem_verbose", "false", "-output", path] + extra
    r = subprocess.run(command, env=env, capture_output=True, text=True)
    if r.returncode != 0:
        fail("run failed (%d): %s" % (r.returncode, " ".join(command)), r.stdout + r.stderr)
    return r.stdout, path


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def stored(path, observable="mu_s"):
    """The point's stored bar: {field: value}, the error column's attributes (this point's line) and
    /fem/results' <observable>_error_basis."""
    with h5py.File(path, "r") as f:
        st = f["statistics"]
        fields = {k: float(st["%s_discretisation_%s" % (observable, k)][0])
                  for k in ("error", "order", "safety_factor", "extrapolated", "half_width")}
        error = st["%s_discretisation_error" % observable]
        attributes = {k: text(error.attrs[k]).split("\n")[0] for k in ("convergence", "fit", "ladder", "basis")}
        if text(error.attrs["units"]) != "1":
            fail("%s_discretisation_error without its unit 1" % observable)
        basis = text(f["fem/results"].attrs["%s_error_basis" % observable])
        value = float(f["realisations/%s" % observable][0, 0])
    return fields, attributes, basis, value


# The study's verdict on the ladder member 50x50x5 at the defaults (scene "-").
tsv = os.path.join(work, "verdicts.tsv")
r = subprocess.run([judge, "-study_judge", table, "-output", tsv], env=env, capture_output=True, text=True)
if r.returncode != 0 or not os.path.exists(tsv):
    fail("gradfric-study -study_judge %s failed (%d)" % (table, r.returncode), r.stdout + r.stderr)
with open(tsv) as f:
    members = [row for row in csv.DictReader(f, delimiter="\t")
               if (row["observable"], row["scene"], row["mesh"], row["members"]) == ("mu_s", "-", "50x50x5", "3")]
if len(members) != 1:
    fail("the study: expected one 3-member mu_s ladder holding 50x50x5 at the defaults, found %d" % len(members))
expected = members[0]
if expected["convergence"] not in ("monotone", "oscillatory") or not math.isfinite(float(expected["relative_uncertainty"])):
    fail("the study's non-graded ladder is no longer bounded (%s): pick another studied run" % expected["convergence"])

out, path = run((50, 50, 5), [], "studied")
fields, attributes, basis, value = stored(path)
if abs(value - float(expected["value"])) > 1e-6:
    fail("studied run: mu_s %.6f differs from the study's row %s (the run is not the study's)" % (value, expected["value"]))
for field, column, tolerance in (("error", "relative_uncertainty", 1e-5), ("order", "order", 1e-5),
                                 ("safety_factor", "safety_factor", 1e-12), ("extrapolated", "extrapolated", 1e-8)):
    want = float(expected[column])
    if not abs(fields[field] - want) <= tolerance * abs(want):
        fail("studied run: stored mu_s_discretisation_%s %r, -study_judge gives %s %s" % (field, fields[field], column,
                                                                                         expected[column]))
if not math.isfinite(fields["half_width"]):
    fail("studied run: stored mu_s_discretisation_half_width is not finite")
if attributes["convergence"] != expected["convergence"] or attributes["fit"] != expected["fit"]:
    fail("studied run: stored convergence/fit %r/%r, -study_judge gives %r/%r" % (
        attributes["convergence"], attributes["fit"], expected["convergence"], expected["fit"]))
if [m.split(":")[0] for m in attributes["ladder"].split()] != ["50x50x5", "100x100x10", "200x200x20"]:
    fail("studied run: stored ladder %r does not name the three meshes" % attributes["ladder"])
if not basis.startswith("+- ") or "50x50x5:" not in basis or basis != attributes["basis"]:
    fail("studied run: /fem/results mu_s_error_basis %r, the column's basis %r" % (basis, attributes["basis"]))
if not re.search(r"mu_s \(global\) +[0-9.]+\s+\(?discretisation " + re.escape(basis), out):
    fail("studied run: the printed mu_s does not carry the stored basis", out)

# Unstudied: a mesh in no ladder, and the studied mesh in a scene no row has.
for mesh, extra, name in (((6, 6, 2), [], "unstudied_mesh"), ((50, 50, 5), ["-fem_gravity", "9.81"], "unstudied_scene")):
    out, path = run(mesh, extra, name)
    fields, attributes, basis, _ = stored(path)
    if not all(math.isnan(v) for v in fields.values()):
        fail("%s: stored bar fields are not all NaN: %r" % (name, fields))
    if not basis.startswith("not measured") or not attributes["basis"].startswith("not measured"):
        fail("%s: stored basis %r / %r does not say 'not measured'" % (name, basis, attributes["basis"]))
    print("%s: %s" % (name, basis))

shutil.rmtree(work, ignore_errors=True)
print("studied 50x50x5: mu_s_discretisation_error %s (%s, order %s, Fs %s)" % (
    expected["relative_uncertainty"], expected["convergence"], expected["order"], expected["safety_factor"]))
print("error bar OK")
