"""The files of gradfric-calibrate (docs/calibration.md): the curves (CSV, -calibrate_curve) and the
calibrated scene (an options file whose comment header states the fit, -output)."""
import os
import re

import numpy as np
import xarray as xr

CURVE_HEADER = "t,mu_reference,mu_sbm_mean"
SCENE_HEADER = "# gradfric-calibrate:"
_NUMBER = r"([-+0-9.eE]+|nan)"
# The header lines calibration_output.cpp writes: (pattern, [(name, units, description), ...]).
_HEADER = [
    (r"# reference: loading slope %s 1/s \(over %s-%s mu_s\), peak mu_s %s" % ((_NUMBER,) * 4),
     [("reference_slope", "1/s", "loading slope of the reference mu(t)"),
      ("slope_window_low", "1", "lower end of the mu window of the slope fit, as a fraction of mu_s"),
      ("slope_window_high", "1", "upper end of the mu window of the slope fit, as a fraction of mu_s"),
      ("reference_peak", "1", "static peak (mu_s) of the reference")]),
    (r"# fitted: +l_z = %s \+- %s m, sigma = %s \+- %s" % ((_NUMBER,) * 4),
     [("lz", "m", "fitted mass-layer thickness l_z (-sbm_lz)"),
      ("lz_ci95_half_width", "m", "95 % half-width of l_z"),
      ("sigma", "1", "fitted relative dispersion of the local coefficients (-surface_sigma_s = -surface_sigma_k)"),
      ("sigma_ci95_half_width", "1", "95 % half-width of sigma")]),
    (r"# residuals: slope %s %%, peak %s \(ensemble 95 %% CI \+- %s\)" % ((_NUMBER,) * 3),
     [("slope_residual_percent", "%", "SBM slope / reference slope - 1, in per cent"),
      ("peak_residual", "1", "SBM peak - reference peak"),
      ("peak_ci95_half_width", "1", "95 % half-width of the ensemble's peak")]),
    # -calibrate_fit lz: l_z alone, sigma the surface's, the peak reported and not fitted
    (r"# fitted: +l_z = %s \+- %s m \(95 %%\); surface sigma_s %s, sigma_k %s" % ((_NUMBER,) * 4),
     [("lz", "m", "fitted mass-layer thickness l_z (-sbm_lz)"),
      ("lz_ci95_half_width", "m", "95 % half-width of l_z"),
      ("sigma", "1", "the surface's relative dispersion of the local mu_s (-surface_sigma_s), not fitted"),
      ("sigma_k", "1", "the surface's relative dispersion of the local mu_k (-surface_sigma_k), not fitted")]),
    (r"# residuals: slope %s %%; peak %s \(not fitted; ensemble 95 %% CI \+- %s\)" % ((_NUMBER,) * 3),
     [("slope_residual_percent", "%", "SBM slope / reference slope - 1, in per cent"),
      ("peak_residual", "1", "SBM peak - reference peak: what the two models differ by on this surface"),
      ("peak_ci95_half_width", "1", "95 % half-width of the ensemble's peak")]),
]


def is_curves(first_line):
    return first_line.strip() == CURVE_HEADER


def is_scene(first_line):
    return first_line.startswith(SCENE_HEADER)


def read_scene(path):
    """The fitted values as 0-d variables; the options as attributes (names without the dash)."""
    with open(path, encoding="utf-8") as text:
        lines = text.read().splitlines()
    data, attrs = {}, {"format": "gradfric-calibration-scene"}
    source = re.match(r"# gradfric-calibrate: .* fitted to (.*) \((.*)\)$", lines[0])
    if source:
        attrs["reference_file"], attrs["reference_kind"] = source.groups()
    attrs["fit"] = "lz" if "sigma the surface's" in lines[0] else "lz_sigma"
    for line in lines:
        for pattern, fields in _HEADER:
            m = re.match(pattern, line)
            if m:
                for (name, units, description), value in zip(fields, m.groups()):
                    data[name] = xr.Variable((), float(value), {"units": units, "description": description})
        m = re.search(r"; (\S+) after (\d+) evaluations", line)
        if line.startswith("# residuals") and m:
            attrs["status"], attrs["evaluations"] = m.group(1), int(m.group(2))
        if line.startswith("-"):
            name, _, value = line.partition(" ")
            attrs[name[1:]] = value.strip()
    attrs["scene_options"] = [line.partition(" ")[0][1:] for line in lines if line.startswith("-")]
    return xr.Dataset(data, attrs=attrs), {}


def read_curves(path):
    """mu_reference and mu_sbm_mean along time; with the scene file of the same name beside it
    (-output and -calibrate_curve of one stem), its fit and options too."""
    table = np.genfromtxt(path, delimiter=",", names=True)
    time = xr.Variable("time", table["t"], {"units": "s", "description": "time since the start of sliding"})
    data = {
        "mu_reference": xr.Variable("time", table["mu_reference"], {"units": "1", "description": "the reference mu(t), interpolated onto the grid"}),
        "mu_sbm_mean": xr.Variable("time", table["mu_sbm_mean"], {"units": "1", "description": "mean mu(t) of the calibrated spring-block ensemble"}),
    }
    ds = xr.Dataset(data, {"time": time})
    scene = os.path.splitext(path)[0] + ".opts"
    if os.path.exists(scene):
        with open(scene, encoding="utf-8") as text:
            if is_scene(text.readline()):
                fit = read_scene(scene)[0]
                ds = ds.merge(fit)
                ds.attrs.update(fit.attrs, scene_file=scene)
    ds.attrs["format"] = "gradfric-calibration-curves"
    return ds, {}
