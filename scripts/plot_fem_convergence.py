#!/usr/bin/python3
"""The FEM graded convergence study (scripts/fem_graded_study.sh): mu_s against the in-plane
resolution for each grading, with the thickness and time-step refinements, and the table and
error estimates of docs/accuracy_fem.md ("Graded convergence") printed as Markdown.

    /usr/bin/python3 scripts/plot_fem_convergence.py results/fem_graded_study.txt docs/accuracy_fem_graded.png

Estimates, per grading: where mu_s on 50 / 100 / 200 in-plane (nz 5) is monotone with a
contracting difference, the Richardson extrapolation f_inf = f_200 + (f_200 - f_100) / (2^p - 1)
with the observed order p = log2((f_50 - f_100) / (f_100 - f_200)); otherwise (not monotone, or
differences that grow) the in-plane term is the plain 100 -> 200 difference, said as such; the
thickness term 100x100x5 -> 100x100x10 is added. The time-step term is |dt 0.3 / dt 0.6 - 1|.
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import math
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LINE = re.compile(
    r"^mesh (\d+)x\d+x(\d+) dt_safety ([\d.]+) grading (\S+) (\S+)(?: (\w+))?(?: theta (\S+))? \| .*?"
    r"mu_s ([\d.]+) peak .*?trailing ([\d.]+) centre ([\d.]+) leading ([\d.]+).*?, ([\d]+) steps, wall ([\d.]+) s"
)
GRADINGS = [("E", "0.2"), ("E", "-0.2"), ("friction", "0.2"), ("friction", "-0.2")]


def read(path):
    runs = {}
    with open(path) as f:
        for line in f:
            m = LINE.match(line)
            if not m:
                continue
            n, nz, safety, prop, delta, profile, theta = m.group(1, 2, 3, 4, 5, 6, 7)
            key = (int(n), int(nz), float(safety), prop, delta, profile or "linear", float(theta or 0))
            runs[key] = dict(mu=float(m.group(8)), trailing=float(m.group(9)), leading=float(m.group(11)),
                             steps=int(m.group(12)), wall=float(m.group(13)))
    return runs


def mu(runs, n, nz, safety, prop, delta):
    r = runs.get((n, nz, safety, prop, delta, "linear", 0.0))
    return r["mu"] if r else None


def estimate(runs, prop, delta):
    """(mesh bar of the paper mesh 100x100x5 as a fraction, how it was obtained): the in-plane term
    (Richardson where 50/100/200 is monotone and contracting, else the 100 -> 200 difference) plus
    the thickness term (100x100x5 against 100x100x10); added, as the error bar adds its terms."""
    f50, f100, f200 = (mu(runs, n, 5, 0.6, prop, delta) for n in (50, 100, 200))
    f100z10 = mu(runs, 100, 10, 0.6, prop, delta)
    if f100 is None or (f200 is None and f100z10 is None):
        return None, "not run"
    parts, how = 0.0, []
    if f200 is not None:
        if f50 is not None and (f50 - f100) * (f100 - f200) > 0 and abs(f100 - f200) < abs(f50 - f100):
            p = math.log2((f50 - f100) / (f100 - f200))
            f_inf = f200 + (f200 - f100) / (2**p - 1)
            parts += abs(f100 / f_inf - 1)
            how.append(f"in-plane Richardson {100 * abs(f100 / f_inf - 1):.2f} % (p = {p:.2f}, mu_s,inf = {f_inf:.5f})")
        else:
            parts += abs(f100 / f200 - 1)
            shape = "not monotone" if f50 is None or (f50 - f100) * (f100 - f200) <= 0 else "differences grow"
            how.append(f"in-plane {shape}, no extrapolation: 100 vs 200 {100 * (f100 / f200 - 1):+.2f} %")
    else:
        how.append("no 200x200x5")
    if f100z10 is not None:
        parts += abs(f100 / f100z10 - 1)
        how.append(f"thickness 100 vs nz 10 {100 * (f100 / f100z10 - 1):+.2f} %")
    else:
        how.append("no 100x100x10")
    return parts, "; ".join(how)


def finest_order(runs, prop):
    """mu_s(+0.2) and mu_s(-0.2) over the finest meshes (100x100x5, 100x100x10, 200x200x5): does
    every +0.2 lie above every -0.2 (or below), i.e. does the order hold beyond their spread?"""
    meshes = [(100, 5), (100, 10), (200, 5)]
    plus = [f for f in (mu(runs, n, nz, 0.6, prop, "0.2") for n, nz in meshes) if f is not None]
    minus = [f for f in (mu(runs, n, nz, 0.6, prop, "-0.2") for n, nz in meshes) if f is not None]
    if not plus or not minus:
        return None
    gap = min(plus) / max(minus) - 1 if min(plus) > max(minus) else -(min(minus) / max(plus) - 1)
    return f"{prop}: +0.2 in [{min(plus):.5f}, {max(plus):.5f}], -0.2 in [{min(minus):.5f}, {max(minus):.5f}]: " + (
        f"+0.2 above -0.2 on every mesh, gap {100 * gap:.2f} %" if min(plus) > max(minus) else
        f"-0.2 above +0.2 on every mesh, gap {100 * -gap:.2f} %" if min(minus) > max(plus) else
        "the ranges overlap: the order is not resolved")


def table(runs):
    meshes = [(50, 5, 0.6), (100, 5, 0.6), (100, 5, 0.3), (100, 10, 0.6), (200, 5, 0.6)]
    head = "| grading | " + " | ".join(f"{n}x{n}x{nz}" + (f" dt {s}" if s != 0.6 else "") for n, nz, s in meshes)
    print(head + " | bar of 100x100x5 | how |")
    print("|---" * (len(meshes) + 3) + "|")
    for prop, delta in [("none", "0")] + GRADINGS:
        if not any(runs.get((n, nz, s, prop, delta, "linear", 0.0)) for n, nz, s in meshes):
            continue
        cells = []
        for n, nz, s in meshes:
            r = runs.get((n, nz, s, prop, delta, "linear", 0.0))
            cells.append(f"{r['mu']:.5f} ({r['steps']} st, {r['wall']:.0f} s)" if r else "")
        bar, how = estimate(runs, prop, delta) if prop != "none" else (None, "")
        print(f"| {prop} {delta} | " + " | ".join(cells) + f" | {'' if bar is None else f'{100 * bar:.2f} %'} | {how} |")
    print("\n```")
    for n, nz, s in meshes:
        pair = [mu(runs, n, nz, s, "E", d) for d in ("0.2", "-0.2")]
        if None not in pair:
            print(f"E: mu_s(+0.2) / mu_s(-0.2) - 1 on {n}x{n}x{nz} dt {s}: {100 * (pair[0] / pair[1] - 1):+.2f} %")
    for prop in ("E", "friction"):
        line = finest_order(runs, prop)
        if line:
            print("finest meshes, " + line)
    for prop, delta in GRADINGS:
        a, b = mu(runs, 100, 5, 0.6, prop, delta), mu(runs, 100, 5, 0.3, prop, delta)
        if None not in (a, b):
            print(f"dt: {prop} {delta}: dt 0.6 / dt 0.3 - 1 = {100 * (a / b - 1):+.3f} %")
    others = sorted(k for k in runs if k[5] != "linear" or k[6] != 0 or k[4] in ("0.4", "-0.4"))
    for k in others:
        print(f"other: {k}: mu_s {runs[k]['mu']:.5f}, {runs[k]['steps']} steps, {runs[k]['wall']:.0f} s")
    print("```")


def plot(runs, png):
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
    colours = dict(zip(GRADINGS, ("C0", "C1", "C2", "C3")))
    for (prop, delta), colour in colours.items():
        label = f"{prop} Delta = {delta}"
        ns = [n for n in (50, 100, 200) if mu(runs, n, 5, 0.6, prop, delta) is not None]
        axes[0].plot(ns, [mu(runs, n, 5, 0.6, prop, delta) for n in ns], "o-", color=colour, label=f"{label}, nz 5")
        for n, nz, s, marker, what in ((100, 10, 0.6, "s", "nz 10"), (100, 5, 0.3, "^", "dt_safety 0.3")):
            f = mu(runs, n, nz, s, prop, delta)
            if f is not None:
                axes[0].plot([n * (1.04 if nz == 10 else 0.96)], [f], marker, color=colour, mfc="none",
                             label=f"{label}, {what}")
        base = mu(runs, 100, 5, 0.6, prop, delta)
        bar, _ = estimate(runs, prop, delta)
        if base is not None and bar is not None:
            axes[1].bar(f"{prop}\n{delta}", 100 * bar, color=colour)
    axes[0].set_xscale("log", base=2)
    axes[0].set_xticks([50, 100, 200], ["50", "100", "200"])
    axes[0].set_xlabel("elements per side in-plane")
    axes[0].set_ylabel("global mu_s")
    axes[0].set_title("graded mu_s: q1, penalty 250 G/H, dt_safety 0.6 (open: refinements of 100)")
    axes[0].legend(fontsize=6, ncol=2)
    axes[0].grid(True, alpha=0.3)
    axes[1].axhline(1.0, color="grey", ls="--", lw=0.8)
    axes[1].set_ylabel("mesh error bar of 100x100x5 [%]")
    axes[1].set_title("paper mesh: mesh term of the error bar")
    axes[1].grid(True, axis="y", alpha=0.3)
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
