#!/usr/bin/python3
"""The figure of a calibration (docs/calibration.md): the reference mu(t) and the calibrated
spring-block ensemble's mean mu(t), from the CSV gradfric-calibrate writes with -calibrate_curve.

    /usr/bin/python3 scripts/plot_calibration.py curves.csv out.png [--title TEXT]

Needs Debian's python3-numpy and python3-matplotlib.
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("curves", help="CSV t, mu_reference, mu_sbm_mean (gradfric-calibrate -calibrate_curve)")
    parser.add_argument("png", help="figure to write")
    parser.add_argument("--title", default="", help="figure title")
    args = parser.parse_args()
    data = np.genfromtxt(args.curves, delimiter=",", names=True)
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(data["t"] * 1e6, data["mu_reference"], "-", lw=1.6, label="reference (FEM)")
    ax.plot(data["t"] * 1e6, data["mu_sbm_mean"], "--", lw=1.4, label="calibrated spring blocks (ensemble mean)")
    ax.set_xlabel("time since the start of sliding [us]")
    ax.set_ylabel("mu(t)")
    if args.title:
        ax.set_title(args.title, fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    print(f"plot_calibration: wrote {args.png}")


if __name__ == "__main__":
    main()
