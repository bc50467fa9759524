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
from ladder_rule import finer_not_converged, judge, shares_a_limit, through_finer  # noqa: E402  the rule the code's bars use

G, H, P = 10e6 / (2 * (1 + 1 / 3)), 5e-5, 1e4


def plate_name(prop, delta, fmt="%+.1f"):
    """"friction +0.4, theta=90" for the table's "friction,theta=90" (a profile or angle after commas)."""
    if prop == "none":
        return "none"
    base, *others = prop.split(",")
    return ", ".join(["%s %s" % (base, fmt % delta)] + others)


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


def ladders(rows, law, dc, prop, delta, nz=5, contact="penalty"):
    """Every in-plane ladder n, 2n, 4n the rows hold, coarsest first: [(n, [mu(n), mu(2n), mu(4n)])]."""
    sizes = sorted(k[4] for k in rows if k[:4] == (law, dc, prop, delta) and k[5] == nz and k[7] == 0.6 and k[8] == contact)
    key = lambda m: (law, dc, prop, delta, m, nz, "q1", 0.6, contact)
    return [(n, [rows[key(n)], rows[key(2 * n)], rows[key(4 * n)]])
            for n in sizes if key(2 * n) in rows and key(4 * n) in rows]


def analyse(mu):
    """(differences, order, extrapolated, bounds of the three members) by the shared rule."""
    v = [judge(mu, member) for member in range(3)]
    first, second = v[0]["first"], v[0]["second"]
    d = "%+.3f %%, %+.3f %%" % (100 * first / mu[0], 100 * second / mu[1])
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
        kappa = G * dc / (H * P * 0.4)
        grading = plate_name(prop, delta)
        if contact != "penalty":
            grading += ", filter L/V* " + contact.split("=", 1)[1]
        found = ladders(rows, law, dc, prop, delta, contact=contact)
        for i, (n, mu) in enumerate(found):
            d, p, ext, gci = analyse(mu)
            finer = finer_not_converged(found, i)
            if finer and not gci.startswith("not converged"):
                gci = "no bar: the finer %d/%d/%d does not converge" % (finer, 2 * finer, 4 * finer)
            through = through_finer(found, i)
            every = [(law, dc, prop, delta, m, nz, "q1", 0.6, contact) for m, nz in ((50, 5), (100, 10), (200, 20))]
            if through and n == 50 and all(k in rows for k in every):
                gci = "not converged (50x50x5 takes its ladder in every direction)"
            elif through:
                gci = "not converged; %d bounded through %d: %.2f %%" % (n, through[0], 100 * through[1])
            print("| %g | %.2f | %s | %d/%d/%d: %s | %s | %s | %s | %s |" % (
                dc, kappa, grading, n, 2 * n, 4 * n, ", ".join("%.6f" % m for m in mu), d, p, ext, gci))
    print()
    print("Refinement in every direction (D_c 2.5e-8 m), and the thickness, time-step and contact terms of the")
    print("non-graded plate (100 x 100 unless said) for every D_c and filter the study has them:")
    print()
    print("| ladder | mu_s | differences | observed order | extrapolated | bounds of its members |")
    print("|---|---|---|---|---|---|")
    table = []
    for contact in sorted({k[8] for k in rows if k[8].startswith("penalty") and k[1] == 2.5e-8 and k[5] == 20}):
        suffix = "" if contact == "penalty" else ", filter L/V* " + contact.split("=", 1)[1]
        gradings = [("none", 0.0)] + sorted({(k[2], k[3]) for k in rows if k[2] != "none" and k[1] == 2.5e-8})
        table += [("all directions 50x50x5/100x100x10/200x200x20" + ("" if prop == "none" else ", " + plate_name(prop, delta))
                   + suffix, [("state", 2.5e-8, prop, delta, n, nz, "q1", 0.6, contact)
                              for n, nz in ((50, 5), (100, 10), (200, 20))])
                  for prop, delta in gradings]
    variants = sorted({(k[1], k[8], k[4]) for k in rows if k[2] == "none" and k[8].startswith("penalty")
                       and (k[5] != 5 or k[7] != 0.6)})  # meshes with a thickness or time-step study
    contacts = []
    for dc, contact, n in variants:
        at = ("state", dc, "none", 0.0, n, 5, "q1", 0.6, contact)
        tag = "D_c %g%s%s" % (dc, "" if contact == "penalty" else ", filter L/V* " + contact.split("=", 1)[1],
                              "" if n == 100 else ", %d x %d" % (n, n))
        table += [("%s: nz 5/10/20" % tag, [at[:5] + (nz,) + at[6:] for nz in (5, 10, 20)]),
                  ("%s: dt_safety 0.6/0.3/0.15" % tag, [at[:7] + (dts,) + at[8:] for dts in (0.6, 0.3, 0.15)]),
                  ("%s: dt_safety 0.3/0.15/0.075" % tag, [at[:7] + (dts,) + at[8:] for dts in (0.3, 0.15, 0.075)])]
        kinematic = at[:8] + (contact.replace("penalty", "kinematic", 1),)
        if at in rows and kinematic in rows:
            contacts.append("| %s | %.6f | %.6f | %+.3f %% |" % (tag, rows[at], rows[kinematic], 100 * (rows[at] / rows[kinematic] - 1)))
    for index, (label, keys) in enumerate(table):
        if all(k in rows for k in keys):
            mu = [rows[k] for k in keys]
            d, p, ext, bounds = analyse(mu)
            finer = table[index + 1][1] if "dt_safety 0.6/" in label else []
            if finer and all(k in rows for k in finer):  # 0.6 through 0.075 (as the code's time-step term)
                through = through_finer([(0.6, mu), (0.3, [rows[k] for k in finer])], 0)
                if through:
                    bounds = "not converged; 0.6 bounded through 0.075: %.4f %%" % (100 * through[1])
            print("| %s | %s | %s | %s | %s | %s |" % (label, ", ".join("%.6f" % m for m in mu), d, p, ext, bounds))
    paired_differences(rows)
    each_direction_apart(rows)
    if contacts:
        print()
        print("The penalty against the kinematic contact (the exact reference), non-graded 100 x 100 x 5:")
        print()
        print("| D_c, filter | penalty | kinematic | difference |")
        print("|---|---|---|---|")
        print("\n".join(contacts))
    edge_graded(path)

def mesh_bound(found, n):
    """The bound of in-plane mesh n from one family of in-plane ladders found = [(coarsest, values)], as the
    code's mesh term: the finest ladder holding n, every finer one converging, else through the finest
    value of the finer ones; None where that proves no bound."""
    starts = [m for m, _ in found]
    for member in range(3):
        c = n >> member
        if c << member != n or c not in starts:
            continue
        i = starts.index(c)
        if finer_not_converged(found, i):
            return None
        bound = judge(found[i][1], member)["bound"]
        if bound is None and member == 0:
            through = through_finer(found, i)
            bound = through[1] if through else None
        return bound
    return None


def thickness_bound(rows, key, n, nz):
    """The bound of nz (5, 10 or 20) from the thickness ladder 5/10/20 on in-plane mesh n and every
    finer one the rows hold (each must converge; the largest bound), as the code's thickness term."""
    bounds = []
    while all(key(n, z) in rows for z in (5, 10, 20)):
        bound = judge([rows[key(n, z)] for z in (5, 10, 20)], (5, 10, 20).index(nz))["bound"]
        if bound is None:
            return None
        bounds.append(bound)
        n *= 2
    return max(bounds) if bounds else None


def each_direction_apart(rows):
    """The plates refined each direction apart on 50/100/200 x 5/10/20 (where a ladder refined in every
    direction is run with them): each direction's ladders by the rule, and the code's bound of the
    meshes in every direction where that ladder does not converge (the in-plane ladder at the mesh's nz
    plus the thickness ladder at its in-plane mesh and the finer ones), with the test that the bounded
    ones share a limit."""
    plates = sorted({(k[0], k[1], k[2], k[3], k[8]) for k in rows if k[4] == 50 and k[5] in (10, 20)})
    lines = []
    for law, dc, prop, delta, contact in plates:
        key = lambda n, nz: (law, dc, prop, delta, n, nz, "q1", 0.6, contact)
        tag = plate_name(prop, delta) + ", D_c %g%s" % (
            dc, "" if contact == "penalty" else ", filter L/V* " + contact.split("=", 1)[1])
        runs = [("in-plane 50/100/200 x %d" % nz, [key(n, nz) for n in (50, 100, 200)]) for nz in (5, 10, 20)]
        runs += [("nz 5/10/20 on %d x %d" % (n, n), [key(n, nz) for nz in (5, 10, 20)]) for n in (50, 100, 200)]
        for label, keys in runs:
            if all(k in rows for k in keys):
                mu = [rows[k] for k in keys]
                d, p, ext, bounds = analyse(mu)
                lines.append("| %s | %s | %s | %s | %s | %s |" % (tag, label, ", ".join("%.6f" % m for m in mu), d, p, bounds))
        diagonal = [(n, nz) for n, nz in ((50, 5), (100, 10), (200, 20))]
        if not all(key(n, nz) in rows for n, nz in diagonal) or judge([rows[key(*m)] for m in diagonal], 0)["bound"]:
            continue
        apart = []
        for n, nz in diagonal:
            inplane = mesh_bound(ladders(rows, law, dc, prop, delta, nz=nz, contact=contact), n)
            thick = thickness_bound(rows, key, n, nz)
            total = inplane + thick if inplane is not None and thick is not None else None
            apart.append((rows[key(n, nz)], total))
            lines.append("| %s | %dx%dx%d apart | %.6f | in-plane %s + thickness %s | | %s |" % (
                tag, n, n, nz, rows[key(n, nz)], *("%.2f %%" % (100 * b) if b is not None else "none"
                                                   for b in (inplane, thick, total))))
        bounded = [(v, b) for v, b in apart if b is not None]
        if len(bounded) >= 2:
            lines.append("| %s | test | | | | the bounded meshes %s a limit |" % (
                tag, "share" if shares_a_limit(bounded) else "do not share"))
    if lines:
        print()
        print("Refined each direction apart: the in-plane ladders at 5, 10 and 20 layers and the thickness")
        print("ladders nz 5/10/20 on each in-plane mesh, and where the ladder in every direction does not")
        print("converge, the bound of its meshes apart (in-plane + thickness):")
        print()
        print("| plate | ladder | mu_s | differences | observed order | bounds of its members |")
        print("|---|---|---|---|---|---|")
        print("\n".join(lines))


EDGE = (4.0, 5e-4)  # the meshes graded toward the edges the study refined in every direction
EDGE_MESHES = ((60, 5), (120, 10), (240, 20))


def edge_graded(path):
    """The plates on the meshes graded toward the edges (ratio 4 over L/10 bands, D_c 2.5e-8 m, no
    filter), refined in every direction: each plate's ladder and bounds by the rule, as the code's mesh
    term, and the paired differences of the gradings run with both signs."""
    rows = load(path, edge=EDGE)
    key = lambda prop, delta, n, nz: ("state", 2.5e-8, prop, delta, n, nz, "q1", 0.6, "penalty")
    plates = sorted({(k[2], k[3]) for k in rows if (k[4], k[5]) == EDGE_MESHES[0] and k[8] == "penalty"},
                    key=lambda p: (p[0] != "none", p))
    lines, mu_of = [], {}
    for prop, delta in plates:
        keys = [key(prop, delta, n, nz) for n, nz in EDGE_MESHES]
        if not all(k in rows for k in keys):
            continue
        mu = mu_of[(prop, delta)] = [rows[k] for k in keys]
        d, p, ext, bounds = analyse(mu)
        tag = plate_name(prop, delta)
        lines.append("| %s | %s | %s | %s | %s | %s |" % (tag, ", ".join("%.6f" % m for m in mu), d, p, ext, bounds))
    if not lines:
        return
    print()
    print("The meshes graded toward the edges (ratio %g over bands of %g m), refined in every direction" % EDGE)
    print("%s:" % "/".join("%dx%dx%d" % (n, n, nz) for n, nz in EDGE_MESHES))
    print()
    print("| grading | mu_s | differences | observed order | extrapolated | bounds of its members |")
    print("|---|---|---|---|---|---|")
    print("\n".join(lines))
    pairs = [(prop, delta) for prop, delta in mu_of if delta > 0 and (prop, -delta) in mu_of]
    if pairs:
        print()
        print("| grading | mu_s(+Delta) - mu_s(-Delta) | ladder |")
        print("|---|---|---|")
        for prop, delta in pairs:
            diff = [a - b for a, b in zip(mu_of[(prop, delta)], mu_of[(prop, -delta)])]
            v = judge(diff, 2)
            if v["outcome"] == "oscillating":
                verdict = "oscillating: limit between %+.6f and %+.6f" % (diff[1], diff[2])
            elif v["outcome"] == "monotone":
                verdict = "order %.2f, extrapolated %+.6f" % (v["order"], v["extrapolated"])
            else:
                verdict = v["outcome"]
            print("| %s | %s | %s |" % (plate_name(prop, delta, "%.1f"), ", ".join("%+.6f" % x for x in diff), verdict))


def limit_interval(mu):
    """The interval that holds a converged ladder's limit by the rule: the finest value +- its bound."""
    v = judge(mu, 2)
    half = v["bound"] * abs(v["extrapolated"] if v["extrapolated"] is not None else mu[2])
    return mu[2] - half, mu[2] + half


def first_divergent_above(by_mesh, n):
    """Of one sign's in-plane ladders {coarsest mesh: values}, the first finer than n's that does not
    converge, or None."""
    family = sorted((m, mu) for m, mu in by_mesh.items() if m != "all")
    return finer_not_converged(family, [m for m, _ in family].index(n))


def paired_differences(rows):
    """mu_s(+Delta) - mu_s(-Delta) on the same mesh, judged as a ladder by the same rule (absolute
    values: the difference may cross zero). Its sign is decided when both signs' own ladders converge,
    and every finer one, and either the interval that bounds the difference's limit excludes zero or,
    where the difference's own ladder does not converge, the two signs' limit intervals lie apart."""
    pairs = sorted({(k[0], k[1], k[8], k[2], abs(k[3])) for k in rows if k[2] != "none" and k[3] > 0
                    and k[8].startswith("penalty") and (k[0], k[1], k[2], -k[3]) + k[4:] in rows})
    lines = []
    for law, dc, contact, prop, delta in pairs:
        plus = dict(ladders(rows, law, dc, prop, delta, contact=contact))
        minus = dict(ladders(rows, law, dc, prop, -delta, contact=contact))
        meshes = {n: "%d/%d/%d" % (n, 2 * n, 4 * n) for n in set(plus) & set(minus)}
        every = lambda sign: [(law, dc, prop, sign * delta, n, nz, "q1", 0.6, contact)
                              for n, nz in ((50, 5), (100, 10), (200, 20))]
        if all(k in rows for sign in (1, -1) for k in every(sign)):  # refined in every direction
            plus["all"], minus["all"] = ([rows[k] for k in every(sign)] for sign in (1, -1))
            meshes["all"] = "50x50x5/100x100x10/200x200x20"
        for n in sorted(meshes, key=lambda n: (n == "all", 0 if n == "all" else n)):
            d = [a - b for a, b in zip(plus[n], minus[n])]
            v = judge(d, 2)
            singles = [judge(mu[n], 2)["outcome"] != "not converged" for mu in (plus, minus)]
            # A finer ladder of either sign that does not converge takes the verdict away.
            finer = None if n == "all" else min(
                (m for m in (first_divergent_above(mu, n) for mu in (plus, minus)) if m), default=None)
            if v["outcome"] == "not converged" and all(singles) and not finer:
                # Each sign's own limit is bounded: the sign is decided if the two intervals are apart.
                lo_hi = [limit_interval(mu[n]) for mu in (plus, minus)]
                apart = lo_hi[0][0] > lo_hi[1][1] or lo_hi[1][0] > lo_hi[0][1]
                verdict = "not converged; the limits of +%.1f and -%.1f lie in [%.6f, %.6f] and [%.6f, %.6f]" % (
                    delta, delta, *lo_hi[0], *lo_hi[1])
                sign = ("decided: %s" % ("+Delta above" if lo_hi[0][0] > lo_hi[1][1] else "-Delta above")) if apart \
                    else "not decided"
            elif v["outcome"] == "not converged":
                verdict, sign = "not converged", "not decided"
            elif not all(singles):
                verdict, sign = "converges, but the ladder of %s does not" % " and of ".join(
                    "%+.1f" % x for x, ok in zip((delta, -delta), singles) if not ok), "not decided"
            elif finer:
                verdict, sign = "converges, but the finer ladder %d/%d/%d does not" % (finer, 2 * finer, 4 * finer), \
                    "not decided"
            else:
                if v["outcome"] == "oscillating":
                    low, high = sorted(d[1:])
                    verdict = "oscillating: limit between %+.6f and %+.6f" % (d[1], d[2])
                else:
                    low, high = limit_interval(d)
                    verdict = "order %.2f, extrapolated %+.6f, finest %+.6f +- %.6f" % (
                        v["order"], v["extrapolated"], d[2], (high - low) / 2)
                sign = "decided: %s" % ("+Delta above" if low > 0 else "-Delta above") if low * high > 0 else "not decided"
            tag = "%s, D_c %g%s" % (plate_name(prop, delta, "%.1f"), dc, "" if contact == "penalty" else ", filter L/V* " + contact.split("=", 1)[1])
            lines.append("| %s | %s: %s | %s | %s |" % (tag, meshes[n], ", ".join("%+.6f" % x for x in d), verdict, sign))
    if lines:
        print()
        print("The paired difference mu_s(+Delta) - mu_s(-Delta) on the same mesh (in-plane ladders x 5, and refined")
        print("in every direction where run):")
        print()
        print("| grading, interface | differences on n, 2n, 4n | ladder | sign |")
        print("|---|---|---|---|")
        print("\n".join(lines))


if __name__ == "__main__":
    main()
