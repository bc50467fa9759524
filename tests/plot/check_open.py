#!/usr/bin/python3
"""gradfric.open (python/gradfric) on every kind of results file, made here by small runs: the
ensemble, a FEM run (with property fields and the pressure response), a FEM sweep, an accuracy
study, a design and a calibration (its CSV and scene file). For each, the named dimensions and
coordinates it must have, and every variable against what h5py reads from the dataset it names
(values, shape, axes, units, description), strings as str, the scene and provenance as attrs.
A corrupted Dataset must fail the same comparison (the check can fail).
Usage: check_open.py <gradfric> <gradfric-fem> <gradfric-study> <gradfric-design> <gradfric-calibrate>
                     <source dir> <version>
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np
import xarray as xr

sbm, fem, study, design, calibrate, src = (os.path.abspath(a) for a in sys.argv[1:7])
version = sys.argv[7]
sys.path.insert(0, os.path.join(src, "python"))
import gradfric  # noqa: E402

env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
work = tempfile.mkdtemp(prefix="gradfric_open_")


def run(driver, *args, ranks=2):
    command = ["mpiexec", "--oversubscribe", "-n", str(ranks), driver, *args]
    r = subprocess.run(command, env=env, capture_output=True, text=True, cwd=work)
    assert r.returncode == 0, " ".join(command) + "\n" + r.stdout[-2000:] + r.stderr[-2000:]
    return r.stdout


def path(name):
    return os.path.join(work, name)


def same(a, b):
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype.kind == "f" or b.dtype.kind == "f":
        return a.shape == b.shape and np.array_equal(a, b, equal_nan=True)
    return a.shape == b.shape and np.array_equal(a, b)


def is_str(value):
    return isinstance(value, str) or (isinstance(value, (list, np.ndarray)) and all(isinstance(v, str) for v in np.ravel(value)))


def check_against_file(ds, file_path):
    """Every variable and coordinate that names a dataset (or /results attribute) equals it."""
    checked = 0
    with h5py.File(file_path, "r") as f:
        for name, var in list(ds.data_vars.items()) + list(ds.coords.items()):
            where = var.attrs.get("hdf5_path")
            if where is None:  # only the coordinates the package derives (block and node positions, phases)
                assert name in ds.coords and name in ("x", "y", "node_x", "node_y", "phase"), f"{name}: from nowhere"
                continue
            assert is_str(var.attrs["units"]) and is_str(var.attrs["description"]) and var.attrs["description"], name
            if "@" in where:  # an attribute of a record group (/results@mu_s)
                group, attribute = where.split("@")
                raw = f[group].attrs[attribute]
                raw = raw.decode() if isinstance(raw, bytes) else raw
                assert var.dims == () and (var.item() == raw or same(var.values, raw)), (name, var.values, raw)
                checked += 1
                continue
            d = f[where]
            raw = d[()]
            if d.dtype.kind == "S":
                raw = np.array([v.decode() for v in raw.ravel()], dtype=object).reshape(raw.shape)
                assert all(isinstance(v, str) for v in var.values.ravel()), f"{name}: not decoded"
            if "rows" in d.attrs:  # /fields/<p>_map: flat in the file
                raw = raw.reshape(int(d.attrs["rows"]), int(d.attrs["columns"]))
            values = var.values
            if values.shape != raw.shape and raw.shape == (1,):  # one-row tables read as 0-d
                raw = raw[0]
            if "sample" in var.dims and "sample" in ds.dims:  # histories end at the longest length
                axis = var.dims.index("sample")
                assert np.isnan(np.take(raw, range(ds.sizes["sample"], raw.shape[axis]), axis=axis)).all() \
                    if raw.dtype.kind == "f" else True, f"{name}: values cut off"
                raw = np.take(raw, range(ds.sizes["sample"]), axis=axis)
            assert same(values, raw), f"{name}: values differ from {where}"
            for axis, dim in zip(d.dims, var.dims):  # an axis the file names is named alike
                if len(axis):
                    assert axis[0].name.rsplit("/", 1)[1] == dim, (name, dim, axis[0].name)
            for key in ("units", "description"):
                if key in d.attrs:
                    raw_text = d.attrs[key]
                    assert var.attrs[key] == (raw_text.decode() if isinstance(raw_text, bytes) else raw_text), (name, key)
            checked += 1
    return checked


def check_provenance(ds, ranks, options_file=None):
    assert ds.attrs["software_version"] == version, ds.attrs["software_version"]
    assert ds.attrs["software_commit"] and ds.attrs["date"].endswith("Z") and ds.attrs["ranks"] == ranks
    assert is_str(ds.attrs["command_line"]) and is_str(ds.attrs["options_files"])
    if options_file:
        k = ds.attrs["options_files"].index(options_file)
        with open(options_file) as text:
            assert ds.attrs["options_files_text"][k] == text.read()


def expect_dims(ds, sizes):
    assert dict(ds.sizes) == sizes, (dict(ds.sizes), sizes)


# 1. The spring-block ensemble: 3 points, 2 realisations, histories, maps, snapshots.
scene_file = os.path.join(src, "input", "sbm_fig4_reduced.opts")
printed = run(sbm, "-options_file", scene_file, "-sbm_N", "16", "-ensemble_delta", "-0.3,0,0.3", "-ensemble_realisations", "2",
    "-ensemble_friction_fields", "true", "-sbm_snapshot_times", "1.0e-4,1.2e-4", "-output", path("ens.h5"))
with gradfric.open(path("ens.h5")) as ds, h5py.File(path("ens.h5"), "r") as f:
    C = f["history/length"][()].max()  # open() cuts the sample axis at the longest history
    expect_dims(ds, {"point": 3, "realisation": 2, "sample": C, "block_row": 16, "block_column": 16, "snapshot": 2})
    assert ds.attrs["format"] == "gradfric-sbm-ensemble" and ds.attrs["sweep_axes"] == "delta"
    assert same(ds["delta"], [-0.3, 0, 0.3]) and ds["delta"].dims == ("point",) and ds["delta"].attrs["units"] == "1"
    assert list(ds["property"].values) == ["friction"] * 3 and ds["theta"].attrs["units"] == "degree"
    assert ds["time"].dims == ("point", "realisation", "sample") and ds["time"].attrs["units"] == "s"
    assert ds["mu"].dims == ("point", "realisation", "sample") and ds["force_x"].attrs["units"] == "N"
    assert ds["mu_s"].dims == ("point", "realisation") and ds["mu_s_mean"].dims == ("point",)
    # Found in the file, in the order of the C++ table, which the printed tables follow
    # ("Global static friction mu_s over 2 realisation(s) per point ...").
    tables = re.findall(r"^\S.* (\w+) over \d+ realisation\(s\) per point", printed, re.M)
    assert tables[:2] == ["mu_s", "mu_k"] and ds.attrs["observables"] == tables, (ds.attrs["observables"], tables)
    assert ds["first_slip_time"].dims == ("point", "realisation", "block_row", "block_column")
    assert ds["sigma_x_over_p"].dims == ("point", "realisation", "snapshot", "block_row", "block_column")
    assert same(ds["snapshot_times"], [1.0e-4, 1.2e-4]) and ds["snapshot_times"].dims == ("snapshot",)
    assert ds["properties_mu_s"].dims == ("point", "block_column") and ds["run_wall_seconds"].dims == ("point", "realisation")
    assert np.allclose(ds["x"], (np.arange(16) + 0.5) * 0.005 / 16) and ds["x"].dims == ("block_column",)
    # selections by label: the history of (Delta = 0.3, realisation 1), up to its length
    n = int(ds["length"].sel(point=2, realisation=1))
    assert same(ds["mu"].sel(point=2, realisation=1)[:n], f["history/mu"][2, 1, :n])
    assert float(ds["mu_s_relative"].swap_dims(point="delta").sel(delta=0.0)) == 0.0
    assert ds.attrs["sbm_N"] == "16" and "sbm_N" in ds.attrs["scene_options"] and ds.attrs["output"].endswith("ens.h5")
    # Each point's discretisation bar (core/study_table.hpp): five fields along point (N_b 16 is in
    # no ladder: NaN), the verdict's text one line per point in the error column's attributes.
    for mu in ("mu_s", "mu_k"):
        for field in ("error", "order", "safety_factor", "extrapolated", "half_width"):
            bar = ds[f"{mu}_discretisation_{field}"]
            assert bar.dims == ("point",) and bar.attrs["units"] == "1" and np.isnan(bar.values).all(), (mu, field)
        for attribute in ("convergence", "fit", "ladder", "basis"):
            assert len(ds[f"{mu}_discretisation_error"].attrs[attribute].split("\n")) == 3, (mu, attribute)
        assert f"{mu}_discretisation_lattice" not in ds and f"{mu}_discretisation_dt" not in ds
    check_provenance(ds, 2, scene_file)
    assert check_against_file(ds, path("ens.h5")) >= 45
    assert gradfric.options(path("ens.h5"))["plate_E"] == ("10000000", "Pa", "default")
    # The comparison fails on a Dataset that is wrong: a changed value, a swapped axis, a lost unit.
    for broken in (lambda: ds.assign(mu_s=ds["mu_s"] + 1e-12), lambda: ds.assign(mu_s=ds["mu_s"].copy(data=ds["mu_s"].values + 1e-12)),
                   lambda: ds.assign(mu_s=ds["mu_s"].transpose()),
                   lambda: ds.assign_coords(delta=ds["delta"].copy(data=ds["delta"].values[::-1])),
                   lambda: ds.assign(mu=ds["mu"].assign_attrs(units="s"))):
        try:
            check_against_file(broken(), path("ens.h5"))
        except (AssertionError, ValueError):
            continue
        raise SystemExit("check_against_file accepted a wrong Dataset")

# 1b. A file of format version 2 (one standard error in mu_*_relative_error): open() adds the 95 %
# half-width later files store, t(0.975, min(n, n_0) - 1) x the error.
shutil.copy(path("ens.h5"), path("ens_v2.h5"))
with h5py.File(path("ens_v2.h5"), "r+") as f:
    st = f["statistics"]
    assert st["mu_s_relative_ci95"].attrs["interval"].startswith("95 % Student t")
    half = st["mu_s_relative_ci95"][:]
    f.attrs["format_version"] = 2
    for mu in ("mu_s", "mu_k"):
        st.move(f"{mu}_relative_ci95", f"{mu}_relative_error")
        st[f"{mu}_relative_error"][...] = st[f"{mu}_relative_error"][:] / 12.7062047  # 2 realisations: 1 dof
with gradfric.open(path("ens_v2.h5")) as old:
    assert np.allclose(old["mu_s_relative_ci95"].values, half, rtol=1e-7, equal_nan=True), (old["mu_s_relative_ci95"].values, half)
    assert "mu_s_relative_error" in old and old["mu_s_relative_ci95"].attrs["interval"].startswith("95 % Student t")

# 1c. A file written before the bars came from the study's ladders (the lattice and time-step terms
# _lattice and _dt beside _error, one "point p: ..." basis line per point, no _order ... _half_width):
# open() reads it as it is.
shutil.copy(path("ens.h5"), path("ens_old_bars.h5"))
with h5py.File(path("ens_old_bars.h5"), "r+") as f:
    st = f["statistics"]
    for mu in ("mu_s", "mu_k"):
        for field in ("order", "safety_factor", "extrapolated", "half_width"):
            del st[f"{mu}_discretisation_{field}"]
        error = st[f"{mu}_discretisation_error"]
        for attribute in ("convergence", "fit", "ladder"):
            del error.attrs[attribute]
        error.attrs["interval"] = "bound: lattice + dt terms"
        error.attrs["basis"] = "\n".join(f"point {p}: not measured" for p in range(3))
        for term in ("lattice", "dt"):
            term_column = st.create_dataset(f"{mu}_discretisation_{term}", data=np.full(3, np.nan))
            term_column.attrs.update(units="1", description=f"{term} term of {mu}_discretisation_error (NaN: not measured)")
            term_column.dims[0].attach_scale(error.dims[0][0])
with gradfric.open(path("ens_old_bars.h5")) as old:
    assert old["mu_s_discretisation_lattice"].dims == ("point",) and old["mu_k_discretisation_dt"].dims == ("point",)
    assert "mu_s_discretisation_order" not in old and old["mu_s_discretisation_error"].attrs["basis"].startswith("point 0: ")
    assert check_against_file(old, path("ens_old_bars.h5")) >= 45

# 2. A FEM run with a property field (/fields) and its pressure response.
fem_out = "-output"
run(fem, "-field_mu_profile", "step", "-field_mu_position", "3e-3", "-field_mu_delta", "0.2", "-fem_nx", "8",
    "-fem_ny", "6", "-fem_nz", "1", "-friction_observables", "mu_s,first_slip", fem_out, path("fem.h5"))
with gradfric.open(path("fem.h5")) as ds, h5py.File(path("fem.h5"), "r") as f:
    # The campaign layout of one point, one realisation (as a FEM sweep's), plus the /fem extras.
    # The FEM's names (format version 4): the bottom cells, no lattice; the history its samples alone.
    assert f.attrs["history_capacity"] == f["history/length"][0, 0]
    expect_dims(ds, {"point": 1, "realisation": 1, "sample": f.attrs["history_capacity"],
                     "cell_x": 8, "cell_y": 6, "node_x": 9, "node_y": 7})
    assert ds.attrs["format"] == "gradfric-fem-run" and ds["mu"].dims == ("point", "realisation", "sample")
    assert not np.isnan(ds["mu"].values).any() and "mu_s_relative" not in ds and "sigma" not in ds.coords
    assert ds["properties_mu_s"].dims == ("point", "cell_x") and ds["properties_mu_s_map"].dims == ("point", "cell_y", "cell_x")
    assert np.allclose(ds["properties_mu_s_map"][0], ds["fem_fields_mu_s_map"])  # both at the bottom cells' centres
    assert ds["time"].attrs["units"] == "s" and ds.attrs["fem_format_version"] == 5
    # /fem/properties holds the physics' values: mu per bottom node, on node_x.
    assert ds["fem_properties_mu_s"].dims == ("node_x",) and ds["fem_properties_E"].dims == ("cell_x",)
    assert ds["fem_fields_mu_s_map"].dims == ("cell_y", "cell_x") and ds["pressure_response_g"].dims == ("node_y", "node_x")
    assert ds["normal_force"].dims == ("point", "realisation", "sample")
    first = ds["fem_first_slip_time"]  # each bottom node's first slip; the earliest is the run's first slip
    assert first.dims == ("node_y", "node_x") and first.attrs["units"] == "s"
    assert float(first.min()) == float(ds["first_slip_time"])
    assert np.allclose(ds["node_x"], np.linspace(0, 0.005, 9)) and np.allclose(ds["cell_y"], (np.arange(6) + 0.5) * 0.005 / 6)
    mu_map = ds["fem_fields_mu_s_map"]  # the step at x = 3 mm: 1 - D before, 1 + D beyond, every row alike
    assert np.allclose(mu_map.where(mu_map["cell_x"] < 3e-3, drop=True), 0.8)
    assert np.allclose(mu_map.where(mu_map["cell_x"] > 3e-3, drop=True), 1.2)
    assert ds["mu_s"].dims == ("point", "realisation") and float(ds["mu_s"][0, 0]) == f["realisations/mu_s"][0, 0]
    assert ds["first_slip_time"].attrs["units"] == "s" and ds["mu_s_discretisation_error"].dims == ("point",)
    assert isinstance(ds["mu_s_error_basis"].item(), str) and ds["dt"].attrs["units"] == "s"
    assert ds["mu_s_error_basis"].item() == ds["mu_s_discretisation_error"].attrs["basis"]  # the one point's line
    assert ds["mu_k_discretisation_order"].dims == ("point",) and "mu_s_discretisation_lattice" not in ds
    assert ds.attrs["field_mu_profile"] == "step" and ds.attrs["plate_L"] == "0.005"
    check_provenance(ds, 2)
    assert check_against_file(ds, path("fem.h5")) >= 40

# 3. A FEM sweep: the ensemble's layout, one run per point.
run(fem, "-grading_profile", "linear", "-grading_property", "friction", "-ensemble_delta", "0,0.2", "-fem_nx", "6",
    "-fem_ny", "6", "-fem_nz", "1", "-friction_observables", "mu_s", fem_out, path("sweep.h5"))
with gradfric.open(path("sweep.h5")) as ds, h5py.File(path("sweep.h5"), "r") as f:
    expect_dims(ds, {"point": 2, "realisation": 1, "sample": f["history/length"][()].max(), "cell_x": 6})
    assert same(ds["reference_point"], [0, 0]) and float(ds["mu_s_relative"][0]) == 0.0
    assert ds.attrs["format"] == "gradfric-fem-sweep" and same(ds["delta"], [0, 0.2])
    assert ds["mu_s_discretisation_error"].dims == ("point",) and ds["mu"].dims == ("point", "realisation", "sample")
    check_provenance(ds, 2)
    assert check_against_file(ds, path("sweep.h5")) >= 40

# 4. The accuracy study: described columns along each ladder's rung scale, the provenance record.
study_file = os.path.join(src, "input", "study_sbm_reduced.opts")
run(study, "-options_file", study_file, "-output", path("study.h5"))
with gradfric.open(path("study.h5")) as ds, h5py.File(path("study.h5"), "r") as f:
    ladders = sorted(name for name in f if name != "provenance")
    rungs = max(len(f[name]["setting"]) for name in ladders)
    expect_dims(ds, {"ladder": len(ladders), "rung": rungs})
    assert list(ds["ladder"].values) == ladders and ds.attrs["format"] == "gradfric-accuracy-study"
    for name in ladders:
        row = ds.sel(ladder=name)
        k = int(row["rungs"])
        assert k == len(f[name]["setting"]) and row["knob"].item() == f[name].attrs["knob"]
        assert row["setting_unit"].item() == f[name]["setting"].attrs["units"]
        for column in f[name]:
            if column == "rung":
                assert list(f[name][column][:]) == list(range(k))
                continue
            assert f[name][column].attrs["description"] and "units" in f[name][column].attrs, (name, column)
            assert list(f[name][column].dims[0].keys()) == ["rung"], (name, column)
            assert same(row[column][:k], f[name][column][:]) and np.isnan(row[column][k:]).all(), (name, column)
    assert ds["wall_seconds"].attrs["units"] == "s" and ds["mu_s_error"].dims == ("ladder", "rung")
    assert ds["mu_s"].attrs["description"] == f[ladders[0]]["mu_s"].attrs["description"]
    assert ds.attrs["sbm_N"] == "20" and isinstance(ds.attrs["study_knobs"], str)
    check_provenance(ds, 2, study_file)
for name in ("N", "dt_verlet"):  # each ladder opens in plain xarray with its named axis
    plain = xr.open_dataset(path("study.h5"), engine="h5netcdf", group=name)
    assert plain["mu_s"].dims == ("rung",) and plain["mu_s"].attrs["units"] == "1", name
    plain.close()

# 5. A design: described columns on named axes and the provenance record, also to plain xarray.
design_file = os.path.join(src, "input", "design_friction_delta.opts")
variant_file = os.path.join(src, "input", "sbm_variant_calibrated_state.opts")
run(design, "-options_file", design_file, "-sbm_N", "12", "-design_variants", variant_file, "-output", path("design.h5"))
with gradfric.open(path("design.h5")) as ds, h5py.File(path("design.h5"), "r") as f:
    n = len(f["evaluations/index"])
    expect_dims(ds, {"evaluation": n, "variant": 1})
    assert ds["variants_value"].dims == ("variant",) and float(ds["variants_value"][0]) == f["variants/value"][0]
    assert ds.attrs["variants_files"] == variant_file and "-friction_law state" in ds.attrs["variants_options"]
    assert list(ds["phase"].values) == f["evaluations"].attrs["phases"].split(",")
    assert ds["value"].dims == ("evaluation",) and ds["x_grading_delta"].attrs["units"] == "1"
    assert ds["design_value"].dims == () and float(ds["design_value"]) == f["design/value"][0]
    assert float(ds["verification_mu_s"]) == f["verification/mu_s"][0] and ds["design_slope"].attrs["units"] == "1"
    assert ds.attrs["status"] == "found" and ds.attrs["free_parameters"] == "grading_delta"
    assert ds.attrs["value_meaning"] == "mean mu_s"
    check_provenance(ds, 2, design_file)
    assert check_against_file(ds, path("design.h5")) >= 30
for group, dim in (("evaluations", "evaluation"), ("design", "row"), ("verification", "row"), ("variants", "variant")):
    plain = xr.open_dataset(path("design.h5"), engine="h5netcdf", group=group, phony_dims="access")
    assert set(plain.dims) == {dim} and plain["value"].attrs["units"] == "1", (group, plain.dims)
    plain.close()

# 6. A calibration against a small FEM reference: the curves (with the scene beside them) and the scene.
run(fem, "-fem_nx", "10", "-fem_ny", "10", "-fem_nz", "5", "-friction_observables", "mu_s", fem_out, path("ref.h5"), ranks=1)
run(calibrate, "-calibrate_reference", path("ref.h5"), "-calibrate_fit", "lz_sigma", "-sbm_N", "20",
    "-calibrate_realisations", "16", "-output", path("fit.opts"), "-calibrate_curve", path("fit.csv"))
table = np.genfromtxt(path("fit.csv"), delimiter=",", names=True)
options = dict(line.split(" ", 1) for line in open(path("fit.opts")).read().splitlines() if line.startswith("-"))
with gradfric.open(path("fit.csv")) as ds:
    expect_dims(ds, {"time": len(table)})
    assert same(ds["time"], table["t"]) and same(ds["mu_sbm_mean"], table["mu_sbm_mean"]) and ds["time"].attrs["units"] == "s"
    assert np.isclose(float(ds["lz"]), float(options["-sbm_lz"]), rtol=1e-6) and ds["lz"].attrs["units"] == "m"
    assert np.isclose(float(ds["sigma"]), float(options["-surface_sigma_s"]), rtol=1e-5) and ds.attrs["status"] == "converged"
    assert ds.attrs["sbm_N"] == "20" and ds.attrs["reference_kind"] == "gradfric-fem run"
with gradfric.open(path("fit.opts")) as ds:
    assert ds.attrs["format"] == "gradfric-calibration-scene" and float(ds["reference_peak"]) > 0.5
    assert ds.attrs["ensemble_realisations"] == "16" and ds["lz_ci95_half_width"].attrs["units"] == "m"
    assert ds.attrs["fit"] == "lz_sigma"
# l_z alone on the FEM's undispersed surface: sigma 0 is the surface's, the peak residual is reported.
run(calibrate, "-calibrate_reference", path("ref.h5"), "-sbm_N", "20", "-calibrate_realisations", "2",
    "-surface_sigma_s", "0", "-surface_sigma_k", "0", "-output", path("layer.opts"))
options = dict(line.split(" ", 1) for line in open(path("layer.opts")).read().splitlines() if line.startswith("-"))
with gradfric.open(path("layer.opts")) as ds:
    assert ds.attrs["fit"] == "lz" and ds.attrs["status"] == "converged", ds.attrs
    assert float(ds["sigma"]) == 0 and float(ds["sigma_k"]) == 0
    assert np.isclose(float(ds["lz"]), float(options["-sbm_lz"]), rtol=1e-6)
    assert np.isclose(float(ds["reference_peak"]) + float(ds["peak_residual"]), 1.0, atol=0.005)  # the undispersed SBM peaks at 1

# Anything else is refused with the file named.
with open(path("bogus.h5"), "w") as text:
    text.write("not a results file\n")
for wrong in (path("bogus.h5"), os.path.join(src, "input", "fields", "pressure_response_fem100.h5")):
    try:
        gradfric.open(wrong)
    except ValueError as error:
        assert os.path.basename(wrong) in str(error), error
    else:
        raise SystemExit(f"{wrong} was opened")
shutil.rmtree(work)
print("gradfric.open checks passed: ensemble, FEM run, FEM sweep, study, design, calibration")
