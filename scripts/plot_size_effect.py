#!/usr/bin/python3
"""The size effect of the random surface: the non-graded mu_s and the reduction by a grading
against the correlation length l_c / L, one curve per dispersion sigma and model, in one figure.

    /usr/bin/python3 scripts/plot_size_effect.py out.png out.tsv sbm_*.h5 fem_*.h5

Each file is a finished gradfric or gradfric-fem ensemble with a non-graded point (Delta 0) and
graded points of one grading (its reference is the non-graded point): l_c is its /scene
surface_length; sigma is each point's /sweep/sigma (spring blocks, a sigma sweep) or /scene
surface_sigma_s (FEM). Writes the points as TSV (model, l_c/L, sigma, delta, mu_s, ci95,
reduction, ci95) and the figure: (a) mu_s at Delta 0, (b) the relative variation at each graded
Delta, both with their 95 % intervals.
"""
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def scene(f, name):
    value = f["scene"].attrs[name]
    return float(value.decode() if isinstance(value, bytes) else value)


def rows_of(path):
    with h5py.File(path, "r") as f:
        model = "FEM" if "fem" in str(f.attrs["format"]) else "SBM"
        length = scene(f, "surface_length") / scene(f, "plate_L") if "plate_L" in f["scene"].attrs else None
        if length is None:
            length = scene(f, "surface_length") / 5e-3  # the paper's plate, L = 5 mm
        st = f["statistics"]
        sigmas = f["sweep/sigma"][...] if "sigma" in f["sweep"] else np.full(len(f["sweep/delta"]),
                                                                              scene(f, "surface_sigma_s"))
        half = st["mu_s_ci95_high"][...] - st["mu_s_mean"][...]
        for p, delta in enumerate(f["sweep/delta"][...]):
            yield (model, length, float(sigmas[p]), float(delta), float(st["mu_s_mean"][p]), float(half[p]),
                   float(st["mu_s_relative"][p]), float(st["mu_s_relative_ci95"][p]))


def main(png, tsv, paths):
    rows = [r for path in paths for r in rows_of(path)]
    with open(tsv, "w") as out:
        out.write("model\tlc_over_L\tsigma\tdelta\tmu_s\tmu_s_ci95\treduction\treduction_ci95\n")
        for r in sorted(rows):
            out.write("%s\t%.6g\t%.4g\t%.3g\t%.6f\t%.6f\t%.6f\t%.6f\n" % r)
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    styles = {"SBM": ("o", "-"), "FEM": ("s", "--")}  # the model by marker and line, sigma by colour
    sigmas = sorted({r[2] for r in rows})
    colour = {s: f"C{i}" for i, s in enumerate(sigmas)}
    for model in ("SBM", "FEM"):
        for sigma in sorted({r[2] for r in rows if r[0] == model}):
            for delta in sorted({r[3] for r in rows if r[0] == model and r[2] == sigma}):
                sel = sorted((r for r in rows if r[0] == model and r[2] == sigma and r[3] == delta), key=lambda r: r[1])
                x = [r[1] for r in sel]
                marker, line = styles[model]
                label = f"{model}, sigma {sigma:g}"
                if delta == 0.0:
                    a.errorbar(x, [r[4] for r in sel], yerr=[r[5] for r in sel], marker=marker, ls=line, capsize=3,
                               color=colour[sigma], label=label)
                else:
                    b.errorbar(x, [100 * r[6] for r in sel], yerr=[100 * r[7] for r in sel], marker=marker, ls=line,
                               capsize=3, color=colour[sigma], label=f"{label}, Delta {delta:g}")
    for ax, where in ((a, "center right"), (b, "upper left")):
        ax.set_xscale("log")
        ax.set_xlabel("correlation length l_c / L")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc=where)
    a.set_ylabel("mu_s, non-graded plate (95 % CI)")
    b.set_ylabel("relative variation of mu_s [%] (95 % CI)")
    a.set_title("(a) non-graded plate")
    b.set_title("(b) reduction by the grading")
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3:])
