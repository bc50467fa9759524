#!/usr/bin/env python3
"""Stand-ins for gradfric-fem pressure-response files, for the per-grading tests: a g on a 21 x 21
node grid (pixel centres on the nodes) and a /scene record holding the grading it was "measured"
under, as gradfric-fem writes them. Each g is a different edge-concentrated tilt, so a run that is
handed the wrong one gives other numbers.
  make_response_files.py <folder>
writes none.h5 (non-graded), E+0.2.h5, E-0.2.h5, and for the refusals noscene.h5 (no /scene),
fields.h5 (a run with a property field), E+0.2-copy.h5 (the same grading again).
"""
import sys

import h5py
import numpy as np

L = 5e-3


def write(path, amplitude, shift, scene):
    h = L / 20
    x = np.linspace(-1.0, 1.0, 21)
    g = amplitude * (np.tile(x**9, (21, 1)) + shift)
    with h5py.File(path, "w") as f:
        d = f.create_dataset("/pressure_response/g", data=g)
        d.attrs["extent"] = np.array([-h / 2, L + h / 2, -h / 2, L + h / 2])
        if scene is None:
            return
        s = f.create_group("scene")
        record = {"grading_profile": "none", "grading_property": "E", "grading_delta": "0", "grading_bands": "10",
                  "plate_theta": "0", "field_E_profile": "none", "field_mu_profile": "none"}
        record.update(scene)
        for k, v in record.items():
            s.attrs[k] = v


def main():
    d = sys.argv[1]
    write(f"{d}/none.h5", 0.8, 0.0, {})
    write(f"{d}/E+0.2.h5", 0.6, 0.01, {"grading_profile": "linear", "grading_delta": "0.2"})
    write(f"{d}/E-0.2.h5", 1.0, -0.01, {"grading_profile": "linear", "grading_delta": "-0.2"})
    write(f"{d}/noscene.h5", 0.8, 0.0, None)
    write(f"{d}/fields.h5", 0.8, 0.0, {"field_E_profile": "power"})
    write(f"{d}/E+0.2-copy.h5", 0.6, 0.01, {"grading_profile": "linear", "grading_delta": "0.2"})


if __name__ == "__main__":
    main()
