#!/usr/bin/env python3
"""With the friction law's normal-stress memory, nodes sliding at mu > 1 are named but are not the
flutter violation: the memory makes the interface well-posed if the mesh resolves it (docs/flutter.md,
"With a normal-stress memory"). The run checks that rule and prints it with the interface
resolution: elements next to those nodes at most lambda_c / 8, lambda_c = 2 pi c_s T / K_c(mu), with
T = L_sigma / (|V| + V*) at their fastest slip rate.

On a 10 x 10 x 2 plate, friction Delta -0.4 (local mu_s up to 1.4, its trailing edge slips before
the peak), -friction_observables mu_s:
  - L_sigma 40 D_c (1e-6 m), V* 0.1 m/s: the memory is not resolved by the 0.5 mm elements. lambda_c
    is recomputed from the stored T with K_c from scripts/flutter_roots.py (an independent numpy
    computation) and T from L_sigma in metres; the violation names the remedy, a longer
    -friction_memory_length; the text is the stored one, printed.
  - at the remedy's -friction_memory_length (rounded up): the memory is resolved, no such violation.
In both the one other violation is the process zone (< 4 elements on this coarse plate).

    check_flutter_memory.py <gradfric-fem> <work dir>"""
import math
import os
import re
import subprocess
import sys

import h5py

driver, work = sys.argv[1:3]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import flutter_roots  # noqa: E402  (the independent K_c)

env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
E, nu, rho = flutter_roots.plate_defaults()
shear_speed = math.sqrt(E / (2 * (1 + nu)) / rho)
K_c = flutter_roots.memory_cutoff(1.4, nu)[0]
D_c = 2.5e-8  # the state law's default -friction_d_c [m]: the memory's unit


def run(length):
    path = os.path.join(work, "flutter_memory_%s.h5" % length)
    command = [driver, "-fem_nx", "10", "-fem_ny", "10", "-fem_nz", "2", "-grading_profile", "linear",
               "-grading_property", "friction", "-grading_delta", "-0.4", "-friction_observables", "mu_s",
               "-friction_memory_length", length, "-friction_memory_speed", "0.1", "-output", path, "-output_overwrite"]
    r = subprocess.run(command, env=env, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("run failed (%d): %s\n%s" % (r.returncode, " ".join(command), r.stdout + r.stderr))
    with h5py.File(path, "r") as f:
        stored = f["fem/derived"].attrs["interface resolution"]
        results = dict(f["fem/results"].attrs)
    stored = stored.decode() if isinstance(stored, bytes) else str(stored)
    head, _, violations = stored.partition(": NOT resolved:")
    found = [v.strip() for v in violations.split(";") if v.strip()]
    if not re.search(r"; local mu_s up to 1\.4, [1-9]\d* nodes \([0-9.e+-]+ % of the area\) slid at mu > 1 by the peak, "
                     r"their flutter bounded by the normal-stress memory \(T [0-9.e+-]+ s at [0-9.e+-]+ m/s, lambda_c "
                     r"[0-9.e+-]+ m; elements there [0-9.e+-]+ m in-plane, [0-9.e+-]+ m base layer\)$", head):
        sys.exit("the bounded flutter is not named: %r" % stored)
    if not re.search(r"interface resolution +.*NOT resolved", r.stdout) or head not in r.stdout:
        sys.exit("the printed interface resolution is not the stored one:\n" + r.stdout)
    for v in found:
        if v not in r.stdout:
            sys.exit("violation %r stored but not printed" % v)
    T, wavelength = results["memory_relaxation_time"], results["memory_cutoff_wavelength"]
    fastest = float(re.search(r"\(T [0-9.e+-]+ s at ([0-9.e+-]+) m/s", head).group(1))
    assert abs(T - float(length) * D_c / (fastest + 0.1)) < 2e-3 * T, (T, length, fastest)  # L_sigma in D_c
    expected = 2 * math.pi * shear_speed * T / K_c
    print("L %s: T %.4g s, lambda_c %.4g m (numpy K_c %.6f gives %.4g m), element %.4g m; violations %s"
          % (length, T, wavelength, K_c, expected, results["largest_element_slid_above_one"], found))
    assert abs(wavelength - expected) < 1e-6 * expected, (wavelength, expected)
    return found, results


found, results = run("40")
assert len(found) == 2 and found[1].startswith("process zone"), found
rule = re.fullmatch(r"memory not resolved: elements up to ([0-9.e+-]+) m \(in-plane\) and ([0-9.e+-]+) m \(base layer\) "
                    r"where nodes slid at mu > 1, above lambda_c/8 = ([0-9.e+-]+) m \(refine there, or raise "
                    r"-friction_memory_length to ([0-9.e+-]+)\)", found[0])
assert rule, found[0]
element, allowed = float(rule.group(1)), float(rule.group(3))
assert element > allowed and abs(allowed - results["memory_cutoff_wavelength"] / 8) < 1e-3 * allowed, (element, allowed)
assert abs(element - results["largest_element_slid_above_one"]) < 1e-3 * element
remedy = float(rule.group(4))
# The remedy's length (lambda_c grows with T, so with L_sigma) resolves the memory on the same mesh.
found, results = run("%.2g" % (1.1 * remedy))
assert len(found) == 1 and found[0].startswith("process zone"), found
assert results["largest_element_slid_above_one"] <= results["memory_cutoff_wavelength"] / 8, results
print("flutter memory OK")
