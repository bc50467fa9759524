#!/usr/bin/env python3
"""A single gradfric-fem run and a one-point FEM sweep of the same scene write the same results
file (docs/fem.md, "Output"): the same groups, datasets and attributes outside /fem and /run,
bit-identical mu_s, mu_k, statistics and stored friction history (the same observer, sampled by
the same -friction_history_interval, on the same ranks and partition). What differs: the root
`format` (gradfric-fem-run, gradfric-fem-sweep), the single run's /fem; the single run stores
its samples alone (history_capacity = /history/length, the sweep pads to the most a run can
take) and, compared with nothing, no /sweep/reference_point or relative statistics."""
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

driver, scene = sys.argv[1], sys.argv[2]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
work = tempfile.mkdtemp(prefix="gradfric_fem_schema_")
single, sweep = os.path.join(work, "single.h5"), os.path.join(work, "sweep.h5")
base = [driver, "-options_file", scene, "-fem_verbose", "false"]
for extra in (["-output", single], ["-output", sweep, "-fem_sweep_ranks_per_run", "1"]):
    r = subprocess.run(base + extra, env=env, capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


def same(a, b):
    """Bit-identical values (NaN where the other has NaN)."""
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype.kind == "f":
        return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))
    return a.shape == b.shape and np.array_equal(a, b)


# What a sweep has and a single run has not: its reference point and the relative variation.
def against_reference(name):
    return name == "sweep/reference_point" or (name.startswith("statistics/") and "_relative" in name)


def contents(f, n):
    """Every object outside /fem and /run: path -> (attribute names, values or None for a group);
    a history (and its sample axis) up to n samples."""
    out = {}

    def visit(name, obj):
        if name.split("/")[0] in ("fem", "run") or against_reference(name):
            return
        attributes = {k for k in obj.attrs if k not in ("REFERENCE_LIST", "DIMENSION_LIST")}
        values = obj[()] if isinstance(obj, h5py.Dataset) else None
        if name == "sample" or (name.startswith("history/") and name != "history/length"):
            values = values[..., :n]
        out[name] = (attributes, values)

    f.visititems(visit)
    return out


with h5py.File(single, "r") as a, h5py.File(sweep, "r") as b:
    assert a.attrs["format"] == "gradfric-fem-run" and b.attrs["format"] == "gradfric-fem-sweep"
    for name in set(a.attrs) | set(b.attrs):
        if name not in ("format", "history_capacity"):
            assert same(a.attrs[name], b.attrs[name]), name
    n = int(a["history/length"][0, 0])
    assert n == int(b["history/length"][0, 0]) == a.attrs["history_capacity"] < b.attrs["history_capacity"]
    assert np.isnan(b["history/mu"][0, 0, n:]).all() and np.isfinite(a["history/mu"][()]).all()
    assert any(against_reference("statistics/" + k) for k in b["statistics"]) and "reference_point" in b["sweep"]
    assert not any(against_reference("statistics/" + k) for k in a["statistics"]) and "reference_point" not in a["sweep"]
    ca, cb = contents(a, n), contents(b, n)
    assert set(ca) == set(cb), sorted(set(ca) ^ set(cb))
    for path in ca:
        assert ca[path][0] == cb[path][0], (path, ca[path][0] ^ cb[path][0])
        for attribute in ca[path][0]:
            if path.startswith("history/") and path != "history/length" and attribute == "description":
                # the sweep's says where its padding starts; the single run has none
                assert b[path].attrs[attribute] == a[path].attrs[attribute] + "; NaN from sample /history/length on"
                continue
            assert same(a[path].attrs[attribute], b[path].attrs[attribute]), (path, attribute)
        if ca[path][1] is not None:
            assert same(ca[path][1], cb[path][1]), path
    assert sorted(a["run"]) == sorted(b["run"]) and "fem" not in b and "fem" in a
    assert n > 100, n
    for name in ("mu_s", "mu_k"):
        assert np.isfinite(a["realisations/" + name][0, 0]), name
    print(f"mu_s {a['realisations/mu_s'][0, 0]:.9f}, mu_k {a['realisations/mu_k'][0, 0]:.9f}, {n} samples: identical")
shutil.rmtree(work)
print("single run schema OK")
