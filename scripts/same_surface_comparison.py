#!/usr/bin/env python3
"""The spring blocks and the FEM on the same random surfaces, realisation by realisation.

Takes a gradfric ensemble file and a gradfric-fem ensemble file run on the same surfaces (the
same seed: -ensemble_seed = -fem_seed, -ensemble_common_streams on, the same -surface_ options)
and the same sweep points. Pairs the points by (property, profile, Delta, theta) and realisation r
with r, and writes one row per point and quantity (TSV on stdout):

  quantity  point  sbm_mean  fem_mean  diff_mean  diff_ci95  diff_std  correlation  pairs

quantity is mu_s, or reduction: the per-realisation relative variation mu_s / mu_s,0 - 1 against
the non-graded point of the same realisation (the same surface). diff = SBM - FEM per
realisation; diff_ci95 is the Student t half-width of its mean; correlation is Pearson's between
the two models' per-realisation values (NaN for fewer than 3 pairs or no spread).
Usage: same_surface_comparison.py sbm.h5 fem.h5 > rows.tsv
"""
import sys

import h5py
import numpy as np

# Student t(0.975, dof) for dof 1..30 (beyond: the normal 1.96 is within 2 %).
T95 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160, 2.145,
       2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042]


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def points(f):
    """(property, profile, delta, theta) of each point; every non-graded point is one plate."""
    out = []
    for p in range(len(f["sweep/delta"])):
        delta = float(f["sweep/delta"][p])
        key = ("-", "-", 0.0) if delta == 0.0 else (text(f["sweep/property"][p]), text(f["sweep/profile"][p]), delta)
        out.append(key + (float(f["sweep/theta"][p]),))
    return out


def finished(f, name):
    values = f["realisations/" + name][...].astype(float)
    values[f["realisations/done"][...] == 0] = np.nan
    return values


def row(quantity, label, a, b):
    ok = np.isfinite(a) & np.isfinite(b)
    a, b = a[ok], b[ok]
    n = len(a)
    d = a - b
    half = T95[min(n - 1, len(T95)) - 1] * d.std(ddof=1) / np.sqrt(n) if n > 1 else np.nan
    corr = np.corrcoef(a, b)[0, 1] if n > 2 and a.std() > 0 and b.std() > 0 else np.nan
    return (f"{quantity}\t{label}\t{a.mean():.6f}\t{b.mean():.6f}\t{d.mean():+.6f}\t{half:.6f}\t"
            f"{d.std(ddof=1) if n > 1 else np.nan:.6f}\t{corr:.3f}\t{n}")


def main(sbm_path, fem_path):
    with h5py.File(sbm_path, "r") as s, h5py.File(fem_path, "r") as f:
        sbm_points, fem_points = points(s), points(f)
        sbm_mu, fem_mu = finished(s, "mu_s"), finished(f, "mu_s")
        sbm_ref, fem_ref = s["sweep/reference_point"][...], f["sweep/reference_point"][...]
        print("quantity\tpoint\tsbm_mean\tfem_mean\tdiff_mean\tdiff_ci95\tdiff_std\tcorrelation\tpairs")
        seen = set()
        for q, key in enumerate(fem_points):
            if key in seen or key not in sbm_points:
                continue  # a repeated non-graded point, or one the spring blocks lack
            seen.add(key)
            p = sbm_points.index(key)
            r = min(sbm_mu.shape[1], fem_mu.shape[1])  # realisation r with r
            label = "Delta=0" if key[2] == 0.0 else f"{key[0]} {key[1]} Delta={key[2]:g}"
            if key[3] != 0.0:
                label += f" theta={key[3]:g}"
            print(row("mu_s", label, sbm_mu[p, :r], fem_mu[q, :r]))
            if key[2] != 0.0 and sbm_ref[p] >= 0 and fem_ref[q] >= 0:
                sbm_red = sbm_mu[p, :r] / sbm_mu[sbm_ref[p], :r] - 1
                fem_red = fem_mu[q, :r] / fem_mu[fem_ref[q], :r] - 1
                print(row("reduction", label, sbm_red, fem_red))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
