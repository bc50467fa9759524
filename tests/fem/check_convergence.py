#!/usr/bin/env python3
"""mu_s converges under mesh refinement with the state law, and does not with Eq. 1 alone.

A half-size paper plate (L = 2.5 mm, H = 50 um: the paper's element sizes 100/50/25 um on
25/50/100 x 5 hexahedra) on 2 ranks, mu_s only, with each law. The rule is the one the error bar
and the docs use (scripts/fem_study_table.py, src/fem/error_estimate.cpp): the two differences
keep their sign and shrink with an observed order above 0.5. The state law (D_c 2.5e-8 m) must
pass it; Eq. 1 without a weakening length (the old law) must fail it, so removing the length
fails this test. Measured: state 0.938065, 0.918270, 0.916344 (order 3.4); Eq. 1 0.900384,
0.861412, 0.819194 (differences -4.3 %, -4.9 %)."""
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from fem_study_table import analyse  # the convergence rule of the docs' tables

driver = sys.argv[1]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def mu_s(law, n):
    command = ["mpiexec", "--oversubscribe", "-n", "2", driver, "-plate_L", "2.5e-3", "-fem_nx", str(n), "-fem_ny",
               str(n), "-friction_law", law, "-friction_observables", "mu_s", "-fem_verbose", "false"]
    r = subprocess.run(command, env=env, capture_output=True, text=True)
    found = re.search(r"mu_s \(global\) +([0-9.]+)", r.stdout)
    if r.returncode != 0 or not found:
        sys.exit("run failed (%d): %s\n%s" % (r.returncode, " ".join(command), r.stdout + r.stderr))
    return float(found.group(1))


verdicts = {}
for law in ("state", "exponential"):
    ladder = [mu_s(law, n) for n in (25, 50, 100)]
    differences, order, _, bars = analyse(ladder)
    verdicts[law] = not bars.startswith("not converged")
    print("%-11s mu_s %s: differences %s, observed order %s" % (law, ", ".join("%.6f" % m for m in ladder),
                                                                differences, order))
if not verdicts["state"]:
    sys.exit("the state law's mu_s does not converge")
if verdicts["exponential"]:
    sys.exit("Eq. 1 without a weakening length converged: the test no longer tells the laws apart")
print("convergence OK")
