"""Checks that a gradfric (or gradfric-fem sweep) results file is complete: every task flagged
done, every realisation's mu_s finite, the statistics written for every point.
Usage: python3 check_complete.py results.h5 <expected tasks>
"""
import sys

import h5py
import numpy as np

path, expected = sys.argv[1], int(sys.argv[2])
with h5py.File(path, "r") as f:
    done = f["realisations/done"][()]
    mu_s = f["realisations/mu_s"][()]
    finished = f["statistics/finished"][()]
problems = []
if done.size != expected:
    problems.append(f"{done.size} tasks, expected {expected}")
if not np.all(done == 1):
    problems.append(f"{int(np.sum(done != 1))} task(s) not done")
if not np.all(np.isfinite(mu_s)):
    problems.append("a realisation's mu_s is not finite")
if int(np.sum(finished)) != done.size:
    problems.append(f"statistics count {int(np.sum(finished))} finished tasks of {done.size}")
if problems:
    print(f"{path}: incomplete: " + "; ".join(problems))
    sys.exit(1)
print(f"{path}: complete, {done.size} tasks")
