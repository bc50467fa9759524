#!/usr/bin/python3
"""Draw the search of a gradfric-design file.

    /usr/bin/python3 scripts/plot_design.py DESIGN.h5 [--out DIR] [--prefix NAME]

Writes <name>_search.png to DIR (default: beside the file):
  one free parameter:  every evaluation's value (mean mu_s or relative variation) against the
                       parameter with its 95 % CI, numbered in search order, the target band
                       (target +- tolerance), the design and the independent verification;
                       below, the realisations each evaluation ran;
  several parameters:  the evaluations in the plane of the first two parameters, coloured by
                       their value, joined in search order, the design marked; below, the value
                       of each evaluation in search order against the target band.
Reads the file with gradfric.open (python/gradfric). Needs Debian's python3-h5py, python3-xarray
and python3-matplotlib (scripts/setup.sh).
"""
import argparse
import os
import sys

import matplotlib
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "python"))  # as gradfric_plot.py
import gradfric  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def table(ds, group):
    """The columns of one table of the file (/evaluations, /design, ...) as arrays; None if absent."""
    columns = {v.attrs["hdf5_path"].rsplit("/", 1)[1]: np.atleast_1d(v.values) for v in ds.data_vars.values()
               if v.attrs["hdf5_path"].startswith(f"/{group}/")}
    return columns or None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("design")
    parser.add_argument("--out", default=None, help="folder of the figure (default: beside the file)")
    parser.add_argument("--prefix", default=None, help="file name prefix (default: the file's name)")
    args = parser.parse_args()
    try:
        ds = gradfric.open(args.design)
    except (ValueError, OSError) as error:
        ds, reason = None, error
    if ds is None or ds.attrs.get("format") != "gradfric-design":
        print(f"plot_design.py: {args.design} is not a gradfric-design file" + ("" if ds else f" ({reason})"), file=sys.stderr)
        return 2
    with ds:
        names = ds.attrs["free_parameters"].split(",")
        kind = ds.attrs["target_type"]
        target = float(ds.attrs["design_target"])
        tolerance = float(ds.attrs["design_tolerance"])
        status = ds.attrs["status"]
        method = ds.attrs["method"]
        ev = table(ds, "evaluations")
        phases = list(ds["phase"].values)
        design = table(ds, "design")
        verification = table(ds, "verification")
    quantity = "relative variation of $\\mu_s$" if kind == "variation" else "global $\\mu_s$"
    out = args.out or os.path.dirname(os.path.abspath(args.design))
    prefix = args.prefix or os.path.splitext(os.path.basename(args.design))[0]
    os.makedirs(out, exist_ok=True)
    value, low, high = ev["value"], ev["ci95_low"], ev["ci95_high"]
    order = np.arange(len(value))
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 7), gridspec_kw={"height_ratios": [3, 1]})
    if len(names) == 1:
        x = ev["x_" + names[0]]
        top.axhspan(target - tolerance, target + tolerance, color="tab:green", alpha=0.2, label="target $\\pm$ tolerance")
        top.errorbar(x, value, yerr=[value - low, high - value], fmt="o", color="tab:blue", capsize=3,
                     label="evaluations (95 % CI)")
        for k in order:
            top.annotate(str(k), (x[k], value[k]), textcoords="offset points", xytext=(5, 4), fontsize=8)
        xd = design["x_" + names[0]][0]
        if "x_ci95_low" in design:
            top.axvspan(design["x_ci95_low"][0], design["x_ci95_high"][0], color="tab:red", alpha=0.15)
        top.plot([xd], [design["value"][0]], "*", color="tab:red", markersize=14, label=f"design ({status})")
        v = verification
        if verification is not None:
            top.errorbar([xd], v["value"], yerr=[v["value"] - v["ci95_low"], v["ci95_high"] - v["value"]], fmt="s",
                         color="black", capsize=4, mfc="none", label="verification (independent streams)")
        top.set_xlabel(names[0])
        # An inset around the design: the last steps and the refinements.
        near = np.abs(value - target) < 12 * tolerance
        if near.sum() >= 2:
            inset = top.inset_axes([0.56, 0.1, 0.4, 0.38])
            inset.axhspan(target - tolerance, target + tolerance, color="tab:green", alpha=0.2)
            inset.errorbar(x[near], value[near], yerr=[(value - low)[near], (high - value)[near]], fmt="o",
                           color="tab:blue", capsize=3)
            for k in order[near]:
                inset.annotate(str(k), (x[k], value[k]), textcoords="offset points", xytext=(4, 3), fontsize=7)
            if "x_ci95_low" in design:
                inset.axvspan(design["x_ci95_low"][0], design["x_ci95_high"][0], color="tab:red", alpha=0.15)
            inset.plot([xd], [design["value"][0]], "*", color="tab:red", markersize=10)
            if verification is not None:
                inset.errorbar([xd], v["value"], yerr=[v["value"] - v["ci95_low"], v["ci95_high"] - v["value"]],
                               fmt="s", color="black", capsize=3, mfc="none")
            inset.tick_params(labelsize=7)
            inset.set_title("near the design", fontsize=8)
        bottom.bar(order, ev["realisations"], color=["tab:orange" if p == "refine" else "tab:blue" for p in phases])
        bottom.set_xlabel("evaluation (orange: refined to the tolerance)")
        bottom.set_ylabel("realisations")
    else:
        x, y = ev["x_" + names[0]], ev["x_" + names[1]]
        top.plot(x, y, "-", color="0.7", zorder=1)
        points = top.scatter(x, y, c=value, cmap="viridis", zorder=2)
        fig.colorbar(points, ax=top, label=quantity)
        for k in order:
            top.annotate(str(k), (x[k], y[k]), textcoords="offset points", xytext=(5, 4), fontsize=8)
        top.plot(design["x_" + names[0]], design["x_" + names[1]], "*", color="tab:red", markersize=16,
                 label=f"design ({status})")
        top.set_xlabel(names[0])
        top.set_ylabel(names[1])
        bottom.axhspan(target - tolerance, target + tolerance, color="tab:green", alpha=0.2)
        bottom.errorbar(order, value, yerr=[value - low, high - value], fmt="o", capsize=2)
        bottom.set_xlabel("evaluation")
        bottom.set_ylabel(quantity)
    if len(names) == 1:
        top.set_ylabel(quantity)
    top.set_title(f"gradfric-design ({method}): {quantity} = {target:g} $\\pm$ {tolerance:g}")
    top.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(out, prefix + "_search.png")
    fig.savefig(path, dpi=120)
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
