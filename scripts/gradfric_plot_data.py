"""The results files gradfric_plot.py draws, read through gradfric.open (python/gradfric): the
ensemble layout (a spring-block ensemble, a FEM sweep, or a single FEM run: one point, one
realisation), a single FEM run as one curve (FemHistory), and the pairing of FEM points with
spring-block points of the same grading and angle."""
import os
import sys

import numpy as np

# python/ beside scripts/, in the source tree and in the install tree (share/gradfric): first, so
# that the script reads with the package of its own version.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "python"))
import gradfric  # noqa: E402

ENSEMBLE_FORMATS = {"gradfric-sbm-ensemble": "SBM", "gradfric-fem-sweep": "FEM", "gradfric-fem-run": "FEM"}
# A single FEM run (gradfric-fem-run, or the older gradfric-fem-history) drawn as one curve.
FEM_RUN_FORMATS = ("gradfric-fem-run", "gradfric-fem-history")
# An older FEM history file does not list its observables: these of its /results.
FEM_HISTORY_OBSERVABLES = ("mu_s", "mu_k")


def refuse(message):
    """Input the tool cannot use: one line on stderr, exit code 2 (the drivers' rule)."""
    print(f"gradfric_plot: error: {message}", file=sys.stderr)
    sys.exit(2)


class Ensemble:
    """A results file with the ensemble layout (docs/ensemble.md): a spring-block ensemble
    (gradfric) or a FEM sweep (gradfric-fem, one run per point; docs/fem.md)."""

    def __init__(self, path, ds=None):
        self.path = path
        self.ds = ds = gradfric.open(path) if ds is None else ds
        self.format = ds.attrs.get("format", "")
        if self.format not in ENSEMBLE_FORMATS:
            raise ValueError(f"{path} is not a gradfric ensemble or FEM sweep file")
        self.model = ENSEMBLE_FORMATS[self.format]
        self.axes = [a for a in ds.attrs["sweep_axes"].split(",") if a]
        self.delta = ds["delta"].values
        self.theta = ds["theta"].values
        # The FEM's coefficients are not dispersed: its files (format version 4) store no sigma.
        self.sigma = ds["sigma"].values if "sigma" in ds.coords else np.zeros(ds.sizes["point"])
        self.property = list(ds["property"].values)
        self.profile = list(ds["profile"].values)
        self.field_value = ds["field_value"].values if "field_value" in ds.coords else None
        self.points = ds.sizes["point"]
        self.done = ds["done"].values.astype(bool)
        self.scene = {k: ds.attrs[k] for k in ds.attrs["scene_options"]}
        # The observables with statistics, as the file lists them (gradfric.open).
        self.observables = list(ds.attrs["observables"])

    def label(self, p):
        parts = []
        for axis in self.axes or ["delta"]:
            if axis == "delta":
                parts.append(f"Delta={self.delta[p]:g}")
            elif axis == "theta":
                parts.append(f"theta={self.theta[p]:g} deg")
            elif axis == "sigma":
                parts.append(f"sigma={100 * self.sigma[p]:g} %")
            elif axis == "property":
                parts.append(self.property[p])
            elif axis == "profile":
                parts.append(self.profile[p])
            elif axis.startswith("field_") and self.field_value is not None:
                parts.append(f"{axis[6:]}={self.field_value[p]:g}")
        return ", ".join(parts)

    def statistic(self, name):
        """A /statistics column; a relative variation a file does not hold (a single FEM run's: no
        reference point) is NaN, as the older files stored it."""
        if name not in self.ds and (name.endswith("_relative") or name.endswith("_relative_ci95")):
            return np.full(self.ds.sizes["point"], np.nan)
        return self.ds[name].values

    def has(self, name):
        return name in self.ds

    def histories(self, p):
        """Every finished realisation's (time, mu) of point p."""
        if "mu" not in self.ds:
            return []
        out = []
        for r in np.flatnonzero(self.done[p]):
            n = int(self.ds["length"][p, r])
            if n > 0:
                out.append((self.ds["time"][p, r, :n].values, self.ds["mu"][p, r, :n].values))
        return out


def point_run(ensemble, p):
    """(time, mu, observables, results) of the first finished run of point p: its mu(t) and its
    observables with their discretisation bars where stored (<name>_discretisation_error, the
    relative uncertainty; files of any version hold it; a FEM run is one realisation)."""
    runs = ensemble.histories(p)
    time, mu = runs[0] if runs else (np.array([]), np.array([]))
    results = {n: float(ensemble.statistic(f"{n}_mean")[p]) for n in ensemble.observables}
    for n in ensemble.observables:
        if ensemble.has(f"{n}_discretisation_error"):
            results[f"{n}_discretisation_error"] = float(ensemble.statistic(f"{n}_discretisation_error")[p])
    return time, mu, ensemble.observables, results


class FemHistory:
    """A single FEM run (docs/fem.md, "Output"): its mu(t) and its observables. A gradfric-fem-run
    file is read as the ensemble layout (its one point and realisation, as a FEM sweep's point);
    an older gradfric-fem-history file as it was."""

    def __init__(self, path, ds=None):
        self.path = path
        ds = gradfric.open(path) if ds is None else ds
        if ds.attrs.get("format") not in FEM_RUN_FORMATS:
            raise ValueError(f"{path} is not a gradfric-fem run")
        if ds.attrs["format"] == "gradfric-fem-run":
            self.time, self.mu, self.observables, self.results = point_run(Ensemble(path, ds), 0)
            where = "/fem/results@"
        else:
            self.time = ds["time"].values
            self.mu = ds["mu"].values
            self.observables = list(FEM_HISTORY_OBSERVABLES)
            self.results = {}
            where = "/results@"
        # the numbers only: /results also holds text (the error bars' basis, the window's description)
        self.results.update({k: float(v) for k, v in ds.data_vars.items()
                             if v.attrs["hdf5_path"].startswith(where) and v.dtype.kind in "iuf"})
        self.parameters = {k: ds.attrs[k] for k in ds.attrs["scene_options"]}
        self.delta = float(self.parameters.get("grading_delta", self.parameters.get("-grading_delta", 0.0)))
        self.profile = self.parameters.get("grading_profile", self.parameters.get("-grading_profile", "none"))
        if self.profile == "none":
            self.delta = 0.0
        self.thickness = self.parameters.get("plate_H", self.parameters.get("-plate_H", self.parameters.get("fem_H", "")))
        self.theta = float(self.parameters.get("plate_theta", self.parameters.get("-plate_theta", 0.0)))


class SweepPoint:
    """One point of a FEM sweep drawn as a single run (FemHistory's fields): a sweep without its own
    non-graded point has no relative variation, so its points join the single runs and are
    measured against the non-graded single run given beside them."""

    def __init__(self, sweep, p):
        self.path = f"{sweep.path}[{p}]"
        self.time, self.mu, self.observables, self.results = point_run(sweep, p)
        self.parameters = sweep.scene
        self.delta = float(sweep.delta[p]) if sweep.profile[p] != "none" else 0.0
        self.theta = float(sweep.theta[p])
        self.thickness = ""


def sweep_without_reference(sweep):
    """True for a FEM sweep none of whose points has a relative variation (no non-graded point)."""
    return sweep.model == "FEM" and not np.isfinite(sweep.statistic(f"{sweep.observables[0]}_relative")).any()


def load(path):
    """A FemHistory (a single FEM run), an Ensemble (ensemble or FEM sweep); ValueError for any other file."""
    ds = gradfric.open(path)
    return FemHistory(path, ds) if ds.attrs.get("format") in FEM_RUN_FORMATS else Ensemble(path, ds)


def pair_key(ensemble, p, digits=9):
    """What a point's physics depends on across the models: its grading, its angle (every
    non-graded point is the same plate whatever its nominal property or profile) and the value of
    a swept field parameter (-ensemble_field), named by its axis."""
    theta = round(float(ensemble.theta[p]), digits)
    delta = round(float(ensemble.delta[p]), digits)
    field = tuple(a for a in ensemble.axes if a.startswith("field_"))
    if field and ensemble.field_value is not None:
        field += (round(float(ensemble.field_value[p]), digits),)
    if ensemble.profile[p] == "none" or delta == 0.0:
        return ("none", "none", 0.0, theta) + field
    return (ensemble.property[p], ensemble.profile[p], delta, theta) + field


def pair_points(sbm, fem):
    """[(FEM point, SBM point)] for every point of the FEM sweep; refuses (exit 2) a sweep of
    another plate or with a point the spring-block file does not have."""
    # The plate, and the property fields (-field_*: the same surface apart from the swept value).
    names = [k for k in fem.scene if k.startswith("plate_") or k.startswith("field_") or k == "grading_bands"]
    differ = [f"-{k}: FEM {fem.scene[k]}, SBM {sbm.scene.get(k, '(not set)')}" for k in names
              if (k in sbm.scene or k.startswith("field_")) and sbm.scene.get(k) != fem.scene[k]]
    if differ:
        refuse(f"{fem.path} and {sbm.path} do not describe the same plate: " + "; ".join(differ))
    by_key = {}
    for q in range(sbm.points):
        by_key.setdefault(pair_key(sbm, q), q)
    pairs, missing = [], []
    for p in range(fem.points):
        q = by_key.get(pair_key(fem, p))
        if q is None:
            missing.append(f"point {p} ({fem.label(p)}, {fem.property[p]} {fem.profile[p]}, theta={fem.theta[p]:g})")
        else:
            pairs.append((p, q))
    if missing:
        refuse(f"{fem.path} does not match {sbm.path}: no spring-block point with the grading, angle and field value of FEM "
               + ", ".join(missing))
    return pairs


def print_pairs(sbm, fem, pairs):
    names = [n for n in sbm.observables if n in fem.observables]
    values = {(m, n): (m.statistic(f"{n}_mean"), m.statistic(f"{n}_relative") * 100) for m in (sbm, fem) for n in names}
    print(f"gradfric_plot: {len(pairs)} FEM point(s) paired with spring-block points ({', '.join(names)}: "
          "value and relative variation):")
    for p, q in pairs:
        line = f"  FEM {p} <-> SBM {q}  {fem.label(p):<24s}"
        for n in names:
            (fm, fr), (sm, sr) = values[(fem, n)], values[(sbm, n)]
            line += f"  {n}: FEM {fm[p]:.6g} ({fr[p]:+.3f} %)  SBM {sm[q]:.6g} ({sr[q]:+.3f} %)"
        print(line)
