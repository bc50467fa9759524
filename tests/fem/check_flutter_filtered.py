#!/usr/bin/env python3
"""With the Prakash-Clifton filter nodes sliding at mu > 1 are named but are not a violation: the
interface resolution stored with the run (/fem/derived, "interface resolution") names the bounded
flutter of friction Delta -0.4 (the high-friction edge slips before the peak), and its one violation
on this coarse 10 x 10 x 2 plate is the process zone (< 4 elements, median), not the flutter. The printed verdict and measures are the stored ones.

    check_flutter_filtered.py <gradfric-fem> <output.h5>"""
import os
import re
import subprocess
import sys

import h5py

driver, path = sys.argv[1:3]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
command = [driver, "-fem_nx", "10", "-fem_ny", "10", "-fem_nz", "2", "-grading_profile", "linear", "-grading_property",
           "friction", "-grading_delta", "-0.4", "-friction_observables", "mu_s", "-fem_pc_length", "1e-6",
           "-fem_pc_speed", "0.1", "-output", path, "-output_overwrite"]
r = subprocess.run(command, env=env, capture_output=True, text=True)
if r.returncode != 0:
    sys.exit("run failed (%d): %s\n%s" % (r.returncode, " ".join(command), r.stdout + r.stderr))
with h5py.File(path, "r") as f:
    stored = f["fem/derived"].attrs["interface resolution"]
    stored = stored.decode() if isinstance(stored, bytes) else str(stored)
print("stored interface resolution:", stored)
head, _, violations = stored.partition(": NOT resolved:")
if not re.search(r"; local mu_s up to 1\.4, [1-9]\d* nodes \([0-9.e+-]+ % of the area\) slid at mu > 1 by the peak, "
                 r"their flutter bounded by the Prakash-Clifton filter$", head):
    sys.exit("the bounded flutter is not named: %r" % stored)
found = [v.strip() for v in violations.split(";") if v.strip()]
if len(found) != 1 or not re.fullmatch(r"process zone [0-9.e+-]+ elements \(median\) < 4 \(refine the mesh\)", found[0]):
    sys.exit("expected the process zone as the one violation, found %r" % found)
if not re.search(r"interface resolution +.*NOT resolved", r.stdout) or head not in r.stdout or found[0] not in r.stdout:
    sys.exit("the printed interface resolution is not the stored one:\n" + r.stdout)
print("flutter filtered OK")
