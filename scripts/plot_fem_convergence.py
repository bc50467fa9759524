#!/usr/bin/python3
"""The FEM graded convergence study (scripts/fem_graded_study.sh): mu_s against the in-plane
resolution for each grading, with the thickness and time-step refinements, and the table and
error estimates of docs/studies/fem-graded-convergence-old-law.md ("Graded convergence") printed as Markdown.

    /usr/bin/python3 scripts/plot_fem_convergence.py results/fem_graded_study.txt docs/accuracy_fem_graded.png

Estimates, per grading: where mu_s on 50 / 100 / 200 in-plane (nz 5) is monotone with a
contracting difference, the Richardson extrapolation f_inf = f_200 + (f_200 - f_100) / (2^p - 1)
with the observed order p = log2((f_50 - f_100) / (f_100 - f_200)) when p >= 0.5; otherwise (not
monotone, differences that grow or barely shrink) the in-plane term is the plain 100 -> 200
difference, said as such (a lower bound: the limit is not located); the thickness term
100x100x5 -> 100x100x10 is added where that run was made. The time-step term is
|dt 0.3 / dt 0.6 - 1| (the first runs, without memory). Every row of the main table uses the
current default friction memory (1e-8 m); the first +-0.2 runs without it follow in a table of
their own.
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import math
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LINE = re.compile(
    r"^mesh (\d+)x\d+x(\d+) dt_safety ([\d.]+) grading (\S+) (\S+)(?: (\w+))?(?: theta (\S+))?(?: slip (\S+))? \| .*?"
    r"mu_s ([\d.]+) peak .*?trailing ([\d.]+) centre ([\d.]+) leading ([\d.]+).*?, ([\d]+) steps, wall ([\d.]+) s"
)
# A grading: (property, Delta, profile, sliding angle in degrees, friction memory -fem_slip_length).
# Every row of the table runs at the current default friction memory (1e-8 m): the linear +-0.2
# gradings (stage pm02mem) and the remaining paper-mesh points of docs/reproduction.md. The first
# +-0.2 runs, made without the memory (slip "0"), are kept as a record of their own (FIRST_RUNS):
# they hold the study's time-step refinement.
MEMORY = "1e-8"
GRADINGS = [("E", "0.2", "linear", 0.0, MEMORY), ("E", "-0.2", "linear", 0.0, MEMORY),
            ("friction", "0.2", "linear", 0.0, MEMORY), ("friction", "-0.2", "linear", 0.0, MEMORY)]
FURTHER = [("E", "0.4", "linear", 0.0, MEMORY), ("E", "-0.4", "linear", 0.0, MEMORY),
           ("friction", "0.4", "linear", 0.0, MEMORY), ("friction", "-0.4", "linear", 0.0, MEMORY),
           ("E", "0.2", "triangular", 0.0, MEMORY), ("E", "-0.2", "triangular", 0.0, MEMORY),
           ("friction", "0.2", "linear", 90.0, MEMORY)]
FIRST_RUNS = [g[:4] + ("0",) for g in GRADINGS]
# Below this observed order the 50/100/200 sequence is not in the asymptotic range (the differences
# barely shrink) and an extrapolation would put the limit anywhere: the plain 100 -> 200 difference
# is given instead, a lower bound on the error.
MIN_ORDER = 0.5
NONGRADED_MU_S, NONGRADED_BAR = 0.883912, 0.065  # the non-graded paper mesh without friction memory, its printed bar
OTHER_TERMS = 0.004 + 0.004  # the printed bar's dt (dt_safety 0.6) and contact (250 G/H) terms


def name(grading):
    prop, delta, profile, theta, slip = grading
    return (f"{prop} {delta}" + ("" if profile == "linear" else f" {profile}") + (f" {theta:g} deg" if theta else "") +
            ("" if slip == "0" else f" (memory {slip})"))


def read(path):
    runs = {}
    with open(path) as f:
        for line in f:
            m = LINE.match(line)
            if not m:
                continue
            n, nz, safety, prop, delta, profile, theta, slip = m.group(1, 2, 3, 4, 5, 6, 7, 8)
            key = (int(n), int(nz), float(safety), prop, delta, profile or "linear", float(theta or 0), slip or "0")
            runs[key] = dict(mu=float(m.group(9)), trailing=float(m.group(10)), leading=float(m.group(12)),
                             steps=int(m.group(13)), wall=float(m.group(14)))
    return runs


def mu(runs, n, nz, safety, grading):
    r = runs.get((n, nz, safety) + tuple(grading))
    return r["mu"] if r else None


def estimate(runs, grading):
    """(mesh bar of the paper mesh 100x100x5 as a fraction, how it was obtained): the in-plane term
    (Richardson where 50/100/200 is monotone and contracting with p >= 0.5, else the 100 -> 200 difference) plus
    the thickness term (100x100x5 against 100x100x10); added, as the error bar adds its terms."""
    f50, f100, f200 = (mu(runs, n, 5, 0.6, grading) for n in (50, 100, 200))
    f100z10 = mu(runs, 100, 10, 0.6, grading)
    if f100 is None or (f200 is None and f100z10 is None):
        return None, "not run"
    parts, how = 0.0, []
    if f200 is not None:
        p = None
        if f50 is not None and (f50 - f100) * (f100 - f200) > 0 and abs(f100 - f200) < abs(f50 - f100):
            p = math.log2((f50 - f100) / (f100 - f200))
        if p is not None and p >= MIN_ORDER:
            f_inf = f200 + (f200 - f100) / (2**p - 1)
            parts += abs(f100 / f_inf - 1)
            how.append(f"in-plane Richardson {100 * abs(f100 / f_inf - 1):.2f} % (p = {p:.2f}, mu_s,inf = {f_inf:.5f})")
        else:
            parts += abs(f100 / f200 - 1)
            shape = ("not monotone" if f50 is None or (f50 - f100) * (f100 - f200) <= 0 else
                     "differences grow" if p is None else f"barely contracting (p = {p:.2f} < {MIN_ORDER})")
            how.append(f"in-plane {shape}, no extrapolation: 100 vs 200 {100 * (f100 / f200 - 1):+.2f} %")
    else:
        how.append("no 200x200x5")
    if f100z10 is not None:
        parts += abs(f100 / f100z10 - 1)
        how.append(f"thickness 100 vs nz 10 {100 * (f100 / f100z10 - 1):+.2f} %")
    else:
        how.append("no 100x100x10")
    return parts, "; ".join(how)


def finest_order(runs, prop, size="0.2", profile="linear", slip="0"):
    """mu_s(+Delta) and mu_s(-Delta) over the finest meshes (100x100x5, 100x100x10, 200x200x5): does
    every +Delta lie above every -Delta (or below), i.e. does the order hold beyond their spread?"""
    meshes = [(100, 5), (100, 10), (200, 5)]
    plus = [f for f in (mu(runs, n, nz, 0.6, (prop, size, profile, 0.0, slip)) for n, nz in meshes) if f is not None]
    minus = [f for f in (mu(runs, n, nz, 0.6, (prop, "-" + size, profile, 0.0, slip)) for n, nz in meshes) if f is not None]
    if not plus or not minus:
        return None
    p, m = f"+{size}", f"-{size}"
    gap = min(plus) / max(minus) - 1 if min(plus) > max(minus) else -(min(minus) / max(plus) - 1)
    return (f"{prop}{'' if profile == 'linear' else ' ' + profile}{'' if slip == '0' else ' memory ' + slip} "
            f"({len(plus)}+{len(minus)} meshes): "
            f"{p} in [{min(plus):.5f}, {max(plus):.5f}], {m} in [{min(minus):.5f}, {max(minus):.5f}]: " + (
                f"{p} above {m} on every mesh, gap {100 * gap:.2f} %" if min(plus) > max(minus) else
                f"{m} above {p} on every mesh, gap {100 * -gap:.2f} %" if min(minus) > max(plus) else
                "the ranges overlap: the order is not resolved"))


def grid(runs, gradings, meshes):
    """One Markdown row per grading: mu_s (steps, wall) on each mesh, the paper mesh's bar and how."""
    head = "| grading | " + " | ".join(f"{n}x{n}x{nz}" + (f" dt {s}" if s != 0.6 else "") for n, nz, s in meshes)
    print(head + " | bar of 100x100x5 | how |")
    print("|---" * (len(meshes) + 3) + "|")
    for grading in gradings:
        if not any(mu(runs, n, nz, s, grading) is not None for n, nz, s in meshes):
            continue
        cells = []
        for n, nz, s in meshes:
            r = runs.get((n, nz, s) + tuple(grading))
            cells.append(f"{r['mu']:.5f} ({r['steps']} st, {r['wall']:.0f} s)" if r else "")
        bar, how = estimate(runs, grading) if grading[0] != "none" else (None, "")
        print(f"| {name(grading)} | " + " | ".join(cells) + f" | {'' if bar is None else f'{100 * bar:.2f} %'} | {how} |")


def table(runs):
    meshes = [(50, 5, 0.6), (100, 5, 0.6), (100, 10, 0.6), (200, 5, 0.6)]
    grid(runs, [("none", "0", "linear", 0.0, MEMORY)] + GRADINGS + FURTHER, meshes)
    print("\n```")
    pairs = (("E", "0.2", "linear", MEMORY), ("friction", "0.2", "linear", MEMORY), ("E", "0.4", "linear", MEMORY),
             ("friction", "0.4", "linear", MEMORY), ("E", "0.2", "triangular", MEMORY))
    for prop, size, profile, slip in pairs:
        for n, nz, s in meshes:
            pair = [mu(runs, n, nz, s, (prop, d, profile, 0.0, slip)) for d in (size, "-" + size)]
            if None not in pair:
                print(f"{prop} {profile}{'' if slip == '0' else ' memory ' + slip}: mu_s(+{size}) / mu_s(-{size}) - 1 "
                      f"on {n}x{n}x{nz} dt {s}: {100 * (pair[0] / pair[1] - 1):+.2f} %")
    for prop, size, profile, slip in pairs:
        line = finest_order(runs, prop, size, profile, slip)
        if line:
            print("finest meshes, " + line)
    for first in FIRST_RUNS:  # what the memory changed, run by run
        for n, nz, s in meshes:
            a, b = mu(runs, n, nz, s, first[:4] + (MEMORY,)), mu(runs, n, nz, s, first)
            if None not in (a, b):
                print(f"memory: {name(first)} on {n}x{n}x{nz}: with / without - 1 = {100 * (a / b - 1):+.2f} %")
    print("```")
    variations(runs)
    print("\nThe first +-0.2 runs, without the friction memory (their thickness and time-step refinements):\n")
    grid(runs, FIRST_RUNS, [(50, 5, 0.6), (100, 5, 0.6), (100, 5, 0.3), (100, 10, 0.6), (200, 5, 0.6)])
    print("\n```")
    for prop in ("E", "friction"):
        line = finest_order(runs, prop)
        if line:
            print("finest meshes, without memory, " + line)
    for grading in FIRST_RUNS:
        a, b = mu(runs, 100, 5, 0.6, grading), mu(runs, 100, 5, 0.3, grading)
        if None not in (a, b):
            print(f"dt: {name(grading)}: dt 0.6 / dt 0.3 - 1 = {100 * (a / b - 1):+.3f} %")
    print("```")


def nongraded(runs, n, nz, slip):
    """(mu_s of the non-graded plate on this mesh at this friction memory, the mesh it comes from):
    the same mesh where it was run, else the paper mesh (without memory: the defaults' run)."""
    for mesh in ((n, nz), (100, 5)):
        f = mu(runs, mesh[0], mesh[1], 0.6, ("none", "0", "linear", 0.0, slip))
        if f is not None:
            return f, mesh
    return (NONGRADED_MU_S, (100, 5)) if slip == "0" else (None, None)


def variations(runs):
    """Each grading's relative variation against the non-graded plate (same friction memory) on the
    paper mesh, with the combined bar (the graded point's mesh bar + dt + contact, plus the
    non-graded bar; ">=" where the mesh term is a lower bound), and on each finer mesh against the
    non-graded plate on that mesh where it was run (else the paper mesh's, marked *)."""
    print("\n| grading | mu_s 100x100x5 | bar (mesh + dt + contact) | variation [%] | 100x100x10 | 200x200x5 | Richardson |")
    print("|---" * 7 + "|")
    for grading in GRADINGS + FURTHER:
        f100 = mu(runs, 100, 5, 0.6, grading)
        base, _ = nongraded(runs, 100, 5, grading[4])
        if f100 is None or base is None:
            continue
        bar, how = estimate(runs, grading)
        bound = ">= " if bar is not None and "no extrapolation" in how else ""
        v = f100 / base - 1
        cell = f"{100 * v:+.1f}" + ("" if bar is None else f" +- {bound}{100 * (1 + v) * (bar + OTHER_TERMS + NONGRADED_BAR):.1f}")
        finer = []
        for n, nz in ((100, 10), (200, 5)):
            f = mu(runs, n, nz, 0.6, grading)
            b, mesh = nongraded(runs, n, nz, grading[4])
            finer.append("" if f is None else f"{f:.5f} ({100 * (f / b - 1):+.1f}{'' if mesh == (n, nz) else '*'})")
        m = re.search(r"mu_s,inf = ([\d.]+)", how)
        b200, _ = nongraded(runs, 200, 5, grading[4])
        rich = f"{float(m.group(1)):.5f} ({100 * (float(m.group(1)) / b200 - 1):+.1f})" if m else ""
        total = "not measured" if bar is None else f"{bound}{100 * (bar + OTHER_TERMS):.1f} %"
        print(f"| {name(grading)} | {f100:.5f} (ref. {base:.5f}) | {total} | {cell} | " + " | ".join(finer) + f" | {rich} |")


def convergence(ax, runs, gradings, title, first_runs=()):
    """mu_s against the in-plane resolution (nz 5), open markers the refinements of the paper mesh;
    dotted, the same grading's first runs without the friction memory."""
    for i, grading in enumerate(gradings):
        colour, label = f"C{i}", name(grading[:4] + ("0",))
        for g, style, what in [(grading, "o-", "")] + [(f, "x:", ", no memory") for f in first_runs
                                                      if f[:4] == tuple(grading[:4])]:
            ns = [n for n in (50, 100, 200) if mu(runs, n, 5, 0.6, g) is not None]
            ax.plot(ns, [mu(runs, n, 5, 0.6, g) for n in ns], style, color=colour, lw=1.5 if g is grading else 0.8,
                    label=f"{label}, nz 5{what}")
            for n, nz, s, marker, refinement in ((100, 10, 0.6, "s", "nz 10"), (100, 5, 0.3, "^", "dt_safety 0.3")):
                f = mu(runs, n, nz, s, g)
                if f is not None:
                    ax.plot([n * (1.04 if nz == 10 else 0.96)], [f], marker, color=colour, mfc="none",
                            mew=1.5 if g is grading else 0.8, label=f"{label}, {refinement}{what}")
    ax.set_xscale("log", base=2)
    ax.set_xticks([50, 100, 200], ["50", "100", "200"])
    ax.set_xlabel("elements per side in-plane")
    ax.set_ylabel("global mu_s")
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=6, ncol=3, loc="upper center", bbox_to_anchor=(0.5, -0.13))
    ax.grid(True, alpha=0.3)


def plot(runs, png):
    fig, axes = plt.subplots(1, 3, figsize=(17, 6.5), gridspec_kw=dict(width_ratios=(1, 1, 0.8)))
    convergence(axes[0], runs, GRADINGS, "linear +-0.2: q1, penalty 250 G/H, dt_safety 0.6, memory 1e-8\n"
                "(open: refinements of 100; dotted: the first runs, without memory)", FIRST_RUNS)
    convergence(axes[1], runs, FURTHER, "|Delta| 0.4, triangular E, friction 0.2 at 90 deg (memory 1e-8)")
    for i, grading in enumerate(GRADINGS + FURTHER):
        bar, _ = estimate(runs, grading)
        if mu(runs, 100, 5, 0.6, grading) is not None and bar is not None:
            colour = f"C{i if i < len(GRADINGS) else i - len(GRADINGS)}"
            axes[2].bar(name(grading[:4] + ("0",)), 100 * bar, color=colour,
                        hatch="" if i < len(GRADINGS) else "//", edgecolor="k", lw=0.3)
    axes[2].axhline(1.0, color="grey", ls="--", lw=0.8)
    axes[2].tick_params(axis="x", labelsize=7, labelrotation=60)
    axes[2].set_ylabel("mesh error bar of 100x100x5 [%]")
    axes[2].set_title("paper mesh: mesh term of the error bar (memory 1e-8)", fontsize=9)
    axes[2].grid(True, axis="y", alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main(path, png=None):
    runs = read(path)
    if not runs:
        sys.exit(f"{path}: no study lines")
    table(runs)
    if png:
        plot(runs, png)
        print(f"figure: {png}")


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    main(*sys.argv[1:])
