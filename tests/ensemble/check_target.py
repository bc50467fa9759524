"""Checks a results file of a precision-target run from its raw data alone.

For every sweep point: the realisations done are the first n of the point (no gaps), n is at most
the cap, the 95 % CI half-width of the target's quantity recomputed from /realisations (Student t,
computed here, not read from /statistics) is at most the target unless the point stopped at the
cap, and /statistics agrees (finished = n, target_met). Exit 0 if all hold, 1 otherwise.
Usage: python3 check_target.py file.h5 <target> <absolute|relative|variation> [--distinct-counts]
"""
import math
import sys

import h5py
import numpy as np


def t_cdf(t, dof):
    """Student t CDF by Simpson integration of the density from 0 (t >= 0)."""
    steps = 4000
    xs = np.linspace(0.0, t, steps + 1)
    log_c = math.lgamma((dof + 1) / 2) - math.lgamma(dof / 2) - 0.5 * math.log(dof * math.pi)
    pdf = np.exp(log_c - (dof + 1) / 2 * np.log1p(xs * xs / dof))
    h = t / steps
    return 0.5 + h / 3 * (pdf[0] + pdf[-1] + 4 * pdf[1:-1:2].sum() + 2 * pdf[2:-1:2].sum())


def t975(dof):
    lo, hi = 0.0, 100.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if t_cdf(mid, dof) < 0.975 else (lo, mid)
    return 0.5 * (lo + hi)


path, target, kind = sys.argv[1], float(sys.argv[2]), sys.argv[3]
distinct = "--distinct-counts" in sys.argv
problems = []
with h5py.File(path, "r") as f:
    mu = f["realisations/mu_s"][()]
    done = f["realisations/done"][()] != 0
    ref = f["sweep/reference_point"][()]
    cap = int(f.attrs["realisations"])
    finished = f["statistics/finished"][()]
    met = f["statistics/target_met"][()]
    assert abs(t975(9) - 2.262157) < 1e-5, "t quantile check"
    counts = []
    for p in range(mu.shape[0]):
        n = int(done[p].sum())
        counts.append(n)
        if not done[p, :n].all():
            problems.append(f"point {p}: the done realisations are not the first {n}")
        if finished[p] != n:
            problems.append(f"point {p}: /statistics/finished {finished[p]} != {n}")
        x = mu[p, :n]
        if kind == "variation":
            q = ref[p]
            if q == p:
                half = 0.0
            else:
                m = min(n, int(done[q].sum()))
                y = mu[q, :int(done[q].sum())]
                xm, ym = x.mean(), y.mean()
                # Paired (first-order) error when the file says common streams, else propagated.
                common = f["scene"].attrs.get("ensemble_common_streams", b"false")
                common = (common.decode() if isinstance(common, bytes) else str(common)) == "true"
                if common:
                    z = x[:m] / mu[q, :m].mean() - x[:m].mean() * mu[q, :m] / mu[q, :m].mean() ** 2
                    err = z.std(ddof=1) / math.sqrt(m)
                else:
                    a = x.std(ddof=1) / math.sqrt(n) / ym
                    b = xm * y.std(ddof=1) / math.sqrt(len(y)) / ym**2
                    err = math.hypot(a, b)
                half = t975(m - 1) * err
        else:
            half = t975(n - 1) * x.std(ddof=1) / math.sqrt(n)
            if kind == "relative":
                half /= abs(x.mean())
        ok = half <= target * (1 + 1e-12)
        if not ok and n < cap:
            problems.append(f"point {p}: half-width {half:.6g} > target {target} with {n} < cap {cap} realisations")
        if int(met[p]) != int(ok):
            problems.append(f"point {p}: /statistics/target_met {met[p]} but half-width {half:.6g}")
        print(f"point {p}: n = {n}, half-width {half:.6g} (target {target}, {kind})")
if distinct and len(set(counts)) < 2:
    problems.append(f"every point got the same count {counts}: realisations not spent where the variance is")
if problems:
    print("\n".join(problems))
    sys.exit(1)
print("target met from the raw data:", counts)
