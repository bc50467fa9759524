#!/usr/bin/env python3
"""The FEM convergence study's tables (docs/accuracy_fem.md) from its measurements
(docs/fem_study.tsv), by the rule the code's error bar uses (scripts/ladder_rule.py, core/refinement_ladder.hpp): a ladder
of three in-plane meshes at ratio 2 converges when its differences shrink with
an observed order p > 0.5 (second difference below 1/sqrt(2) of the first); then, if they keep
their sign, the Richardson extrapolation (p capped at 2) and Roache's GCI 1.25 |mu(n) - mu_ext| /
mu_ext of each mesh; if they alternate, 1.25 x the distance to the farther of the last two values
(the limit lies between them); otherwise no bar.

    fem_study_table.py [docs/fem_study.tsv]     prints Markdown tables
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ladder_rule import judge  # noqa: E402  the rule the code's bars use

G, H, P = 10e6 / (2 * (1 + 1 / 3)), 5e-5, 1e4


def load(path, edge=(1.0, 0.0)):
    """The rows of one mesh family: edge = (edge_ratio, edge_band), (1, 0) the uniform meshes."""
    rows = {}
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            law, dc, prop, delta, n, nz, ratio, band, element, dts, contact, mu = line.split()
            if float(ratio) != edge[0] or (edge[0] != 1.0 and abs(float(band) - edge[1]) > 1e-9 * edge[1]):
                continue
            rows[(law, float(dc), prop, float(delta), int(n), int(nz), element, float(dts), contact)] = float(mu)
    return rows


def ladder(rows, law, dc, prop, delta, nz=5, contact="penalty"):
    sizes = sorted(k[4] for k in rows if k[:4] == (law, dc, prop, delta) and k[5] == nz and k[7] == 0.6 and k[8] == contact)
    for n in sizes:
        key = lambda m: (law, dc, prop, delta, m, nz, "q1", 0.6, contact)
        if key(2 * n) in rows and key(4 * n) in rows:
            return n, [rows[key(n)], rows[key(2 * n)], rows[key(4 * n)]]
    return None, None


def analyse(mu):
    """(differences, order, extrapolated, bounds of the three members) by the shared rule."""
    v = [judge(mu, member) for member in range(3)]
    first, second = v[0]["first"], v[0]["second"]
    d = "%+.2f %%, %+.2f %%" % (100 * first / mu[0], 100 * second / mu[1])
    if v[0]["outcome"] == "not converged":
        why = "signs differ, no shrinking" if first * second <= 0 else "order <= 0.5"
        return d, "none (%s)" % why, "", "not converged: no bar"
    bounds = " / ".join("%.2f %%" % (100 * m["bound"]) for m in v)
    if v[0]["outcome"] == "oscillating":
        return d, "oscillating", "between %.6f and %.6f" % (mu[1], mu[2]), bounds
    return d, "%.2f" % v[0]["order"], "%.6f" % v[0]["extrapolated"], bounds


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "docs", "fem_study.tsv")
    rows = load(path)
    print("| D_c [m] | kappa | grading | mu_s at n, 2n, 4n (x 5) | differences | observed order | extrapolated | GCI of n / 2n / 4n |")
    print("|---|---|---|---|---|---|---|---|")
    # The penalty contact's ladders, then those with the Prakash-Clifton filter ("penalty,pc=L/V*").
    seen = sorted({(k[8] != "penalty", k[8], k[0], k[1], k[2], k[3]) for k in rows if k[8].startswith("penalty")})
    for _, contact, law, dc, prop, delta in seen:
        n, mu = ladder(rows, law, dc, prop, delta, contact=contact)
        if not mu:
            continue
        kappa = G * dc / (H * P * 0.4)
        grading = "none" if prop == "none" else "%s %+.1f" % (prop, delta)
        if contact != "penalty":
            grading += ", filter L/V* " + contact.split("=", 1)[1]
        d, p, ext, gci = analyse(mu)
        print("| %g | %.2f | %s | %d/%d/%d: %s | %s | %s | %s | %s |" % (
            dc, kappa, grading, n, 2 * n, 4 * n, ", ".join("%.6f" % m for m in mu), d, p, ext, gci))
    print()
    print("Refinement in every direction, thickness and time step (non-graded, D_c 2.5e-8 m; the thickness and")
    print("time-step ladders on the 100 x 100 mesh):")
    print()
    print("| ladder | mu_s | differences | observed order | extrapolated | bounds of its members |")
    print("|---|---|---|---|---|---|")
    base = ("state", 2.5e-8, "none", 0.0, 100, 5, "q1", 0.6, "penalty")
    gradings = [("none", 0.0)] + sorted({(k[2], k[3]) for k in rows if k[2] != "none" and k[1] == 2.5e-8})
    ladders = [("all directions 50x50x5/100x100x10/200x200x20" + ("" if prop == "none" else ", %s %+.1f" % (prop, delta)),
                [base[:2] + (prop, delta, n, nz) + base[6:] for n, nz in ((50, 5), (100, 10), (200, 20))])
               for prop, delta in gradings]
    ladders += [("nz 5/10/20", [base[:5] + (nz,) + base[6:] for nz in (5, 10, 20)]),
               ("dt_safety 0.6/0.3/0.15", [base[:7] + (dts,) + base[8:] for dts in (0.6, 0.3, 0.15)])]
    for label, keys in ladders:
        if all(k in rows for k in keys):
            mu = [rows[k] for k in keys]
            d, p, ext, bounds = analyse(mu)
            print("| %s | %s | %s | %s | %s | %s |" % (label, ", ".join("%.6f" % m for m in mu), d, p, ext, bounds))
    kinematic = base[:8] + ("kinematic",)
    if kinematic in rows:
        print()
        print("Kinematic contact (the exact reference): %.6f against the penalty's %.6f (%+.3f %%)"
              % (rows[kinematic], rows[base], 100 * (rows[base] / rows[kinematic] - 1)))

if __name__ == "__main__":
    main()
