#!/usr/bin/python3
"""A FEM results file carries what the FEM has, by the FEM's names (docs/fem.md, "Output";
docs/ensemble.md, format version 4 of the FEM's files), and a spring-block file keeps the lattice's:

- a single run (gradfric-fem-run) and a sweep (gradfric-fem-sweep) have no block_row, block_column,
  map_side, first_slip_map, friction_fields, /realisations/redrawn_blocks, /sweep/sigma or
  /sweep/sigma_kinetic; /properties runs along cell_x [nx] (with property fields also cell_y [ny]),
  dimension scales holding the bottom cells' centres [m]; no description names a -sbm_ option;
- a single run stores its history's samples alone (capacity = /history/length, no NaN) and no
  /sweep/reference_point or relative statistics; gradfric.open reads it with no NaN in mu(t);
- a sweep keeps its reference point and relative variation, and gradfric.open cuts its sample axis
  at the longest run;
- a single run's file of format version 3 (padded history, reference_point -1, NaN relatives,
  block axes) still opens, its histories cut at their length;
- the spring-block ensemble still has the lattice's axes, sigma and redrawn blocks, version 3.

    check_fem_file_layout.py GRADFRIC_FEM GRADFRIC SOURCE_DIR WORK_DIR
"""
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

fem_driver, sbm_driver, source, work = sys.argv[1:5]
sys.path.insert(0, os.path.join(source, "python"))
import gradfric  # noqa: E402

env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
mesh = ["-fem_nx", "8", "-fem_ny", "6", "-fem_nz", "2", "-friction_observables", "mu_s"]
SPRING_BLOCK = ("block_row", "block_column")
SPRING_BLOCK_ROOT = ("map_side", "first_slip_map", "friction_fields")


def run(driver, *args):
    r = subprocess.run([driver, *args], env=env, capture_output=True, text=True, cwd=work)
    assert r.returncode == 0, " ".join(args) + "\n" + r.stdout[-2000:] + r.stderr[-2000:]
    return os.path.join(work, args[args.index("-output") + 1])


def descriptions(f):
    found = {}
    f.visititems(lambda name, obj: found.__setitem__(name, str(obj.attrs.get("description", ""))))
    return found


def check_fem_names(f, nx, ny=None):
    """What every FEM file of version 5 has and lacks."""
    assert f.attrs["format_version"] == 5, f.attrs["format_version"]
    for name in SPRING_BLOCK:
        assert name not in f, f"/{name} in a FEM file"
    for name in SPRING_BLOCK_ROOT:
        assert name not in f.attrs, f"root attribute {name} in a FEM file"
    assert "redrawn_blocks" not in f["realisations"] and "maps" not in f
    assert "sigma" not in f["sweep"] and "sigma_kinetic" not in f["sweep"]
    # The bottom cells' centres [m], as /fem/properties (the physics' own axis) has them in a run.
    L = float(f["scene"].attrs["plate_L"])
    assert f["cell_x"].shape == (nx,) and f["cell_x"].attrs["units"] == "m"
    assert np.allclose(f["cell_x"][:], (np.arange(nx) + 0.5) * L / nx), f["cell_x"][:]
    assert [d.keys()[0] for d in f["properties/E"].dims] == ["point", "cell_x"]
    if ny is None:
        assert "cell_y" not in f
    else:
        assert np.allclose(f["cell_y"][:], (np.arange(ny) + 0.5) * L / ny), f["cell_y"][:]
        m = f["properties/mu_s_map"]
        assert m.shape == (f.attrs["points"], ny, nx) and [d.keys()[0] for d in m.dims] == ["point", "cell_y", "cell_x"]
    # No spring-block option or concept (a model-neutral text may name both models' sites).
    for path, text in descriptions(f).items():
        for word in ("-sbm_", "lattice", "slider-spring", "block column", "block row", "dispersion", "redrawn"):
            assert word not in text, (path, text)


# 1. A single run: its samples alone, no reference point, the FEM's names.
single = run(fem_driver, *mesh, "-grading_profile", "linear", "-grading_delta", "0.2", "-output", "single.h5")
with h5py.File(single, "r") as f:
    assert f.attrs["format"] == "gradfric-fem-run"
    check_fem_names(f, 8)
    n = int(f["history/length"][0, 0])
    assert n > 100 and f.attrs["history_capacity"] == n and f["sample"].shape == (n,), (n, f.attrs["history_capacity"])
    for name in ("time", "mu", "force_x", "force_y"):
        assert f[f"history/{name}"].shape == (1, 1, n) and np.isfinite(f[f"history/{name}"][()]).all(), name
    assert np.max(f["history/mu"][()]) > 0.5  # a plain max is a number
    assert "reference_point" not in f["sweep"]
    relative = [k for k in f["statistics"] if "relative" in k]
    assert not relative, relative
    assert np.isfinite(f["statistics/mu_s_mean"][0]) and f["statistics/mu_s_mean"][0] == f["realisations/mu_s"][0, 0]
    assert np.allclose(f["cell_x"][:], f["fem/properties/cell_x"][:])
    assert "-fem_slide_time" in f["realisations/peak_confirmed"].attrs["description"]
    mu_s = f["realisations/mu_s"][0, 0]
with gradfric.open(single) as ds:
    assert ds.sizes["sample"] == n and not np.isnan(ds["mu"].values).any() and not np.isnan(ds["time"].values).any()
    assert float(ds["mu_s"][0, 0]) == mu_s and ds["properties_E"].dims == ("point", "cell_x")
    assert "mu_s_relative" not in ds and "reference_point" not in ds.coords and "sigma" not in ds.coords
    assert not any(d in ds.dims for d in SPRING_BLOCK) and "x" not in ds.coords
    assert not np.isnan(ds["normal_force"].values).all()

# 2. A sweep with property fields: its reference point and relative variation, cell_y for the maps.
sweep = run(fem_driver, *mesh, "-field_mu_profile", "stripes", "-field_mu_period", "1e-3", "-field_mu_normalise",
            "-ensemble_field", "mu_delta", "-ensemble_field_values", "0,0.3", "-output", "sweep.h5")
with h5py.File(sweep, "r") as f:
    assert f.attrs["format"] == "gradfric-fem-sweep"
    check_fem_names(f, 8, 6)
    assert list(f["sweep/reference_point"][:]) == [0, 0]
    rel = f["statistics/mu_s_relative"][:]
    assert rel[0] == 0 and np.isfinite(rel[1]) and rel[1] != 0, rel
    lengths = f["history/length"][:, 0]
    assert f.attrs["history_capacity"] >= lengths.max()
    base = float(f["scene"].attrs["plate_mu_s"])
    m = f["properties/mu_s_map"][:]
    assert np.allclose(m[0], base) and m[1].max() / m[1].min() > 1.2  # uniform, then stripes across x
with gradfric.open(sweep) as ds:
    assert ds.sizes["sample"] == lengths.max(), (ds.sizes["sample"], lengths)
    for p, length in enumerate(lengths):
        mu = ds["mu"][p, 0].values
        assert np.isfinite(mu[:length]).all() and np.isnan(mu[length:]).all(), p
    assert ds["properties_mu_s_map"].dims == ("point", "cell_y", "cell_x")

# 3. A single run's file as format version 3 wrote it: the history padded with NaN to a capacity,
# a reference point -1 and NaN relative values; gradfric.open cuts the histories at their length.
old = os.path.join(work, "single_v3.h5")
shutil.copy(single, old)
with h5py.File(old, "r+") as f:
    f.attrs["format_version"] = 3
    capacity = n + 50
    del f["sample"]
    sample = f.create_dataset("sample", data=np.arange(capacity, dtype=np.int32))
    sample.make_scale("sample")
    for group in ("history", "fem/history"):
        for name in list(f[group]):
            d = f[f"{group}/{name}"]
            if d.ndim != 3:
                continue
            padded = np.full((1, 1, capacity), np.nan)
            padded[..., :n] = d[()]
            attrs = {k: v for k, v in d.attrs.items() if k in ("units", "description")}
            del f[f"{group}/{name}"]
            e = f[group].create_dataset(name, data=padded)
            e.attrs.update(attrs)
            for axis, scale in enumerate((f["point"], f["realisation"], sample)):
                e.dims[axis].attach_scale(scale)
    f.attrs["history_capacity"] = capacity
    ref = f["sweep"].create_dataset("reference_point", data=np.array([-1], dtype=np.int32))
    ref.attrs.update(units="1", description="index of the non-graded point the relative variation uses; -1: none")
    ref.dims[0].attach_scale(f["point"])
    for name in ("mu_s_relative", "mu_s_relative_ci95"):
        d = f["statistics"].create_dataset(name, data=np.array([np.nan]))
        d.attrs.update(units="1", description=name)
        d.dims[0].attach_scale(f["point"])
with h5py.File(old, "r") as f:
    assert np.isnan(np.max(f["history/mu"][()]))  # the old file's trap: a plain max is NaN
with gradfric.open(old) as ds:
    assert ds.sizes["sample"] == n and not np.isnan(ds["mu"].values).any() and not np.isnan(ds["normal_force"].values).all()
    assert np.isnan(float(ds["mu_s_relative"][0])) and int(ds["reference_point"][0]) == -1

# 4. The spring-block ensemble keeps the lattice: its axes, sigma, redrawn blocks, format version 3.
sbm = run(sbm_driver, "-sbm_N", "8", "-ensemble_realisations", "2", "-grading_profile", "linear",
          "-ensemble_delta", "0,0.2", "-output", "sbm.h5")
with h5py.File(sbm, "r") as f:
    assert f.attrs["format"] == "gradfric-sbm-ensemble" and f.attrs["format_version"] == 3
    assert all(name in f for name in SPRING_BLOCK) and all(name in f.attrs for name in SPRING_BLOCK_ROOT)
    assert "cell_x" not in f and "redrawn_blocks" in f["realisations"] and "sigma" in f["sweep"]
    assert "-sbm_t_max" in f["realisations/peak_confirmed"].attrs["description"]
    assert "mu_s_relative" in f["statistics"] and "reference_point" in f["sweep"]
    assert [d.keys()[0] for d in f["properties/E"].dims] == ["point", "block_column"]
print("fem file layout OK")
