#!/usr/bin/python3
"""A FEM sweep file has the spring-block ensemble's layout with the FEM's own names: the same
root attributes but the lattice's (map_side, first_slip_map, friction_fields), the same datasets
but what only the spring-block model has (/maps, /realisations/redrawn_blocks, /sweep/sigma,
/sweep/sigma_kinetic, the block_row and block_column axes) with the same types, ranks and units,
the dimension scales of the ensemble with the bottom cells (cell_x, cell_y) for the lattice's
block_column and block_row, the same /sweep columns (the swept field values included), per-point
property maps over the bottom cells under property fields, and the FEM's own format name, format
version 4 and one run per point.

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
        lattice = {"map_side", "first_slip_map", "friction_fields"}
        if set(fem.attrs) != set(sbm.attrs) - lattice:
            problems.append(f"root attributes differ: {sorted(set(fem.attrs) ^ (set(sbm.attrs) - lattice))}")
        if fem.attrs["format_version"] != 5 or sbm.attrs["format_version"] != 3:
            problems.append(f"format versions {fem.attrs['format_version']}, ensemble {sbm.attrs['format_version']}")
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
        spring_block = {"realisations/redrawn_blocks", "sweep/sigma", "sweep/sigma_kinetic", "block_row", "block_column"}
        cells = {"cell_x"} | ({"cell_y"} if "cell_y" in fem else set())
        cells |= {"realisations/nodes_slid_above_one", "realisations/area_slid_above_one"}  # the FEM's flutter flag
        wanted = {n for n in a if not n.startswith("maps/") and n not in spring_block} | cells
        if wanted != set(b):
            problems.append(f"datasets differ: {sorted(wanted ^ set(b))}")
        renamed = {"/block_column": "/cell_x", "/block_row": "/cell_y"}
        for name in sorted(wanted & set(b) - cells):
            x, y = a[name], b[name]
            if x.dtype.kind != y.dtype.kind or x.ndim != y.ndim:
                problems.append(f"{name}: {y.dtype}/{y.ndim}D, ensemble {x.dtype}/{x.ndim}D")
            if x.attrs.get("units") != y.attrs.get("units"):
                problems.append(f"{name}: units {y.attrs.get('units')!r}, ensemble {x.attrs.get('units')!r}")
            expected = [[renamed.get(s, s) for s in axis] for axis in scales(x)]
            if not name.startswith("run/") and expected != scales(y):
                problems.append(f"{name}: dimension scales {scales(y)}, ensemble's with the bottom cells {expected}")
        nx, ny = int(fem["scene"].attrs["fem_nx"]), int(fem["scene"].attrs["fem_ny"])
        if fem["cell_x"].shape != (nx,) or fem["cell_x"].attrs["units"] != "m":
            problems.append(f"cell_x: {fem['cell_x'].shape} {fem['cell_x'].attrs['units']!r}, not fem_nx = {nx} centres in m")
        if fem["sweep"].attrs["axes"] != sbm["sweep"].attrs["axes"]:
            problems.append(f"sweep axes {fem['sweep'].attrs['axes']!r}, ensemble {sbm['sweep'].attrs['axes']!r}")
        if list(fem["sweep/delta"][:]) != list(sbm["sweep/delta"][:]):
            problems.append("sweep/delta differs from the ensemble's (same lists, same construction)")
        if ("field_value" in fem["sweep"]) != ("field_value" in sbm["sweep"]) or (
                "field_value" in fem["sweep"] and list(fem["sweep/field_value"][:]) != list(sbm["sweep/field_value"][:])):
            problems.append("sweep/field_value differs from the ensemble's (same -ensemble_field lists)")
        for name in ("E_map", "mu_s_map", "mu_k_map", "p_map"):  # property fields: every point's maps
            want = (fem.attrs["points"], ny, nx)
            if name in sbm["properties"] and fem[f"properties/{name}"].shape != want:
                problems.append(f"properties/{name}: shape {fem[f'properties/{name}'].shape}, not {want} (the bottom cells)")
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
