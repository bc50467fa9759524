#!/usr/bin/env python3
"""The map of the grading's effect against the interface's regime number kappa (docs/accuracy_fem.md,
"The effect against kappa"): the relative reduction v(+-0.2) = mu_s(+-0.2)/mu_s(0) - 1 of the FEM
(friction and E grading, linear, 10 bands, paper plate) and of the spring-block model with the same
state law, for each D_c.

    kappa_map.py <fem folder> <sbm folder> [map.png] [fem_study.tsv]

FEM files: <fem folder>/n<N>_dc<D_c>_friction.h5 (gradfric-fem sweep over Delta = -0.2, 0, 0.2) and
n<N>_dc<D_c>_E.h5 (-0.2, 0.2; its reference is the friction file's Delta = 0). SBM files:
<sbm folder>/dc<D_c>_<property>.h5 (gradfric ensembles over -0.2, 0, 0.2, same seed: paired
streams, so the variation's interval is the file's own mu_s_relative_ci95).
kappa = G D_c / (H p (mu_s - mu_k)) for the FEM, and with H -> l_z for the spring blocks.
With the study's table (docs/fem_study.tsv) the FEM with the normal-stress memory is added from
its rows on the finest in-plane mesh run for every plate of a D_c (200 x 200 x 5): the points whose
ladders converge (docs/accuracy_fem.md, "The map's FEM points refined").
"""
import glob
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import gradfric  # noqa: E402

G, H, LZ, P, DMU = 10e6 / (2 * (1 + 1 / 3)), 5e-5, 5.7e-5, 1e4, 0.4


def point(ds, delta):
    at = [i for i, d in enumerate(ds["delta"].values) if abs(d - delta) < 1e-9]
    return at[0] if at else None


def fem_map(folder):
    """{(n, dc): {(property, delta): v}}"""
    out = {}
    for path in glob.glob(os.path.join(folder, "n*_dc*_friction.h5")):
        n, dc = re.match(r"n(\d+)_dc([^_]+)_friction\.h5", os.path.basename(path)).groups()
        with gradfric.open(path) as f:
            mu = f["mu_s_mean"].values
            i0 = point(f, 0.0)
            ref = mu[i0]
            row = {("friction", d): mu[point(f, d)] / ref - 1 for d in (-0.2, 0.2)}
        e_path = path.replace("_friction.h5", "_E.h5")
        if os.path.exists(e_path):
            with gradfric.open(e_path) as f:
                for d in (-0.2, 0.2):
                    row[("E", d)] = f["mu_s_mean"].values[point(f, d)] / ref - 1
        row["mu_s0"] = ref
        out[(int(n), float(dc))] = row
    return out


# The plates with the normal-stress memory hold only these settings (docs/fem_study.tsv, column
# scene); the defaults they leave out: D_c 2.5e-8 m, grading property E, no grading.
FILTERED_SCENE = {"friction_memory_length", "friction_memory_speed", "friction_d_c", "grading_delta",
                  "grading_profile", "grading_property"}


def study_rows(path):
    """The rows of the study table (docs/fem_study.tsv): (observable, mesh, value, {setting: value})."""
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            observable, mesh, value, _, _, scene = line.split()
            settings = dict(s.split("=", 1) for s in scene.split(",")) if scene != "-" else {}
            rows.append((observable, mesh, float(value), settings))
    return rows


def filtered_map(study):
    """{dc: {(property, delta): v}} from the mu_s rows with the normal-stress memory (linear
    grading, the default step and contact) on 200 x 200 x 5."""
    mu = {}
    for observable, mesh, value, s in study_rows(study):
        if (observable != "mu_s" or mesh != "200x200x5" or "friction_memory_length" not in s or not set(s) <= FILTERED_SCENE
                or s.get("grading_profile", "linear") != "linear"):
            continue
        delta = float(s.get("grading_delta", 0))
        prop = s.get("grading_property", "E") if delta != 0 else "none"
        mu[(float(s.get("friction_d_c", 2.5e-8)), prop, delta)] = value
    plates = [(p, d) for p in ("friction", "E") for d in (-0.2, 0.2)]
    out = {}
    for (dc, prop, delta), value in mu.items():
        ref = mu.get((dc, "none", 0.0))
        if ref is not None and prop != "none" and all((dc, p, d) in mu for p, d in plates):
            out.setdefault(dc, {})[(prop, delta)] = value / ref - 1
    return out


def sbm_map(folder):
    """{dc: {(property, delta): (v, ci95)}, 'mu_s0'}"""
    out = {}
    for path in glob.glob(os.path.join(folder, "dc*_*.h5")):
        dc, prop = re.match(r"dc([^_]+)_(\w+)\.h5", os.path.basename(path)).groups()
        with gradfric.open(path) as f:
            row = out.setdefault(float(dc), {})
            for d in (-0.2, 0.2):
                i = point(f, d)
                row[(prop, d)] = (float(f["mu_s_relative"].values[i]), float(f["mu_s_relative_ci95"].values[i]))
            row["mu_s0"] = float(f["mu_s_mean"].values[point(f, 0.0)])
    return out


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    fem, sbm = fem_map(sys.argv[1]), sbm_map(sys.argv[2])
    filtered = filtered_map(sys.argv[4]) if len(sys.argv) > 4 else {}
    cols = [("friction", -0.2), ("friction", 0.2), ("E", -0.2), ("E", 0.2)]
    print("| model | mesh / blocks | D_c [m] | kappa | mu_s(0) | v friction -0.2 | v friction +0.2 | v E -0.2 | v E +0.2 |")
    print("|---|---|---|---|---|---|---|---|---|")
    for (n, dc) in sorted(fem, key=lambda k: (k[1], k[0])):
        row = fem[(n, dc)]
        cells = " | ".join("%+.2f %%" % (100 * row[c]) if c in row else "" for c in cols)
        print(f"| FEM | {n}x{n}x5 | {dc:g} | {G * dc / (H * P * DMU):.2f} | {row['mu_s0']:.6f} | {cells} |")
    for dc in sorted(sbm):
        row = sbm[dc]
        cells = " | ".join("%+.2f +- %.2f %%" % (100 * row[c][0], 100 * row[c][1]) if c in row else "" for c in cols)
        print(f"| SBM | 60x60, R 8 | {dc:g} | {G * dc / (LZ * P * DMU):.2f} | {row['mu_s0']:.4f} | {cells} |")
    for dc in sorted(filtered):
        cells = " | ".join("%+.2f %%" % (100 * filtered[dc][c]) for c in cols)
        print(f"| FEM, filter | 200x200x5 | {dc:g} | {G * dc / (H * P * DMU):.2f} | | {cells} |")
    if len(sys.argv) > 3:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
        for ax, prop in zip(axes, ("friction", "E")):
            for n, marker in ((50, "s"), (100, "o")):
                keys = sorted(k for k in fem if k[0] == n)
                for d, colour in ((-0.2, "C0"), (0.2, "C3")):
                    xs = [G * k[1] / (H * P * DMU) for k in keys if (prop, d) in fem[k]]
                    ys = [100 * fem[k][(prop, d)] for k in keys if (prop, d) in fem[k]]
                    if xs:
                        ax.plot(xs, ys, marker=marker, color=colour, ls="-",
                                label=f"FEM {n}x{n}x5, Delta {d:+.1f}")
            for d, colour in ((-0.2, "C0"), (0.2, "C3")):
                keys = sorted(dc for dc in filtered if (prop, d) in filtered[dc])
                if keys:
                    ax.plot([G * dc / (H * P * DMU) for dc in keys], [100 * filtered[dc][(prop, d)] for dc in keys],
                            marker="D", color=colour, ls=":", lw=2, label=f"FEM 200x200x5 with filter, Delta {d:+.1f}")
            keys = sorted(sbm)
            for d, colour in ((-0.2, "C0"), (0.2, "C3")):
                xs = [G * dc / (LZ * P * DMU) for dc in keys if (prop, d) in sbm[dc]]
                ys = [100 * sbm[dc][(prop, d)][0] for dc in keys if (prop, d) in sbm[dc]]
                es = [100 * sbm[dc][(prop, d)][1] for dc in keys if (prop, d) in sbm[dc]]
                ax.errorbar(xs, ys, yerr=es, marker="^", color=colour, ls="--", mfc="none",
                            label=f"SBM 60x60, Delta {d:+.1f}")
            ax.axvline(1.0, color="grey", lw=0.8)
            ax.set_xscale("log")
            ax.set_xlabel("kappa = G D_c / (H p (mu_s - mu_k))  (SBM: H -> l_z)")
            ax.set_title(f"{prop} grading")
            ax.grid(alpha=0.3)
        axes[0].set_ylabel("v = mu_s(Delta) / mu_s(0) - 1 [%]")
        axes[1].legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(sys.argv[3], dpi=110)
        print(f"kappa_map: wrote {sys.argv[3]}")


if __name__ == "__main__":
    main()
