#!/usr/bin/python3
"""Draw what a gradfric results file holds, the way the paper shows it.

    /usr/bin/python3 scripts/gradfric_plot.py RESULTS.h5 [--fem FEM.h5 ...] [--out DIR] [--prefix NAME]

RESULTS.h5 is a spring-block ensemble file (gradfric) or a finite-element history
(gradfric-fem). Figures written to DIR (default: beside the file), as PNG:

  <name>_mu_t.png           mu(t) histories, one curve per sweep point (paper Figures 2 and 6)
  <name>_variation.png      relative variation of each observable with statistics (mu_s, mu_k, ...,
                            as the file lists them) against Delta with 95 % bands, SBM and FEM
                            together (Figures 4, 7, 9, 10, 11); one curve per
                            sliding angle, property or profile when those are swept (Figure 8)
  <name>_first_slip.png     first-slip time on the plate (the detachment front)
  <name>_fields.png         the property fields a scene used (-field_*: E, mu_s, mu_k, p per
                            block) next to the first-slip map, one row per sweep point (up to 4)
  <name>_sigma_x.png        sigma_x/p snapshots (Figures 5 and 12)
  <name>_detachment.gif     animation of the sigma_x/p snapshots (the Supporting Information videos)

Single FEM runs (gradfric-fem-run, the campaign layout of one point; or older gradfric-fem-history
files) given with --fem are added to the mu(t) and variation plots (their Delta is read from
their /scene). A FEM sweep file (gradfric-fem with the -ensemble_ sweep lists, format
gradfric-fem-sweep, the ensemble's layout) may be plotted alone or given with --fem next to a
spring-block ensemble: each FEM point is then paired with the spring-block point of the same
grading (property, profile, Delta) and angle, the pairs are printed, and a sweep with a point
that has no partner, or made for another plate (-plate_*, -grading_bands), is refused (exit 2).
A FEM sweep without a non-graded point (-ensemble_delta -0.3,-0.1,0.1,0.3, say) has no relative
variation of its own: its points are drawn as single runs, against the non-graded single run given
with them; the single runs form one curve per sliding angle.
The files are read with gradfric.open (python/gradfric). Needs Debian's python3-h5py,
python3-xarray, python3-matplotlib (and python3-pil for the animation), installed by scripts/setup.sh.
"""
import argparse
import os
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The readers beside this script (they put python/, the gradfric package of this version, first on
# the path: in the source tree and in the install tree, share/gradfric).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from gradfric_plot_data import (Ensemble, FemHistory, SweepPoint, load, pair_points, print_pairs,  # noqa: E402
                                refuse, sweep_without_reference)


def plot_histories(ensemble, fems, png, sweeps=()):
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    for source in ([ensemble] if ensemble is not None else []) + list(sweeps):
        colours = plt.cm.viridis(np.linspace(0, 0.9, max(source.points, 1)))
        style = "--" if source.model == "FEM" else "-"
        for p in range(source.points):
            runs = source.histories(p)
            for k, (t, mu) in enumerate(runs[:3]):  # a few realisations: the spread is visible
                ax.plot(t * 1e3, mu, style, color=colours[p], lw=1.0 if k == 0 else 0.5, alpha=1.0 if k == 0 else 0.5,
                        label=f"{source.model} {source.label(p)}" if k == 0 else None)
    for fem in fems:
        label = f"FEM Delta={fem.delta:g}" + (f", H={fem.thickness}" if fem.thickness else "")
        ax.plot(fem.time * 1e3, fem.mu, "--", lw=1.2, label=label)
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("mu(t) = F / (p L^2)")
    ax.set_title("Friction force history")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)
    return png


def series_key(ensemble, p):
    """Points that differ only in Delta form one curve."""
    return (ensemble.theta[p], ensemble.sigma[p], ensemble.property[p], ensemble.profile[p])


def plot_variation(ensemble, fems, png, sweeps=()):
    """One panel per observable with statistics, as the first file lists them."""
    first = ensemble if ensemble is not None else (sweeps[0] if sweeps else None)
    names = first.observables if first is not None else fems[0].observables
    fig, axes = plt.subplots(1, len(names), figsize=(6 * len(names), 4.8), squeeze=False)
    for ax, name in zip(axes[0], names):
        for source in ([ensemble] if ensemble is not None else []) + list(sweeps):
            if name not in source.observables:
                continue
            relative = source.statistic(f"{name}_relative") * 100
            error = source.statistic(f"{name}_relative_ci95") * 100  # 95 % Student t half-width
            groups = {}
            for p in range(source.points):
                groups.setdefault(series_key(source, p), []).append(p)
            for key, members in groups.items():
                members = sorted(members, key=lambda p: source.delta[p])
                d = source.delta[members]
                y, e = relative[members], error[members]
                theta, sigma, prop, profile = key
                label = f"{source.model} {prop} {profile}" + (f", theta={theta:g}" if len(groups) > 1 else "")
                line, = ax.plot(d, y, "o-" if source.model == "SBM" else "s--", label=label)
                # FEM sweep: each point's discretisation bar (the relative uncertainty U / |mu| of
                # its study ladder, core/study_table.hpp; NaN where no ladder bounds it: no bar there)
                if source.model == "FEM" and source.has(f"{name}_discretisation_error"):
                    bar = source.statistic(f"{name}_discretisation_error")[members]
                    known = np.isfinite(bar) & np.isfinite(y)
                    if known.any():
                        ax.errorbar(d[known], y[known], yerr=(100 + y[known]) * bar[known], fmt="none", capsize=3,
                                    color=line.get_color())
                # 95 % band of the relative variation (the stored Student t half-width)
                if source.model == "SBM":
                    ax.fill_between(d, y - e, y + e, alpha=0.2)
        reference = [f for f in fems if f.delta == 0.0]
        if reference:
            base = reference[0].results.get(name, np.nan)
            # one curve per sliding angle; the non-graded run (the same plate at any angle) in each
            angles = sorted({f.theta for f in fems if f.delta != 0.0}) or [0.0]
            for theta, colour in zip(angles, ("tab:red", "tab:purple", "tab:brown", "tab:olive")):
                members = [f for f in fems if f.delta == 0.0 or f.theta == theta]
                pts = sorted((f.delta, 100 * (f.results.get(name, np.nan) / base - 1),
                              f.results.get(f"{name}_discretisation_error", np.nan)) for f in members)
                x, y, bar = (np.array(v, dtype=float) for v in zip(*pts))
                ax.plot(x, y, "s--", color=colour, label="FEM" + (f", theta={theta:g}" if len(angles) > 1 else ""))
                # each run's own discretisation bar (relative uncertainty of its mu, as for a FEM
                # sweep; NaN where not measured, e.g. a scene or mesh outside the study: no bar drawn)
                known = np.isfinite(bar) & np.isfinite(y)
                if known.any():
                    ax.errorbar(x[known], y[known], yerr=(100 + y[known]) * bar[known], fmt="none", capsize=3,
                                color=colour)
        ax.axhline(0, color="grey", lw=0.8)
        ax.set_xlabel("Delta")
        ax.set_ylabel(f"({name} - {name},0) / {name},0  [%]")
        ax.set_title(f"Relative variation of the global {name}")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)
    return png


def first_finished(ensemble, first=None):
    """(point, realisation) pairs with a finished realisation; `first` leads if given."""
    order = list(range(ensemble.points))
    if first is not None:
        order = [first] + [p for p in order if p != first]
    for p in order:
        r = np.flatnonzero(ensemble.done[p])
        if r.size:
            yield p, r[0]


def default_point(ensemble):
    """The most strongly graded point: its snapshots show a detachment front."""
    return int(np.argmax(np.abs(ensemble.delta))) if ensemble.points else 0


def plot_first_slip(ensemble, png):
    if not ensemble.has("first_slip_time"):
        return None
    cases = list(first_finished(ensemble))[:6]
    if not cases:
        return None
    length = float(ensemble.scene.get("sbm_L", "0.005"))
    fig, axes = plt.subplots(1, len(cases), figsize=(3.6 * len(cases), 3.4), squeeze=False)
    for ax, (p, r) in zip(axes[0], cases):
        m = ensemble.ds["first_slip_time"][p, r].values * 1e3
        im = ax.imshow(m, origin="lower", extent=[0, length * 1e3, 0, length * 1e3], cmap="magma")
        ax.set_title(ensemble.label(p), fontsize=8)
        ax.set_xlabel("x [mm]")
        fig.colorbar(im, ax=ax, label="first slip [ms]", shrink=0.8)
    axes[0][0].set_ylabel("y [mm]")
    fig.suptitle("Detachment front: time of each block's first slip", fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)
    return png


FIELD_MAPS = [("E_map", "E [MPa]", 1e-6), ("mu_s_map", "mu_s", 1.0), ("mu_k_map", "mu_k", 1.0),
              ("p_map", "p [kPa]", 1e-3)]


def plot_fields(ensemble, png):
    """Every property field that varies over the plate, then the first-slip map of the point."""
    group = {name: ensemble.ds[f"properties_{name}"].values for name, _, _ in FIELD_MAPS
             if ensemble.has(f"properties_{name}")}
    if not group:
        return None
    shown = [(n, label, scale) for n, label, scale in FIELD_MAPS
             if n in group and np.ptp(group[n]) > 1e-12 * np.max(np.abs(group[n]))]
    has_slip = ensemble.has("first_slip_time")
    points = list(range(min(ensemble.points, 4)))
    columns = len(shown) + (1 if has_slip else 0)
    if columns == 0:
        return None
    scene = ensemble.scene
    length = float(scene.get("plate_L", scene.get("sbm_L", "0.005"))) * 1e3
    fig, axes = plt.subplots(len(points), columns, figsize=(3.3 * columns, 3.0 * len(points)), squeeze=False)
    for row, p in zip(axes, points):
        for ax, (name, label, scale) in zip(row, shown):
            im = ax.imshow(group[name][p] * scale, origin="lower", extent=[0, length, 0, length], cmap="viridis")
            fig.colorbar(im, ax=ax, label=label, shrink=0.8)
            ax.set_title(label.split()[0] + (f": {ensemble.label(p)}" if ensemble.axes else ""), fontsize=8)
        if has_slip:
            ax = row[len(shown)]
            done = np.flatnonzero(ensemble.done[p])
            if done.size:
                m = ensemble.ds["first_slip_time"][p, done[0]].values * 1e3
                im = ax.imshow(m, origin="lower", extent=[0, length, 0, length], cmap="magma")
                fig.colorbar(im, ax=ax, label="first slip [ms]", shrink=0.8)
                ax.set_title(f"first slip, realisation {done[0]}", fontsize=8)
        for ax in row:
            ax.set_xlabel("x [mm] (sliding along x)", fontsize=8)
        row[0].set_ylabel("y [mm]")
    fig.suptitle("Property fields and the detachment front", fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=100)
    plt.close(fig)
    return png


def stress_frames(ensemble, point):
    if not ensemble.has("sigma_x_over_p"):
        return None
    cases = list(first_finished(ensemble, point))
    if not cases:
        return None
    p, r = cases[0]
    times = ensemble.ds["snapshot_time"][p, r].values
    keep = np.isfinite(times)
    if not keep.any():
        return None
    return p, times[keep], ensemble.ds["sigma_x_over_p"][p, r].values[keep]


def plot_sigma(ensemble, png, point):
    frames = stress_frames(ensemble, point)
    if frames is None:
        return None
    p, times, maps = frames
    shown = list(range(len(times)))[:6]
    limit = np.nanmax(np.abs(maps)) or 1.0
    length = float(ensemble.scene.get("sbm_L", "0.005"))
    fig, axes = plt.subplots(1, len(shown), figsize=(3.6 * len(shown), 3.4), squeeze=False)
    for ax, k in zip(axes[0], shown):
        im = ax.imshow(maps[k], origin="lower", extent=[0, length * 1e3, 0, length * 1e3], cmap="RdBu_r",
                       vmin=-limit, vmax=limit)
        ax.set_title(f"t = {times[k] * 1e3:.4f} ms", fontsize=8)
        ax.set_xlabel("x [mm]")
    axes[0][0].set_ylabel("y [mm]")
    fig.colorbar(im, ax=axes[0].tolist(), label="sigma_x / p", shrink=0.8)
    fig.suptitle(f"Longitudinal stress, {ensemble.label(p)}", fontsize=10)
    fig.savefig(png, dpi=110)
    plt.close(fig)
    return png


def animate_sigma(ensemble, gif, point):
    frames = stress_frames(ensemble, point)
    if frames is None or len(frames[1]) < 2:
        return None
    try:
        from matplotlib.animation import FuncAnimation, PillowWriter
    except ImportError:
        return None
    p, times, maps = frames
    limit = np.nanmax(np.abs(maps)) or 1.0
    fig, ax = plt.subplots(figsize=(4.8, 4.2))
    im = ax.imshow(maps[0], origin="lower", cmap="RdBu_r", vmin=-limit, vmax=limit)
    fig.colorbar(im, ax=ax, label="sigma_x / p")
    title = ax.set_title("")

    def update(k):
        im.set_data(maps[k])
        title.set_text(f"{ensemble.label(p)}: t = {times[k] * 1e3:.4f} ms")
        return im, title

    FuncAnimation(fig, update, frames=len(times), blit=False).save(gif, writer=PillowWriter(fps=4))
    plt.close(fig)
    return gif


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results", help="an ensemble file (gradfric), a FEM sweep or a single FEM run (gradfric-fem)")
    parser.add_argument("--fem", nargs="*", default=[], help="FEM runs or FEM sweeps to add")
    parser.add_argument("--out", help="folder for the figures (default: beside the results file)")
    parser.add_argument("--prefix", help="file name prefix (default: the results file's name)")
    parser.add_argument("--point", type=int, help="sweep point of the stress snapshots (default: the largest |Delta|)")
    args = parser.parse_args(argv)

    if not os.path.exists(args.results):
        sys.exit(f"gradfric_plot: no such file: {args.results}")
    out = args.out or os.path.dirname(os.path.abspath(args.results))
    os.makedirs(out, exist_ok=True)
    prefix = os.path.join(out, args.prefix or os.path.splitext(os.path.basename(args.results))[0])

    ensemble, fems, sweeps = None, [], []
    try:
        first = load(args.results)
    except (ValueError, KeyError, OSError) as error:
        sys.exit(f"gradfric_plot: {args.results} is neither a gradfric ensemble nor a FEM run ({error})")
    if isinstance(first, Ensemble):
        ensemble = first
    else:
        fems.append(first)
    for path in args.fem:
        try:
            item = load(path)
        except (ValueError, KeyError, OSError) as error:
            sys.exit(f"gradfric_plot: --fem {path} is not a gradfric-fem run or sweep ({error})")
        if isinstance(item, FemHistory):
            fems.append(item)
        elif item.model != "FEM":
            refuse(f"--fem {path} is a spring-block ensemble, not a FEM sweep or history")
        elif sweep_without_reference(item):
            fems.extend(SweepPoint(item, p) for p in range(item.points) if item.done[p].any())
        else:
            sweeps.append(item)
    if sweeps and (ensemble is None or ensemble.model != "SBM"):
        refuse("a FEM sweep given with --fem is paired with a spring-block ensemble: give that one first")
    for sweep in sweeps:
        print_pairs(ensemble, sweep, pair_points(ensemble, sweep))

    written = [plot_histories(ensemble, fems, prefix + "_mu_t.png", sweeps)]
    if ensemble is not None:
        # A relative variation needs a non-graded reference point in the sweep.
        first = ensemble.observables[0]
        if len(set(ensemble.delta)) > 1 and np.isfinite(ensemble.statistic(f"{first}_relative")).sum() > 1:
            written.append(plot_variation(ensemble, fems, prefix + "_variation.png", sweeps))
        written.append(plot_first_slip(ensemble, prefix + "_first_slip.png"))
        written.append(plot_fields(ensemble, prefix + "_fields.png"))
        point = default_point(ensemble) if args.point is None else args.point
        if not 0 <= point < ensemble.points:
            sys.exit(f"gradfric_plot: --point {point} is out of range: 0 <= point < {ensemble.points}")
        written.append(plot_sigma(ensemble, prefix + "_sigma_x.png", point))
        written.append(animate_sigma(ensemble, prefix + "_detachment.gif", point))
    elif len(fems) > 1:
        written.append(plot_variation(None, fems, prefix + "_variation.png"))
    for path in written:
        if path:
            print(f"gradfric_plot: wrote {path}")


if __name__ == "__main__":
    main()
