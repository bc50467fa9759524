#!/usr/bin/env python3
"""A figure of the FEM-measured pressure response g (docs/fields.md): maps and profiles along x.

Each argument is label=file, a gradfric-fem results file (or a shipped input/fields/
pressure_response_*.h5) with /fem/pressure_response/g (shipped: /pressure_response/g). The first one is the reference whose map is
drawn with each other's difference from it. Top row: the maps (the first g, then g - g_first for
up to three others); bottom row: g along x through the plate's centre line over the whole plate,
then near the trailing (x = 0) and the leading (x = L) edge, the FEM's nodes as lines and the
spring-block model's block centres (bilinear, as -pressure_response fem samples it, mean removed)
as markers.
  python3 scripts/pressure_response_plot.py -o docs/figures/pressure_response_g.png \\
      non-graded=input/fields/pressure_response_fem100.h5 "E +0.2=run_E+0.2.h5" ...
Headless (matplotlib Agg).
"""
import argparse
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pressure_response_fit import sample  # noqa: E402


def read(path):
    with h5py.File(path, "r") as f:
        d = f["fem/pressure_response/g" if "fem" in f else "pressure_response/g"]  # shipped files: /pressure_response
        return d[...], [float(v) for v in d.attrs["extent"]], float(d.attrs["moment_over_H"])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("-o", "--output", required=True, help="PNG to write")
    ap.add_argument("--blocks", type=int, default=120, help="spring-block lattice N (markers)")
    ap.add_argument("--length", type=float, default=5e-3, help="plate side L [m]")
    ap.add_argument("--thickness", type=float, default=5e-5, help="plate thickness H [m]")
    ap.add_argument("--edge", type=float, default=6.0, help="width of the edge panels, in H")
    ap.add_argument("runs", nargs="+", help="label=file")
    a = ap.parse_args()
    runs = []
    for item in a.runs:
        if "=" not in item:
            sys.exit(f"pressure_response_plot: '{item}' is not label=file")
        label, path = item.split("=", 1)
        g, extent, moment = read(path)
        runs.append((label, g, extent, moment))
    L, H = a.length, a.thickness
    mm = 1e3
    maps = runs[: min(len(runs), 4)]
    fig = plt.figure(figsize=(4.2 * max(len(maps), 3), 8.2))
    grid = fig.add_gridspec(2, max(len(maps), 3), height_ratios=[1.0, 0.9])
    reference = maps[0][1]
    for k, (label, g, extent, moment) in enumerate(maps):
        ax = fig.add_subplot(grid[0, k])
        box = [e * mm for e in extent]
        if k == 0:
            lim = np.abs(g).max()
            im = ax.imshow(g, origin="lower", extent=box, cmap="RdBu_r", vmin=-lim, vmax=lim)
            ax.set_title(f"g, {label} (moment {moment:.3f} H)", fontsize=9)
        else:
            if g.shape != reference.shape:
                sys.exit(f"pressure_response_plot: {label} is on another node grid than {maps[0][0]}")
            diff = g - reference
            lim = np.abs(diff).max()
            im = ax.imshow(diff, origin="lower", extent=box, cmap="PuOr_r", vmin=-lim, vmax=lim)
            ax.set_title(f"g({label}) - g({maps[0][0]}) (moment {moment:.3f} H)", fontsize=9)
        ax.set_xlabel("x [mm] (sliding along +x)")
        ax.set_ylabel("y [mm]")
        fig.colorbar(im, ax=ax, fraction=0.046, pad=0.03)
    n = a.blocks
    centres = (np.arange(n) + 0.5) * L / n
    panels = [("whole plate", 0.0, L), ("trailing edge", 0.0, a.edge * H), ("leading edge", L - a.edge * H, L)]
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, (title, lo, hi) in enumerate(panels):
        ax = fig.add_subplot(grid[1, k])
        for j, (label, g, extent, moment) in enumerate(runs):
            ny, nx = g.shape
            x = extent[0] + (np.arange(nx) + 0.5) * (extent[1] - extent[0]) / nx
            row = g[ny // 2, :]
            c = colours[j % len(colours)]
            ax.plot(x / H, row, "-", color=c, lw=1.2, label=f"{label}, FEM nodes")
            blocks = sample(g, extent, n, L)
            blocks = blocks - blocks.mean()
            keep = (centres >= lo) & (centres <= hi)
            if k > 0:
                ax.plot(centres[keep] / H, blocks[n // 2, keep], "o", color=c, ms=4, mfc="none",
                        label=f"{label}, {n} blocks")
        ax.set_xlim(lo / H, hi / H)
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.set_xlabel("x / H")
        ax.set_ylabel("g on the centre line y = L/2")
        ax.set_title(title, fontsize=9)
        ax.grid(alpha=0.3)
        if k == 1:
            ax.legend(fontsize=7)
    fig.suptitle("Pressure response g = (1/p) dp_c/dmu measured by gradfric-fem over the loading phase", fontsize=11)
    fig.tight_layout()
    fig.savefig(a.output, dpi=110)
    print(f"pressure_response_plot: wrote {a.output}")


if __name__ == "__main__":
    main()
