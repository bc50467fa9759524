#!/usr/bin/python3
"""A FEM sweep file has the spring-block ensemble's layout: the same root attributes, the same
datasets (but /maps, which only the spring-block model fills) with the same types, ranks, units
and dimension scales, the same /sweep columns (the swept field values included), the same
per-point property maps under property fields, and the FEM's own format name and one run per point.

    check_sweep_layout.py SBM_ENSEMBLE.h5 FEM_SWEEP.h5
"""
import sys

import h5py


def datasets(f):
    found = {}
    f.visititems(lambda name, obj: found.__setitem__(name, obj) if isinstance(obj, h5py.Dataset) else None)
    return found


def scales(d):
    return [[s.name for s in dim.values()] for dim in d.dims]


def main(sbm_path, fem_path):
    problems = []
    with h5py.File(sbm_path, "r") as sbm, h5py.File(fem_path, "r") as fem:
        if fem.attrs["format"] != "gradfric-fem-sweep":
            problems.append(f"format {fem.attrs['format']}")
        if sbm.attrs["format"] != "gradfric-sbm-ensemble":
            problems.append(f"reference format {sbm.attrs['format']}")
        if set(fem.attrs) != set(sbm.attrs):
            problems.append(f"root attributes differ: {sorted(set(fem.attrs) ^ set(sbm.attrs))}")
        if fem.attrs["realisations"] != 1 or fem.attrs["complete"] != 1:
            problems.append("not one complete run per point")
        a, b = datasets(sbm), datasets(fem)
        # Both hold each point's discretisation bar, the same fields for both models (relative
        # uncertainty, order, safety factor, extrapolated value, half-width; NaN: not measured).
        bars = {f"statistics/{m}_discretisation_{t}" for m in ("mu_s", "mu_k")
                for t in ("error", "order", "safety_factor", "extrapolated", "half_width")}
        if not bars <= set(b) or not bars <= set(a):
            problems.append(f"missing error bars: {sorted((bars - set(b)) | (bars - set(a)))}")
        old = {f"statistics/{m}_discretisation_{t}" for m in ("mu_s", "mu_k") for t in ("lattice", "dt")}
        if old & (set(a) | set(b)):
            problems.append(f"the old bar terms are still written: {sorted(old & (set(a) | set(b)))}")
        for name in ("statistics/mu_s_discretisation_error", "statistics/mu_k_discretisation_error"):
            for model, f in (("FEM", fem), ("ensemble", sbm)):
                if name in f and not {"convergence", "fit", "ladder", "basis"} <= set(f[name].attrs):
                    problems.append(f"{model} {name}: attributes {sorted(f[name].attrs)}")
        wanted = {n for n in a if not n.startswith("maps/")}
        if wanted != set(b):
            problems.append(f"datasets differ: {sorted(wanted ^ set(b))}")
        for name in sorted(wanted & set(b)):
            x, y = a[name], b[name]
            if x.dtype.kind != y.dtype.kind or x.ndim != y.ndim:
                problems.append(f"{name}: {y.dtype}/{y.ndim}D, ensemble {x.dtype}/{x.ndim}D")
            if x.attrs.get("units") != y.attrs.get("units"):
                problems.append(f"{name}: units {y.attrs.get('units')!r}, ensemble {x.attrs.get('units')!r}")
            if not name.startswith("run/") and scales(x) != scales(y):
                problems.append(f"{name}: dimension scales {scales(y)}, ensemble {scales(x)}")
        if fem["sweep"].attrs["axes"] != sbm["sweep"].attrs["axes"]:
            problems.append(f"sweep axes {fem['sweep'].attrs['axes']!r}, ensemble {sbm['sweep'].attrs['axes']!r}")
        if list(fem["sweep/delta"][:]) != list(sbm["sweep/delta"][:]):
            problems.append("sweep/delta differs from the ensemble's (same lists, same construction)")
        if ("field_value" in fem["sweep"]) != ("field_value" in sbm["sweep"]) or (
                "field_value" in fem["sweep"] and list(fem["sweep/field_value"][:]) != list(sbm["sweep/field_value"][:])):
            problems.append("sweep/field_value differs from the ensemble's (same -ensemble_field lists)")
        for name in ("E_map", "mu_s_map", "mu_k_map", "p_map"):  # property fields: every point's maps
            if name in sbm["properties"] and fem[f"properties/{name}"].shape != sbm[f"properties/{name}"].shape:
                problems.append(f"properties/{name}: shape {fem[f'properties/{name}'].shape}, "
                                f"ensemble {sbm[f'properties/{name}'].shape} (same map side)")
        if list(fem["sweep/reference_point"][:]) != list(sbm["sweep/reference_point"][:]):
            problems.append("sweep/reference_point differs from the ensemble's")
        if not all(fem["realisations/done"][:].ravel() == 1):
            problems.append("a point is not done")
    if problems:
        print("FAILED: " + "; ".join(problems))
        return 1
    print("sweep layout OK")
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:3]))
