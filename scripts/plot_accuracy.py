#!/usr/bin/python3
"""Work-precision plots of an accuracy-cost study (gradfric-study): error of the global mu_s and
mu_k against wall time per realisation, one curve per knob.

    /usr/bin/python3 scripts/plot_accuracy.py results/study_sbm.h5 docs/accuracy_sbm.png

Reads the study with gradfric.open (python/gradfric). Needs Debian's python3-h5py, python3-xarray
and python3-matplotlib (installed by scripts/setup.sh).
"""
import os
import sys

import matplotlib

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "python"))  # as gradfric_plot.py
import gradfric  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LABELS = {
    "dt_rk4": "time step, RK4",
    "dt_verlet": "time step, velocity Verlet",
    "N": "lattice size N_b (vs the largest)",
    "R": "realisations R (statistical error)",
    "dt_gfverlet": "FEM dt safety, gfverlet (50x50x2)",
    "dt_ssp": "FEM dt safety, PETSc SSP (50x50x2)",
    "dt_fine_mesh": "FEM dt safety, gfverlet (100x100x5)",
    "kn": "FEM k_n factor (vs 30x default)",
    "kt": "FEM k_t factor (vs 30x default)",
    "mesh": "FEM mesh nx (vs 100x100x5)",
}


def main(path, png):
    try:
        ds = gradfric.open(path)
    except (ValueError, OSError) as error:
        sys.exit(f"{path} is not a gradfric accuracy study ({error})")
    with ds:
        if ds.attrs.get("format") != "gradfric-accuracy-study":
            sys.exit(f"{path} is not a gradfric accuracy study")
        fig, axes = plt.subplots(1, 2, figsize=(12, 4.8), sharey=False)
        for ax, quantity in zip(axes, ("mu_s", "mu_k")):
            for name in ds["ladder"].values:
                ladder = ds.sel(ladder=name).isel(rung=slice(0, int(ds["rungs"].sel(ladder=name))))
                wall = ladder["wall_seconds"].values
                error = ladder[f"{quantity}_error"].values
                setting = ladder["setting"].values
                keep = error > 0  # the reference rung has no error of its own
                if not keep.any():
                    continue
                ax.loglog(wall[keep], error[keep], "o-", label=LABELS.get(name, name))
                for w, e, s in zip(wall[keep], error[keep], setting[keep]):
                    ax.annotate(f"{s:.3g}", (w, e), textcoords="offset points", xytext=(4, 3), fontsize=7)
            ax.axhline(1e-2, color="grey", lw=0.8, ls="--")
            ax.axhline(1e-3, color="grey", lw=0.8, ls=":")
            ax.set_xlabel("wall time per realisation [s]")
            ax.set_ylabel(f"relative error of global {quantity}")
            ax.set_title(f"{quantity}: what accuracy costs")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=8)
        fig.suptitle(f"gradfric accuracy study ({path})", fontsize=9)
        fig.tight_layout()
        fig.savefig(png, dpi=110)
        print(f"wrote {png}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
