#!/usr/bin/env python3
"""Keeps of a gradfric-fem results file what -pressure_response fem reads, to ship it in input/fields/.

Copies /fem/pressure_response/g (deflate-compressed, every attribute kept) and the run's /scene record
(the grading -pressure_response_select grading matches on), nothing else; prints the grading and
the g's moment.
  python3 scripts/pressure_response_extract.py run.h5 input/fields/pressure_response_fem100_E+0.2.h5
"""
import os
import sys

import h5py


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    source, target = sys.argv[1], sys.argv[2]
    if os.path.exists(target):
        sys.exit(f"pressure_response_extract: {target} exists; not replaced")
    partial = target + ".partial"
    with h5py.File(source, "r") as src, h5py.File(partial, "w") as dst:
        # a results file's /fem/pressure_response (older files: /pressure_response); the shipped
        # file keeps /pressure_response, which -pressure_response fem reads as well
        where = "fem/pressure_response" if "fem" in src and "pressure_response" in src["fem"] else "pressure_response"
        if where not in src or "g" not in src[where] or "scene" not in src:
            sys.exit(f"pressure_response_extract: {source} has no /fem/pressure_response/g or no /scene")
        g = src[where + "/g"]
        group = dst.create_group("pressure_response")
        copy = group.create_dataset("g", data=g[...], compression="gzip", compression_opts=9, shuffle=True)
        for k, v in g.attrs.items():
            if k not in ("DIMENSION_LIST", "REFERENCE_LIST", "CLASS", "NAME"):  # references into the source file
                copy.attrs[k] = v
        # The node positions (format 3) as the map's dimension scales again, in this file.
        for axis, name in ((1, "node_x"), (0, "node_y")):
            if name in src[where]:
                node = group.create_dataset(name, data=src[where][name][...])
                for k, v in src[where][name].attrs.items():
                    if k not in ("DIMENSION_LIST", "REFERENCE_LIST", "CLASS", "NAME"):
                        node.attrs[k] = v
                node.make_scale(name)
                copy.dims[axis].attach_scale(node)
        src.copy(src["scene"], dst, "scene")
        s = src["scene"].attrs
        grading = f"{s['grading_property']} {s['grading_profile']} Delta = {s['grading_delta']}"
        print(f"{target}: {grading}, moment {g.attrs['moment_over_H']:.4f} H, edges (centre line) "
              f"{g[g.shape[0] // 2, 0]:.3f} / {g[g.shape[0] // 2, -1]:.3f}")
    os.replace(partial, target)


if __name__ == "__main__":
    main()
