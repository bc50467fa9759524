#!/usr/bin/env python3
"""The spring-block discretisation study's table (docs/accuracy.md, "The discretisation bar") from
its measurements (docs/sbm_study.tsv), by the rule of the code's bar
(src/ensemble/sbm_error_estimate.cpp): each difference of a lattice ladder N_b, 2 N_b, 4 N_b must
exceed its 95 % statistical half-width, and the ladder converges when the second difference stays
below 1/sqrt(2) of the first (observed order p > 0.5) across both half-widths; then Roache's GCI
(monotone; p capped at 2) or the bracket of the last two means (oscillating), widened by the
half-width of the distance, times 1.25. Otherwise no bar.

    sbm_study_table.py [docs/sbm_study.tsv]     prints a Markdown table
"""
import math
import os
import sys

from scipy.stats import t as student


def load(path):
    rows = {}
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            kind, law, grading, delta, n, observable, r, value, se, _ = line.split()
            if kind == "lattice":
                rows[(law, grading, float(delta), observable, int(n))] = (int(r), float(value), float(se))
    return rows


def half(members, c):
    """95 % half-width of sum c_i mean_i, t of the smallest sample used."""
    used = [m for m, k in zip(members, c) if k]
    var = sum((k * m[2]) ** 2 for m, k in zip(members, c))
    return student.ppf(0.975, min(m[0] for m in used) - 1) * math.sqrt(var)


def verdict(m):
    """The rule on one ladder of three (R, mean, se): (text, bound of its coarsest member or None)."""
    a, b, c = (x[1] for x in m)
    d1, d2 = b - a, c - b
    h1, h2 = half(m, (-1, 1, 0)), half(m, (0, -1, 1))
    order = math.log2(abs(d1 / d2)) if d2 else math.inf
    diffs = f"{100 * d1 / a:+.3f} +- {100 * h1 / a:.3f} %, {100 * d2 / b:+.3f} +- {100 * h2 / b:.3f} %"
    if abs(d1) <= h1 or abs(d2) <= h2:
        return diffs, f"{order:.2f}", "a difference within its statistical error: proves nothing", None
    if not abs(d2) + h2 < (abs(d1) - h1) / math.sqrt(2):
        why = "<= 0.5" if order <= 0.5 else "> 0.5 only within the statistical error"
        return diffs, f"{order:.2f}", f"not converged (order {why}): no bar", None
    if d1 * d2 < 0:
        far = 1 if abs(a - b) > abs(a - c) else 2
        coeff = [1, 0, 0]
        coeff[far] -= 1
        bound = 1.25 * (abs(a - m[far][1]) + half(m, coeff)) / abs(c)
        return diffs, "oscillating", f"GCI of N_b: {100 * bound:.2f} %", bound
    r = 1 / (2 ** min(order, 2) - 1)
    ext = c + r * d2
    bound = 1.25 * (abs(a - ext) + half(m, (1, r, -1 - r))) / abs(ext)
    return diffs, f"{order:.2f}", f"extrapolated {ext:.6f}, GCI of N_b: {100 * bound:.2f} %", bound


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    rows = load(sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "docs", "sbm_study.tsv"))
    print("| observable | grading | ladder N_b | R | mean +- standard error | differences (+- 95 %) | observed order | verdict |")
    print("|---|---|---|---|---|---|---|---|")
    for key in sorted({k[:4] for k in rows}, key=lambda k: (k[3], k[1] != "none", k[2])):
        sizes = sorted(k[4] for k in rows if k[:4] == key)
        for n in sizes:
            if (*key, 2 * n) not in rows or (*key, 4 * n) not in rows:
                continue
            m = [rows[(*key, n << i)] for i in range(3)]
            diffs, order, text, _ = verdict(m)
            grading = "none" if key[1] == "none" else f"{key[1]} {key[2]:+g}"
            means = ", ".join(f"{x[1]:.6f} +- {x[2]:.6f}" for x in m)
            print(f"| {key[3]} | {grading} | {n}/{2 * n}/{4 * n} | {'/'.join(str(x[0]) for x in m)} | {means} | "
                  f"{diffs} | {order} | {text} |")


if __name__ == "__main__":
    main()
