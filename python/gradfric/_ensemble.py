"""The ensemble layout (docs/ensemble.md, section 5): a spring-block ensemble (gradfric) or a FEM
sweep (gradfric-fem with sweep lists), one row of /sweep per point."""
import numpy as np
import xarray as xr

from . import _h5

FORMATS = ("gradfric-sbm-ensemble", "gradfric-fem-sweep")
# Groups whose datasets keep their own names; /properties and /run are prefixed (their names
# repeat /realisations').
_PLAIN = {"sweep", "realisations", "statistics", "history", "maps"}
# /run's per-task tables have no scales (so that h5diff --exclude-path /run is blind to them).
_RUN_DIMS = {"run/wall_seconds": ["point", "realisation"], "run/rank": ["point", "realisation"]}


def read(f):
    coords, data = _h5.collect(f, _PLAIN, _RUN_DIMS)
    # The sweep table and the sample times describe the points and samples: coordinates.
    for name in [k for k in data if data[k].attrs["hdf5_path"].startswith("/sweep/")]:
        coords[name] = data.pop(name)
    for name in ("time", "snapshot_times"):
        if name in data:
            coords[name] = data.pop(name)
    scene = _h5.option_record(f["scene"])
    # Block centres [m]: column i of N covers [i, i + 1) L / N (also the FEM sweep's cell columns).
    side = scene.get("plate_L", scene.get("sbm_L", ("nan",)))[0]
    n = int(f.attrs["map_side"])
    centres = (np.arange(n) + 0.5) * float(side) / n
    coords["x"] = xr.Variable("block_column", centres, {"units": "m", "description": "centre of each block column along x (the grading axis)"})
    coords["y"] = xr.Variable("block_row", centres, {"units": "m", "description": "centre of each block row along y"})
    attrs = _h5.attributes(f)
    attrs["sweep_axes"] = _h5.text(f["sweep"].attrs.get("axes", ""))
    attrs.update({k: v[0] for k, v in scene.items()})
    attrs["scene_options"] = list(scene)
    attrs.update(_h5.provenance(f["run"]))
    return xr.Dataset(data, coords, attrs), scene
