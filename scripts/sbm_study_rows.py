#!/usr/bin/env python3
"""Study-table rows (docs/sbm_study.tsv) from the finished gradfric results files of one lattice
ladder run with the same seed and realisations on every rung (the same surfaces): for each sweep
point, `observable mesh value std_error samples scene` for mu_s and mu_k.

value is the ensemble mean. std_error is the standard error of the member's own part: with the
same surfaces on every rung, phi_i^r = a^r + e_i^r, and the surface's part a^r cancels in every
quantity the verification procedure uses (differences of members, and distances to the
extrapolated value, whose coefficients sum to zero). var(phi_i - phi_j) = v_i + v_j over the
realisations gives the v_i by least squares over all pairs (clipped at 0);
std_error = sqrt(v_i / R). The paired differences of successive rungs go to stderr.
The own parts' standard errors are exact for three members (any covariance: for coefficients
summing to zero, c'Cc = -1/2 sum c_i c_j var(phi_i - phi_j)), a least-squares fit for more.
Usage: sbm_study_rows.py ladder_N120.h5 ladder_N240.h5 ladder_N480.h5 > rows.tsv
"""
import itertools
import sys

import h5py
import numpy as np


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def scene_of(f, point):
    delta = float(f["sweep/delta"][point])
    if delta == 0.0:
        return "-"
    return (f"grading_delta={delta:g},grading_profile={text(f['sweep/profile'][point])},"
            f"grading_property={text(f['sweep/property'][point])}")


files = [h5py.File(path, "r") for path in sys.argv[1:]]
meshes = [int(f["scene"].attrs["sbm_N"]) for f in files]
seeds = {text(f["scene"].attrs["ensemble_seed"]) for f in files}
assert len(seeds) == 1, f"the rungs must share the seed (the same surfaces): {seeds}"
for point in range(len(files[0]["sweep/delta"])):
    scene = scene_of(files[0], point)
    for obs in ("mu_s", "mu_k"):
        counts = [int(f["statistics/" + obs + "_count"][point]) for f in files]
        r = min(counts)
        values = np.array([f["realisations/" + obs][point, :r] for f in files])  # [rung, realisation]
        if r < 2 or not np.isfinite(values).all():  # not observed (-friction_observables), or unfinished
            print(f"# {obs} point {point}: not every realisation has it: no rows", file=sys.stderr)
            continue
        n = len(files)
        pairs = list(itertools.combinations(range(n), 2))
        design = np.zeros((len(pairs), n))
        target = np.zeros(len(pairs))
        for k, (i, j) in enumerate(pairs):
            design[k, i] = design[k, j] = 1.0
            target[k] = np.var(values[i] - values[j], ddof=1)
        own = np.clip(np.linalg.lstsq(design, target, rcond=None)[0], 0.0, None) if n > 2 else \
            np.full(n, target[0] / 2)
        for i in range(n):
            print(f"{obs}\t{meshes[i]}\t{values[i].mean():.6f}\t{np.sqrt(own[i] / r):.2e}\t{r}\t{scene}")
        for i in range(1, n):
            d = values[i] - values[i - 1]
            print(f"# {obs} {scene}: N_b {meshes[i - 1]} -> {meshes[i]}: paired difference {d.mean():+.6f} "
                  f"+- {d.std(ddof=1) / np.sqrt(r):.1e} (standard error, {r} pairs); independent standard "
                  f"errors {values[i - 1].std(ddof=1) / np.sqrt(r):.1e}, {values[i].std(ddof=1) / np.sqrt(r):.1e}",
                  file=sys.stderr)
