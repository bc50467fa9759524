#!/usr/bin/env python3
"""Runs a small sweep on 2 ranks and checks that the results file makes sense with h5py alone and
with xarray (engine h5netcdf): every dataset has units and a description, the axes are named
dimension scales, the force components reproduce mu(t), the property fields are the ones the
scene asked for, and /run records the software version, command line, options file text, date
and ranks; each realisation's local friction coefficients follow from the file alone (the recipe of
docs/ensemble.md with numpy's Philox) and equal the ones stored with -ensemble_friction_fields.
Usage: check_self_describing.py <gradfric driver> <source dir> <version>
"""
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np
from numpy.random import Philox

driver, src, version = sys.argv[1:4]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
work = tempfile.mkdtemp(prefix="gradfric_describe_")
out = os.path.join(work, "sweep.h5")
scene_file = os.path.join(src, "input", "sbm_fig4_reduced.opts")
# -surface_length: a value the file stores exactly (a derived L/120 is stored to 10 digits); 1.25
# cells per block, so blocks straddle cells. Independent streams: each point its own surface, and
# the relative variations' propagated error.
r = subprocess.run(["mpiexec", "--oversubscribe", "-n", "2", driver, "-options_file", scene_file, "-sbm_N", "16",
                    "-ensemble_delta", "-0.3,0,0.3", "-ensemble_realisations", "2", "-friction_observables", "first_slip",
                    "-ensemble_friction_fields", "true", "-surface_length", "2.5e-4",
                    "-ensemble_common_streams", "false", "-output", out], env=env, capture_output=True, text=True)
assert r.returncode == 0, r.stdout + r.stderr


def philox_normal(key, words):
    """RandomStream::normalPair(...).first and .second for the counter words (w0, w1)."""
    # numpy's Philox steps its counter before each block: start one below.
    w = Philox(key=key, counter=((words[0] | (words[1] << 64)) - 1) % 2**256).random_raw(2)
    u0, u1 = ((w >> np.uint64(11)) + np.uint64(1)).astype(float) * 2.0**-53
    radius = np.sqrt(-2 * np.log(u0))
    return radius * np.cos(2 * np.pi * u1), radius * np.sin(2 * np.pi * u1)


def local_coefficients(f, point, realisation):
    """Each block's (mu_s,i, mu_k,i) of a realisation from the file alone (docs/surface.md)."""
    scene = f["scene"].attrs
    q = 0 if scene["ensemble_common_streams"] == "true" else point
    key = [int(scene["ensemble_seed"]), (q << 32) | realisation]
    sigma_s, sigma_k = f["sweep/sigma"][point], f["sweep/sigma_kinetic"][point]
    mean_s, mean_k = f["properties/mu_s"][point], f["properties/mu_k"][point]
    n = len(mean_s)
    mus, muk = np.empty((n, n)), np.empty((n, n))
    if scene["surface_kind"] == "blocks":  # one draw per block, redrawn until 0 < mu_k <= mu_s
        for row in range(n):
            for column in range(n):
                for attempt in range(1000):
                    zs, zk = philox_normal(key, (row * n + column, attempt))
                    s = mean_s[column] * (1 + sigma_s * zs)
                    k = mean_k[column] * (1 + sigma_k * zk)
                    if 0 < k <= s:
                        break
                mus[row, column], muk[row, column] = s, k
        return mus, muk
    # Cells of side l_c from the plate's corner, cell (i, j) along (x, y) holding the normals of the
    # counters (i << 32 | j, purpose << 32), purpose 0 for mu_s and 1 for mu_k; a block takes the
    # cells' area-weighted mean, then mu_s = max(mean_s (1 + sigma_s z_s), 0.01 mean_s) and
    # mu_k = min(max(mean_k (1 + sigma_k z_k), 0.01 mean_k), mu_s).
    assert scene["surface_kind"] == "cells", scene["surface_kind"]
    cells_per_block = float(scene["plate_L"]) / n / float(scene["surface_length"])
    edges = np.arange(n + 1) * cells_per_block  # block edges in units of l_c
    cells = int(np.ceil(edges[-1] - 1e-9))
    z = np.array([[[philox_normal(key, ((i << 32) | j, purpose << 32))[0] for purpose in (0, 1)]
                   for j in range(cells)] for i in range(cells)])  # z[i, j, purpose]
    overlap = np.clip(np.minimum(edges[1:, None], np.arange(1, cells + 1)[None, :]) -
                      np.maximum(edges[:-1, None], np.arange(cells)[None, :]), 0, None)  # overlap[block, cell]
    area = cells_per_block ** 2
    for row in range(n):
        for column in range(n):
            zs, zk = np.einsum("i,j,ijp->p", overlap[column], overlap[row], z) / area
            s = max(mean_s[column] * (1 + sigma_s * zs), 0.01 * mean_s[column])
            k = min(max(mean_k[column] * (1 + sigma_k * zk), 0.01 * mean_k[column]), s)
            mus[row, column], muk[row, column] = s, k
    return mus, muk


with h5py.File(out, "r") as f:
    undescribed = []

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset):
            units, text = obj.attrs.get("units"), obj.attrs.get("description")
            if not isinstance(units, str) or not isinstance(text, str) or not text:
                undescribed.append(name)

    f.visititems(visit)
    assert not undescribed, undescribed
    dims = lambda path: [d.label or (d.keys() or [""])[0] for d in f[path].dims]
    assert dims("realisations/mu_s") == ["point", "realisation"], dims("realisations/mu_s")
    assert dims("history/mu") == ["point", "realisation", "sample"], dims("history/mu")
    assert dims("maps/first_slip_time") == ["point", "realisation", "block_row", "block_column"]
    # The detachment time of each task is the latest first slip of its map, the same double (both
    # are the time of the step after which the last block had slipped); NaN would be a block that never did.
    first = f["maps/first_slip_time"][:]
    latest = first.reshape(first.shape[0], first.shape[1], -1).max(axis=2)
    assert np.isfinite(latest).all() and np.array_equal(latest, f["realisations/detachment_time"][:]), latest
    assert dims("properties/E") == ["point", "block_column"] and dims("statistics/mu_s_mean") == ["point"]
    assert f.attrs["format_version"] == 3 and isinstance(f.attrs["format"], str)
    # One interval convention, named on every interval (docs/ensemble.md, section 3), and the
    # discretisation bar with its basis per point (this scene's N_b is outside the study: NaN).
    st = f["statistics"]
    for name in ("mu_s_ci95_low", "mu_s_ci95_high", "mu_k_ci95_low", "mu_s_relative_ci95", "mu_k_relative_ci95",
                 "detachment_time_ci95_low", "detachment_time_relative_ci95"):
        assert st[name].attrs["interval"].startswith("95 % Student t"), (name, st[name].attrs.get("interval"))
    assert "mu_s_relative_error" not in st
    counts = st["mu_s_count"][:]
    t975 = {1: 12.7062047, 2: 4.30265273, 3: 3.18244631, 4: 2.77644511}  # Student t quantiles, n - 1 dof
    for point, ref in enumerate(f["sweep/reference_point"][:]):
        half = 0.5 * (st["mu_s_ci95_high"][point] - st["mu_s_ci95_low"][point])
        mean, se = st["mu_s_mean"][point], st["mu_s_stderr"][point]
        assert np.isclose(half, t975[counts[point] - 1] * se, rtol=1e-6), (point, half, se)
        if ref >= 0 and ref != point:
            m0, se0 = st["mu_s_mean"][ref], st["mu_s_stderr"][ref]
            error = np.hypot(se / m0, mean * se0 / m0**2)
            dof = min(counts[point], counts[ref]) - 1
            assert np.isclose(st["mu_s_relative_ci95"][point], t975[dof] * error, rtol=1e-6), point
    # The bar's fields (core/study_table.hpp): NaN where not measured, each with units, description
    # and the procedure named; the error column's text attributes hold one line per point.
    for field in ("error", "order", "safety_factor", "extrapolated", "half_width"):
        column = st[f"mu_s_discretisation_{field}"]
        assert "not a statistical interval" in column.attrs["interval"] and np.isnan(column[:]).all(), field
    assert not any(f"{m}_discretisation_{t}" in st for m in ("mu_s", "mu_k") for t in ("lattice", "dt"))
    bar = st["mu_s_discretisation_error"]
    for attribute in ("convergence", "fit", "ladder", "basis"):
        assert len(bar.attrs[attribute].split("\n")) == len(counts), (attribute, bar.attrs[attribute])
    basis = bar.attrs["basis"].split("\n")
    assert all(b.startswith("not measured: ") and len(b) > 16 for b in basis), basis

    scene = {k: v for k, v in f["scene"].attrs.items()}
    p, side = float(scene["plate_p"]), float(scene["plate_L"])
    n = f["history/length"][:]
    mu, fx, fy = f["history/mu"][:], f["history/force_x"][:], f["history/force_y"][:]
    for point in range(mu.shape[0]):
        for real in range(mu.shape[1]):
            k = n[point, real]
            assert k > 100, k
            assert np.allclose(np.hypot(fx[point, real, :k], fy[point, real, :k]) / (p * side**2), mu[point, real, :k],
                               rtol=1e-12, atol=1e-15)
            assert np.isnan(fx[point, real, k:]).all()
            # theta = 0: the force is along +x; only the random friction field makes a small F_y
            assert fx[point, real, k - 1] > 0 and np.abs(fy[point, real, :k]).max() < 0.01 * fx[point, real, :k].max()

    # The property fields: this scene grades friction linearly; E is uniform.
    delta = f["sweep/delta"][:]
    e0, mus0, muk0 = (float(scene[name]) for name in ("plate_E", "plate_mu_s", "plate_mu_k"))
    assert np.all(f["properties/E"][:] == e0)
    mus, muk = f["properties/mu_s"][:], f["properties/mu_k"][:]
    for point, d in enumerate(delta):
        assert np.isclose(mus[point].mean(), mus0) and np.isclose(muk[point].mean(), muk0)  # linear: mean kept
        assert np.isclose(mus[point, -1] - mus[point, 0], 2 * d * mus0), (d, mus[point])   # edge bands 1 -+ delta
        assert np.allclose(muk[point] / mus[point], muk0 / mus0)

    # Each realisation's coefficients: regenerated from (seed, point, realisation) = stored.
    for point in range(len(delta)):
        for real in range(f.attrs["realisations"]):
            s, k = local_coefficients(f, point, real)
            assert np.allclose(s, f["maps/mu_s_local"][point, real], rtol=1e-14, atol=0), (point, real)
            assert np.allclose(k, f["maps/mu_k_local"][point, real], rtol=1e-14, atol=0), (point, real)
            assert np.isclose(s.mean(), mus0, rtol=0.05) and s.std() > 0  # dispersed around the mean
    run = f["run"].attrs
    assert run["software_version"] == version, run["software_version"]
    assert run["software_commit"], "no commit"
    assert run["ranks"] == 2 and run["date"].endswith("Z")
    assert "-options_file" in run["command_line"] and "-ensemble_delta -0.3,0,0.3" in run["command_line"]
    with open(scene_file) as text:
        assert f["run/options_files"].attrs[scene_file] == text.read()

try:
    import xarray as xr
except ImportError:
    sys.exit("xarray is not installed: install python3-xarray and python3-h5netcdf (scripts/setup.sh --tests)")
ds = xr.open_dataset(out, engine="h5netcdf", group="history")
assert ds["mu"].dims == ("point", "realisation", "sample") and ds["mu"].attrs["units"] == "1", ds["mu"]
assert ds["force_x"].attrs["units"] == "N"
maps = xr.open_dataset(out, engine="h5netcdf", group="maps")
assert maps["first_slip_time"].dims == ("point", "realisation", "block_row", "block_column")
stats = xr.open_dataset(out, engine="h5netcdf", group="statistics")
assert stats["mu_s_mean"].dims == ("point",)
props = xr.open_dataset(out, engine="h5netcdf", group="properties")
assert props["mu_s"].sel(point=1).values.tolist() == [mus0] * 16  # delta = 0
shutil.rmtree(work)
print("self-describing file OK: every dataset described; xarray opens %d variables with named dimensions" % (
    len(ds.variables) + len(maps.variables) + len(stats.variables) + len(props.variables)))
