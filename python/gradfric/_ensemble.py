"""The ensemble layout (docs/ensemble.md, section 5): a spring-block ensemble (gradfric), a FEM
sweep (gradfric-fem with sweep lists) or a single FEM run (one point, one realisation, with its
FEM extras under /fem: _fem.extras), one row of /sweep per point."""
import numpy as np
import xarray as xr

from . import _fem, _h5

FORMATS = ("gradfric-sbm-ensemble", "gradfric-fem-sweep", "gradfric-fem-run")
# Groups whose datasets keep their own names; /properties and /run are prefixed (their names
# repeat /realisations').
_PLAIN = {"sweep", "realisations", "statistics", "history", "maps"}
# /run's per-task tables have no scales (so that h5diff --exclude-path /run is blind to them).
_RUN_DIMS = {"run/wall_seconds": ["point", "realisation"], "run/rank": ["point", "realisation"]}


def read(f):
    coords, data = _h5.collect(f, _PLAIN, _RUN_DIMS, skip=("fem",))
    # The sweep table and the sample times describe the points and samples: coordinates.
    for name in [k for k in data if data[k].attrs["hdf5_path"].startswith("/sweep/")]:
        coords[name] = data.pop(name)
    for name in ("time", "snapshot_times"):
        if name in data:
            coords[name] = data.pop(name)
    scene = _h5.option_record(f["scene"])
    if "map_side" in f.attrs:
        # Block centres [m]: column i of N covers [i, i + 1) L / N. FEM files of format version 3
        # have these axes too (block_row, block_column: nx each); from version 4 their axes are the
        # bottom cells, cell_x and cell_y, which hold the centres themselves.
        side = scene.get("plate_L", scene.get("sbm_L", ("nan",)))[0]
        n = int(f.attrs["map_side"])
        centres = (np.arange(n) + 0.5) * float(side) / n
        coords["x"] = xr.Variable("block_column", centres, {"units": "m", "description": "centre of each block column along x (the grading axis)"})
        coords["y"] = xr.Variable("block_row", centres, {"units": "m", "description": "centre of each block row along y"})
    _old_relative_errors(data, coords)
    attrs = _h5.attributes(f)
    attrs["sweep_axes"] = _h5.text(f["sweep"].attrs.get("axes", ""))
    attrs.update({k: v[0] for k, v in scene.items()})
    attrs["scene_options"] = list(scene)
    attrs["observables"] = observables(f)
    attrs.update(_h5.provenance(f["run"]))
    if "fem" in f:  # a single FEM run's extras
        fem_coords, fem_data, fem_attrs = _fem.extras(f)
        coords.update(fem_coords)
        data.update(fem_data)
        attrs.update(fem_attrs)
    longest = _mask_histories(f, data, coords)
    ds = xr.Dataset(data, coords, attrs)
    if longest is not None and "sample" in ds.dims:
        ds = ds.isel(sample=slice(0, longest))
    return ds, scene


def _mask_histories(f, data, coords):
    """Each history [point, realisation, sample] (mu, force_x, force_y, time, a FEM run's
    normal_force) NaN from sample /history/length[point, realisation] on, whatever the file holds
    there (a sweep's file pads its shorter tasks with NaN, and so did a single FEM run's before
    format version 4): read lazily like the rest. Returns the longest length, where open() cuts the
    sample axis (None: no histories), so a single run's arrays hold its samples alone."""
    if "history/length" not in f:
        return None
    lengths = np.asarray(f["history/length"][()])
    for table in (data, coords):
        for name, var in table.items():
            where = var.attrs.get("hdf5_path", "")
            if var.dims == ("point", "realisation", "sample") and where in f and where != "/history/length":
                table[name] = _h5.masked_history(var, f[where], lengths)
    return int(lengths.max(initial=0))


def observables(f):
    """The per-realisation observables with statistics, in the order the file made them: every
    /realisations/<name> with a /statistics/<name>_mean (C++: physics/observables.hpp; the same
    rule reads every format version). Their units and description are the datasets' attributes."""
    names = [n for n in f["realisations"] if f"{n}_mean" in f["statistics"]]
    # Datasets are allocated when created (contiguous, in creation order): their offsets keep it.
    return sorted(names, key=lambda n: (f["realisations"][n].id.get_offset() or 0, n))


def _old_relative_errors(data, coords):
    """Files before format version 3 stored one propagated standard error (mu_*_relative_error);
    they also get the 95 % half-width later files store (mu_*_relative_ci95): the error x
    t(0.975, min(n, n_0) - 1), n and n_0 the counts of the point and its reference."""
    for mu in [n[:-len("_relative_error")] for n in list(data) if n.endswith("_relative_error")]:
        old, new = data.get(f"{mu}_relative_error"), f"{mu}_relative_ci95"
        if old is None or new in data:
            continue
        attrs = dict(old.attrs, description=f"95 % confidence half-width of {mu}_relative (from {mu}_relative_error)",
                     interval="95 % Student t half-width: the propagated standard error x t(0.975, min(n, n_0) - 1)")
        if f"{mu}_count" not in data or "reference_point" not in coords:
            # Without the counts (or the reference point) the factor is unknown: the name is there, NaN.
            data[new] = old.copy(data=np.full(old.shape, np.nan))
            data[new].attrs = dict(attrs, interval="unknown: the file has no realisation counts or reference "
                                   f"points to turn {mu}_relative_error into a 95 % half-width")
            continue
        count = np.asarray(data[f"{mu}_count"].values, dtype=float)
        reference = np.asarray(coords["reference_point"].values)
        dof = np.full(count.shape, np.nan)
        known = reference >= 0
        dof[known] = np.minimum(count[known], count[reference[known]]) - 1
        factor = np.array([t_quantile_975(d) if d >= 1 else np.nan for d in dof.ravel()]).reshape(dof.shape)
        data[new] = old.copy(data=np.asarray(old.values) * factor)
        data[new].attrs = attrs


def t_quantile_975(dof):
    """t(0.975, dof) of Student's t with an integer number of degrees of freedom dof >= 1, without
    scipy: P(|T| < t) = 0.95 solved by bisection in theta = atan(t / sqrt(dof)), with the closed
    forms of Abramowitz & Stegun 26.7.3 and 26.7.4 (1e-12 relative)."""
    dof = int(dof)

    def inside(theta):  # P(|T| < sqrt(dof) tan(theta))
        s, c = np.sin(theta), np.cos(theta)
        if dof % 2:
            total, term = 0.0, c
            for k in range(1, (dof - 1) // 2 + 1):  # c, (2/3) c^3, (2 4)/(3 5) c^5, ...
                total += term
                term *= c * c * (2 * k) / (2 * k + 1)
            return 2 / np.pi * (theta + s * total)
        total, term = 0.0, 1.0
        for k in range(1, dof // 2 + 1):  # 1, (1/2) c^2, (1 3)/(2 4) c^4, ...
            total += term
            term *= c * c * (2 * k - 1) / (2 * k)
        return s * total

    low, high = 0.0, np.pi / 2
    for _ in range(200):
        middle = (low + high) / 2
        if inside(middle) < 0.95:
            low = middle
        else:
            high = middle
        if high - low < 1e-15:
            break
    return float(np.sqrt(dof) * np.tan((low + high) / 2))
