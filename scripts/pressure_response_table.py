#!/usr/bin/env python3
"""Tables of the pressure-coupled spring-block sweeps (docs/fields.md): mu_s per Delta with its
standard error for each results file, and the asymmetry A = (mu_s(+D) - mu_s(-D)) / mu_s(0) with
its error propagated from the three standard errors.
  python3 scripts/pressure_response_table.py label=results.h5 ...
"""
import sys

import h5py
import numpy as np


def read(path):
    with h5py.File(path, "r") as f:
        s = f["/statistics"]
        return f["/sweep/delta"][...], s["mu_s_mean"][...], s["mu_s_stderr"][...], s["mu_s_count"][...]


def main():
    runs = [a.split("=", 1) for a in sys.argv[1:]]
    data = {label: read(path) for label, path in runs}
    deltas = next(iter(data.values()))[0]
    print("| Delta | " + " | ".join(label for label, _ in runs) + " |")
    print("|---" * (len(runs) + 1) + "|")
    for i, d in enumerate(deltas):
        cells = []
        for label, _ in runs:
            _, m, e, n = data[label]
            cells.append(f"{m[i]:.4f} +- {e[i]:.4f}")
        print(f"| {d:+.1f} | " + " | ".join(cells) + " |")
    for amplitude in sorted({abs(d) for d in deltas if d != 0}):
        cells = []
        for label, _ in runs:
            delta, m, e, _ = data[label]
            p, q, z = (int(np.argmin(abs(delta - v))) for v in (amplitude, -amplitude, 0.0))
            a = (m[p] - m[q]) / m[z]
            err = np.sqrt(e[p] ** 2 + e[q] ** 2 + (a * e[z]) ** 2) / m[z]
            cells.append(f"{100 * a:+.2f} +- {100 * err:.2f} %")
        print(f"| A({amplitude:.1f}) | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
