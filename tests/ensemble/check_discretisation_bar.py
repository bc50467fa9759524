"""The default scene's discretisation bars, stored per point (docs/verification.md): each point gets
the verdict of the spring-block study's lattice ladder of its scene (docs/sbm_study.tsv) at its
N_b. At a fixed random surface the mu_s and mu_k ladders (N_b 120/240/480) are monotone and
bounded. The stored fields equal what gradfric-study -study_judge gives the ladder member of the
run's N_b at each point's scene (the same procedure: this checks that each point finds its ladder
and stores it). Two realisations per point keep it short.

    check_discretisation_bar.py <gradfric> <gradfric-study> <source dir>"""
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

driver, judge, src = sys.argv[1:4]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
work = tempfile.mkdtemp(prefix="gradfric_bar_")
out = os.path.join(work, "default.h5")
r = subprocess.run(["mpiexec", "--oversubscribe", "-n", "2", driver, "-options_file", os.path.join(src, "input", "default.opts"),
                    "-plot", "false", "-ensemble_realisations", "2", "-ensemble_history", "false", "-output", out],
                   env=env, capture_output=True, text=True)
assert r.returncode == 0, r.stdout + r.stderr

# The study's verdict on every ladder member (docs/sbm_study.tsv).
tsv = os.path.join(work, "verdicts.tsv")
j = subprocess.run([judge, "-study_judge", os.path.join(src, "docs", "sbm_study.tsv"), "-output", tsv], env=env,
                   capture_output=True, text=True)
assert j.returncode == 0 and os.path.exists(tsv), j.stdout + j.stderr
with open(tsv) as f:
    verdicts = {(row["observable"], row["scene"], row["mesh"]): row for row in csv.DictReader(f, delimiter="\t")}


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def lines(column, attribute):
    return text(column.attrs[attribute]).split("\n")


with h5py.File(out, "r") as f:
    st, scene = f["statistics"], f["scene"].attrs
    n_b, delta = text(scene["sbm_N"]), f["sweep/delta"][:]
    assert n_b == "120" and list(delta) == [0.0, 0.2], (n_b, delta)
    # Each point's scene as the study writes it: the inactive grading of Delta 0 is left out.
    scenes = ["-" if d == 0 else "grading_delta=%g,grading_profile=linear,grading_property=friction" % d for d in delta]
    assert not any(f"{m}_discretisation_{t}" in st for m in ("mu_s", "mu_k") for t in ("lattice", "dt"))

    # mu_s and mu_k: monotone and bounded on both points' ladders at a fixed surface (120, 240,
    # 480), the fields -study_judge gives the N_b 120 member.
    for observable in ("mu_s", "mu_k"):
        error = st[f"{observable}_discretisation_error"]
        for point, key in enumerate(scenes):
            study = verdicts[(observable, key, n_b)]
            assert study["convergence"] == "monotone" and study["members"] == "3", study
            assert lines(error, "convergence")[point] == "monotone", lines(error, "convergence")
            assert lines(error, "fit")[point] == study["fit"], (lines(error, "fit"), study["fit"])
            for field, column, tolerance in (("error", "relative_uncertainty", 1e-5), ("order", "order", 1e-5),
                                             ("safety_factor", "safety_factor", 1e-12),
                                             ("extrapolated", "extrapolated", 1e-8)):
                stored, want = st[f"{observable}_discretisation_{field}"][point], float(study[column])
                assert math.isfinite(stored) and abs(stored - want) <= tolerance * abs(want), \
                    (observable, point, field, stored, want)
            assert math.isfinite(st[f"{observable}_discretisation_half_width"][point])
            ladder = lines(error, "ladder")[point].split()
            assert [m.split(":")[0] for m in ladder] == ["120", "240", "480"], ladder
            assert float(dict(m.split(":") for m in ladder)[n_b]) == float(study["value"]), (ladder, study["value"])
            assert lines(error, "basis")[point].startswith("+- "), lines(error, "basis")
            # A bound, not a formality: the run's mean lies within its bar plus its sampling
            # interval of the ladder's extrapolated value.
            mean = st[f"{observable}_mean"][point]
            half = 0.5 * (st[f"{observable}_ci95_high"][point] - st[f"{observable}_ci95_low"][point])
            assert abs(mean - float(study["extrapolated"])) <= float(study["relative_uncertainty"]) * mean + half, \
                (observable, point, mean, study["extrapolated"])
            print("point %d (%s): %s_discretisation_error %.6g (study %s)" % (
                point, key, observable, st[f"{observable}_discretisation_error"][point], study["relative_uncertainty"]))
shutil.rmtree(work, ignore_errors=True)
print("discretisation bar OK")
