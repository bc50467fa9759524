"""One gradfric-fem run (docs/fem.md, "Output"): the FEM extras (/fem) of a gradfric-fem-run file,
which is otherwise read as the campaign layout (_ensemble.py); and the older gradfric-fem-history
files (format versions 1 to 4), read as they were."""
import numpy as np
import xarray as xr

from . import _h5

FORMATS = ("gradfric-fem-history",)
_PLAIN = {"history"}
# /results is a record of attributes; what each one is (docs/fem.md), the file has their units.
_RESULTS = {
    "mu_s": "global static friction coefficient: the peak of mu(t)",
    "mu_k": "global kinetic coefficient: mean of mu(t) over the kinetic window; NaN: not measured",
    # The discretisation bar (core/study_table.hpp): /statistics columns in gradfric-fem-run files;
    # the older history files held the error alone here.
    **{f"{mu}_discretisation_{field}": f"{text} of {mu}; NaN: not measured"
       for mu in ("mu_s", "mu_k") for field, text in (
           ("error", "relative discretisation uncertainty U / |value| (study ladder, Eca-Hoekstra)"),
           ("order", "observed order p of the study ladder's fit"),
           ("safety_factor", "safety factor Fs of the discretisation uncertainty"),
           ("extrapolated", "value the study ladder's error fit extrapolates to"),
           ("half_width", "relative 95 % statistical half-width included in the discretisation uncertainty"),
           ("lattice", "lattice term of the discretisation error (files before the study ladders)"),
           ("dt", "time-step term of the discretisation error (files before the study ladders)"))},
    "mu_s_error_basis": "what the error bar of mu_s rests on: the study ladder's verdict, or why not measured",
    "mu_k_error_basis": "what the error bar of mu_k rests on: the study ladder's verdict, or why not measured",
    "peak_time": "time of the peak of mu(t)",
    "eq2_peak_time": "the peak time Eq. 2 of the paper predicts",
    "first_slip_time": "time of the first slip of a bottom node",
    "slide_start": "time the sliding (step 2) started",
    "settled_normal_force": "total normal contact force / (p L^2) after the pressing step",
    "peak_confirmed": "1 if the peak was confirmed before the run ended",
    "kinetic_window_complete": "1 if the kinetic window was complete",
    "mu_k_window_start": "start of the mu_k window, since the start of sliding",
    "mu_k_window_end": "end of the mu_k window, since the start of sliding",
    "mu_k_window_spread": "(max - min) / mean of the window's quarters' means",
    "mu_k_window_steady": "1 steady, 0 not steady by the latest start, -1 not tested",
    "mu_k_steady_tolerance": "the spread below which the window is steady",
    "nodes_slid_above_one": "bottom nodes that slid at mu(theta) > 1 by the peak (flutter; -1: not measured)",
    "area_slid_above_one": "their share of the contact area",
    "largest_element_slid_above_one": "the largest in-plane element side next to them",
    "memory_relaxation_time": "the normal-stress memory's T = L_sigma / (|V| + V*) at their fastest slip rate (NaN: not applied)",
    "memory_cutoff_wavelength": "the shortest wavelength that still grows with the memory, 2 pi c_s T / K_c",
    "dt": "time step",
    "stable_dt": "the stable time step estimate",
    "steps": "time steps taken",
    "wall_seconds": "wall time of the run",
}


def _fields(f):
    """/fields/<p>_map: fem_ny x fem_nx row-major, flat in the file (attributes rows, columns)."""
    out = {}
    for name, d in f.get("fields", {}).items():
        if name in ("x", "y"):  # the maps' axes (format 3)
            continue
        rows, columns = int(d.attrs["rows"]), int(d.attrs["columns"])
        out[f"fields_{name}"] = xr.Variable(("y", "x"), d[()].reshape(rows, columns),
                                            dict(_h5.attributes(d, skip=("rows", "columns")), hdf5_path=d.name))
    return out


def _scene(f):
    if "scene" in f:
        return _h5.option_record(f["scene"])
    # format 1: /parameters, each value "value [unit] (origin)"
    record = {}
    if "parameters" not in f:
        return record
    for name, value in _h5.attributes(f["parameters"]).items():
        words = str(value).split(" ")
        unit = words[1].strip("[]") if len(words) > 2 else ""
        record[name.lstrip("-")] = (words[0], unit, words[-1].strip("()") if len(words) > 1 else "")
    return record


def read(f):
    skip = {"fields", "pressure_response"}
    coords, data = _h5.collect(f, _PLAIN, skip=skip)
    data.update(_fields(f))
    if any(k.startswith("fields_") for k in data):
        if "fields/y" in f:  # the stored axis (a graded mesh's cells are unequal)
            coords["y"] = _h5.variable(f["fields/y"], ("y",))
        else:
            ny = data[next(k for k in data if k.startswith("fields_"))].shape[0]
            side = float(_scene(f)["plate_L"][0])
            coords["y"] = xr.Variable("y", (np.arange(ny) + 0.5) * side / ny,
                                      {"units": "m", "description": "centre of each bottom cell row along y"})
    if "pressure_response/g" in f:
        g = f["pressure_response/g"]
        if "pressure_response/node_x" in f:  # the stored node positions (format 3)
            coords["node_x"] = _h5.variable(f["pressure_response/node_x"], ("node_x",))
            coords["node_y"] = _h5.variable(f["pressure_response/node_y"], ("node_y",))
        else:
            x0, x1, y0, y1 = g.attrs["extent"]  # pixel edges: nodes at the pixel centres
            ny, nx = g.shape
            coords["node_x"] = xr.Variable("node_x", x0 + (np.arange(nx) + 0.5) * (x1 - x0) / nx,
                                           {"units": "m", "description": "bottom node position along x"})
            coords["node_y"] = xr.Variable("node_y", y0 + (np.arange(ny) + 0.5) * (y1 - y0) / ny,
                                           {"units": "m", "description": "bottom node position along y"})
        data["pressure_response_g"] = _h5.variable(g, ("node_y", "node_x"))
    units = _h5.attributes(f["results/units"]) if "results/units" in f else {}
    for name, value in _h5.attributes(f["results"]).items():
        attrs = {"units": units.get(name, ""), "description": _RESULTS.get(name, name),
                 "hdf5_path": f"/results@{name}"}
        data[name] = xr.Variable((), np.asarray(value, dtype=object if isinstance(value, str) else None), attrs)
    scene = _scene(f)
    attrs = _h5.attributes(f)
    attrs.update({k: v[0] for k, v in scene.items()})
    attrs["scene_options"] = list(scene)
    if "provenance" in f:
        attrs.update(_h5.provenance(f["provenance"]))
    return xr.Dataset(data, coords, attrs), scene


# /fem/results of a gradfric-fem-run file: the run's scalars the campaign layout has no place for.
_EXTRA_RESULTS = {k: v for k, v in _RESULTS.items() if "_discretisation_" not in k and k not in
                  ("mu_s", "mu_k", "peak_time", "peak_confirmed", "steps", "wall_seconds")}


def extras(f):
    """(coords, data, attrs) of /fem: dims cell_x, node_x (/fem/properties), cell_y (/fem/fields),
    node_y (/fem/pressure_response, and /fem/first_slip as fem_first_slip_time); the normal force
    along (point, realisation, sample); each /fem/results attribute as a 0-d variable; /fem/derived
    as attributes."""
    fem = f["fem"]
    coords, data = {}, {}
    def axis(d, name):
        coords[name] = _h5.variable(d, (name,))

    if "properties" in fem:
        group = fem["properties"]
        axis(group["cell_x"], "cell_x")
        axis(group["node_x"], "node_x")
        for name, d in group.items():
            if name not in ("cell_x", "node_x"):
                data[f"fem_properties_{name}"] = _h5.variable(d, tuple(_h5.scale_dims(d)))
    if "fields" in fem:
        group = fem["fields"]
        axis(group["cell_y"], "cell_y")
        for name, d in group.items():
            if name not in ("cell_x", "cell_y"):
                data[f"fem_fields_{name}"] = _h5.variable(d, ("cell_y", "cell_x"))
    if "pressure_response" in fem:
        group = fem["pressure_response"]
        axis(group["node_y"], "node_y")
        data["pressure_response_g"] = _h5.variable(group["g"], ("node_y", "node_x"))
    if "first_slip" in fem:  # each bottom node's first slip (with first_slip in -friction_observables)
        group = fem["first_slip"]
        axis(group["node_y"], "node_y")
        data["fem_first_slip_time"] = _h5.variable(group["time"], ("node_y", "node_x"))
    if "history" in fem:
        data["normal_force"] = _h5.variable(fem["history/normal_force"], ("point", "realisation", "sample"))
    units = _h5.attributes(fem["results/units"])
    for name, value in _h5.attributes(fem["results"]).items():
        attrs = {"units": units.get(name, ""), "description": _EXTRA_RESULTS.get(name, name),
                 "hdf5_path": f"/fem/results@{name}"}
        data[name] = xr.Variable((), np.asarray(value, dtype=object if isinstance(value, str) else None), attrs)
    attrs = {f"fem_{k}": v for k, v in _h5.attributes(fem).items()}
    if "derived" in fem:
        attrs.update({k: v[0] for k, v in _h5.option_record(fem["derived"]).items()})
    return coords, data, attrs
