#!/usr/bin/env python3
"""The spring-block discretisation study's table (docs/accuracy.md, "The discretisation bar") from
its measurements (docs/sbm_study.tsv), by the rule of the code's bar
(scripts/ladder_rule.py, core/refinement_ladder.hpp): each difference of a lattice ladder N_b, 2 N_b, 4 N_b must
exceed its 95 % statistical half-width, and the ladder converges when the second difference stays
below 1/sqrt(2) of the first (observed order p > 0.5) across both half-widths; then Roache's GCI
(monotone; p capped at 2) or the bracket of the last two means (oscillating), widened by the
half-width of the distance, times 1.25. Otherwise no bar.

    sbm_study_table.py [docs/sbm_study.tsv]     prints a Markdown table
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ladder_rule import finer_not_converged, judge, through_finer  # noqa: E402  the rule the code's bars use


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


def rungs(m):
    """The rule's (value, standard error, realisations) of a ladder's three (R, mean, se) rows."""
    return [(x[1], x[2], x[0]) for x in m]


def verdict(m):
    """The shared rule on one ladder of three (R, mean, se): (differences, order, text, bound of its
    coarsest member or None)."""
    v = judge(rungs(m), 0)
    a, b = m[0][1], m[1][1]
    diffs = f"{100 * v['first'] / a:+.3f} +- {100 * v['h1'] / a:.3f} %, {100 * v['second'] / b:+.3f} +- {100 * v['h2'] / b:.3f} %"
    order = f"{v['order']:.2f}"
    if v["outcome"] == "no signal":
        return diffs, order, "a difference within its statistical error: proves nothing", None
    if v["outcome"] == "not converged":
        why = "<= 0.5" if v["order"] <= 0.5 else "> 0.5 only within the statistical error"
        return diffs, order, f"not converged (order {why}): no bar", None
    if v["outcome"] == "oscillating":
        return diffs, "oscillating", f"GCI of N_b: {100 * v['bound']:.2f} %", v["bound"]
    return diffs, order, f"extrapolated {v['extrapolated']:.6f}, GCI of N_b: {100 * v['bound']:.2f} %", v["bound"]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    rows = load(sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "docs", "sbm_study.tsv"))
    print("| observable | grading | ladder N_b | R | mean +- standard error | differences (+- 95 %) | observed order | verdict |")
    print("|---|---|---|---|---|---|---|---|")
    for key in sorted({k[:4] for k in rows}, key=lambda k: (k[3], k[1] != "none", k[2])):
        sizes = sorted(k[4] for k in rows if k[:4] == key)
        ladders = [(n, [rows[(*key, n << i)] for i in range(3)]) for n in sizes
                   if (*key, 2 * n) in rows and (*key, 4 * n) in rows]
        for i, (n, m) in enumerate(ladders):
            diffs, order, text, _ = verdict(m)
            finer = finer_not_converged([(f, rungs(fm)) for f, fm in ladders], i)
            if finer and not text.startswith(("not converged", "no signal")):
                text += f"; no bar: the finer {finer}/{2 * finer}/{4 * finer} does not converge"
            through = through_finer([(f, rungs(fm)) for f, fm in ladders], i)
            if through:
                text += f"; N_b = {n} bounded through {through[0]}: {100 * through[1]:.2f} %"
            grading = "none" if key[1] == "none" else f"{key[1]} {key[2]:+g}"
            means = ", ".join(f"{x[1]:.6f} +- {x[2]:.6f}" for x in m)
            print(f"| {key[3]} | {grading} | {n}/{2 * n}/{4 * n} | {'/'.join(str(x[0]) for x in m)} | {means} | "
                  f"{diffs} | {order} | {text} |")


if __name__ == "__main__":
    main()
