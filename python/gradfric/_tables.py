"""Files of tables: the accuracy study (gradfric-study, docs/accuracy.md) and the design file
(gradfric-design, docs/design.md)."""
import numpy as np
import xarray as xr

from . import _h5

STUDY_FORMATS = ("gradfric-accuracy-study",)
DESIGN_FORMATS = ("gradfric-design",)

# Study files written before they described their columns (src/study/study_file.cpp writes the
# same words as units and description attributes now).
_STUDY_COLUMNS = {
    "setting": ("", "the knob's value at this rung (its unit: coordinate setting_unit)"),
    "mu_s_error": ("1", "relative error of the global mu_s (coordinate error_meaning)"),
    "mu_k_error": ("1", "relative error of the global mu_k (coordinate error_meaning)"),
    "mu_s_stderr": ("1", "relative standard error of the ensemble mean of mu_s at this rung"),
    "mu_k_stderr": ("1", "relative standard error of the ensemble mean of mu_k at this rung"),
    "wall_seconds": ("s", "wall time per realisation (per run in the FEM study)"),
    "cpu_seconds": ("s", "CPU time of the run"),
    "mu_s": ("1", "global static friction coefficient at this rung"),
    "mu_k": ("1", "global kinetic coefficient at this rung"),
    "dt": ("s", "time step of the run"),
    "steps": ("1", "time steps taken"),
}
# Design files written before they described their datasets (the same words as design_file.cpp).
_DESIGN_COLUMNS = {
    "index": ("1", "order of the evaluation in the search"),
    "realisations": ("1", "realisations the evaluation ran"),
    "value": ("1", "the target's quantity: mean mu_s or relative variation (attribute value_meaning)"),
    "ci95_low": ("1", "lower end of the 95 % confidence interval of value"),
    "ci95_high": ("1", "upper end of the 95 % confidence interval of value"),
    "mu_s": ("1", "mean global static friction coefficient"),
    "mu_s_ci95_low": ("1", "lower end of the 95 % confidence interval of mu_s"),
    "mu_s_ci95_high": ("1", "upper end of the 95 % confidence interval of mu_s"),
    "slope": ("", "local slope d value / d parameter at the design"),
    "x_ci95_low": ("", "the design's CI mapped onto the parameter through the local slope (low end)"),
    "x_ci95_high": ("", "the design's CI mapped onto the parameter through the local slope (high end)"),
    "peak_confirmed": ("1", "1 if the FEM run confirmed its peak"),
    "cells": ("1", "hexahedra of the FEM mesh"),
}


def _described(name, attrs, table):
    units, description = table.get(name, ("", name))
    if name.startswith("x_") and name not in table:
        description = f"value of the free parameter {name[2:]}"
    attrs.setdefault("units", units)
    attrs.setdefault("description", description)
    return attrs


def read_study(f):
    """Ladders stacked along `ladder`, rungs along `rung` (NaN where a ladder is shorter or lacks
    a column); the ladders' texts (knob, unit, error_meaning, ...) are coordinates along ladder."""
    ladders = [name for name in f if hasattr(f[name], "keys") and name != "provenance"]
    rungs = max([len(f[name]["setting"]) for name in ladders] + [0])
    columns = sorted({c for name in ladders for c in f[name] if c != "rung"}, key=lambda c: (c != "setting", c))
    texts = sorted({t for name in ladders for t in f[name].attrs})
    data = {}
    for column in columns:
        table = np.full((len(ladders), rungs), np.nan)
        for i, name in enumerate(ladders):
            if column in f[name]:
                v = f[name][column][()]
                table[i, :len(v)] = v
        stored = next((f[name][column] for name in ladders if column in f[name]), None)
        attrs = {k: _h5.text(stored.attrs[k]) for k in ("units", "description") if stored is not None and k in stored.attrs}
        if column == "setting":  # its unit is the ladder's knob unit (coordinate setting_unit)
            attrs = {"units": "", "description": "the knob's value at this rung (its unit: coordinate setting_unit)"}
        data[column] = xr.Variable(("ladder", "rung"), table, _described(column, attrs, _STUDY_COLUMNS))
    coords = {"ladder": ladders, "rung": np.arange(rungs),
              "rungs": ("ladder", [len(f[name]["setting"]) for name in ladders], {"units": "1", "description": "rungs of each ladder"})}
    for t in texts:
        key = "setting_unit" if t == "unit" else t
        coords[key] = ("ladder", np.array([_h5.text(f[name].attrs.get(t, "")) for name in ladders], dtype=object))
    attrs = _h5.attributes(f)
    if "provenance" in f:
        attrs.update(_h5.provenance(f["provenance"]))
    return xr.Dataset(data, coords, attrs), {}


def read_design(f):
    """/evaluations along `evaluation` (phase as a coordinate); the one-row tables /design,
    /verification, /fem_verification as 0-d variables design_<column>, ...; /variants along
    `variant` (variants_<column>); texts as attributes."""
    fallback = {}
    for group in f:
        if group in ("evaluations", "design", "verification", "fem_verification"):
            dim = "evaluation" if group == "evaluations" else "row"
            fallback.update({f"{group}/{c}": [dim] for c in f[group] if not _h5.scale_dims(f[group][c])[0]})
    coords, data = _h5.collect(f, {"evaluations"}, fallback, skip={"provenance"})
    coords.pop("row", None)
    if "evaluation" not in coords:  # a file written before the design file had scales
        coords["evaluation"] = np.arange(len(f["evaluations/index"]))
    for name in list(data):
        var = data[name]
        _described(_h5.basename(var.attrs["hdf5_path"]), var.attrs, _DESIGN_COLUMNS)
        if var.dims == ("row",):
            data[name] = var.squeeze("row")
    phases = _h5.text(f["evaluations"].attrs.get("phases", ""))
    coords["phase"] = ("evaluation", np.array(phases.split(",") if phases else [], dtype=object),
                       {"description": "search phase of each evaluation"})
    attrs = _h5.attributes(f)
    attrs["value_meaning"] = _h5.text(f["evaluations"].attrs.get("value_meaning", ""))
    if "fem_verification" in f:
        attrs.update({f"fem_verification_{k}": v for k, v in _h5.attributes(f["fem_verification"]).items()})
    if "variants" in f:  # -design_variants: the files and the options each set
        attrs.update({f"variants_{k}": v for k, v in _h5.attributes(f["variants"]).items() if k in ("files", "options")})
    if "provenance" in f:
        attrs.update(_h5.provenance(f["provenance"]))
    return xr.Dataset(data, coords, attrs), {}
