#!/usr/bin/python3
"""The calibrated spring-block ensemble (gradfric run on the scene file gradfric-calibrate wrote)
against the FEM reference it was fitted to, from the two files alone:
  - the loading slope (least squares of mu against t where 0.2 mu_s <= mu <= 0.6 mu_s before the
    peak, per realisation, averaged) within 1 % of the FEM's (the same rule on its history);
  - l_z = G v / (p slope_FEM) to 0.5 % (the slider springs are the only compliance while every
    block sticks);
  - l_z and sigma fitted (-calibrate_fit lz_sigma): the FEM's mu_s inside the ensemble's 95 %
    confidence interval of the mean mu_s, and a sigma between 0 and 0.2;
  - l_z alone (-calibrate_fit lz, the header says "sigma the surface's"): sigma_s = sigma_k = the
    FEM's surface, and the ensemble's mean mu_s is the reference's peak plus the residual the header
    reports; on an undispersed surface it is the local mu_s, 1 (every block sticks until the
    uniform load reaches its threshold), to 0.5 %.

    check_calibration.py FEM.h5 ENSEMBLE.h5 SCENE.opts
"""
import sys

import h5py
import numpy as np


def slope(t, mu, peak, peak_time):
    keep = (t <= peak_time) & (mu >= 0.2 * peak) & (mu <= 0.6 * peak)
    return np.polyfit(t[keep], mu[keep], 1)[0]


def main(fem_path, sbm_path, scene_path):
    problems = []
    lines = open(scene_path).read().splitlines()
    options = dict(line.split()[:2] for line in lines if line.startswith("-"))
    layer_only = "sigma the surface's" in lines[0]
    with h5py.File(fem_path, "r") as f:
        n = int(f["history/length"][0, 0])  # the one run of a gradfric-fem results file
        t, mu = f["history/time"][0, 0, :n], f["history/mu"][0, 0, :n]
        peak, peak_time = f["realisations/mu_s"][0, 0], f["realisations/peak_time"][0, 0]
        scene = {k: float(v) for k, v in f["scene"].attrs.items()
                 if k in ("plate_E", "plate_nu", "plate_v", "plate_p", "surface_sigma_s", "surface_sigma_k")}
    reference = slope(t, mu, peak, peak_time)
    with h5py.File(sbm_path, "r") as s:
        slopes = []
        for r in range(s.attrs["realisations"]):
            n = int(s["history/length"][0, r])
            slopes.append(slope(s["history/time"][0, r, :n], s["history/mu"][0, r, :n], s["realisations/mu_s"][0, r],
                                s["realisations/peak_time"][0, r]))
        low, high = s["statistics/mu_s_ci95_low"][0], s["statistics/mu_s_ci95_high"][0]
        mean = s["statistics/mu_s_mean"][0]
    ratio = np.mean(slopes) / reference
    print(f"slope: SBM {np.mean(slopes):.6e}, FEM {reference:.6e} 1/s (ratio {ratio:.5f}); "
          f"mu_s: SBM {mean:.6f} [{low:.6f}, {high:.6f}], FEM {peak:.6f}")
    if abs(ratio - 1) > 0.01:
        problems.append(f"slope ratio {ratio:.5f} (allowed 1 +- 0.01)")
    sigma, sigma_k = float(options["-surface_sigma_s"]), float(options["-surface_sigma_k"])
    if layer_only:
        residual = float(next(l for l in lines if l.startswith("# residuals:")).split("peak")[1].split()[0])
        if abs(mean - (peak + residual)) > 2e-6:
            problems.append(f"SBM mu_s {mean:.6f}, the header's reference + residual {peak + residual:.6f}")
        if (sigma, sigma_k) != (scene["surface_sigma_s"], scene["surface_sigma_k"]):
            problems.append(f"sigma {sigma}, {sigma_k}: the FEM's surface has {scene['surface_sigma_s']}, {scene['surface_sigma_k']}")
        if sigma == 0 and sigma_k == 0 and abs(mean - 1) > 0.005:
            problems.append(f"undispersed SBM mu_s {mean:.6f}, expected the local mu_s 1 to 0.5 %")
    else:
        if not low <= peak <= high:
            problems.append(f"FEM mu_s {peak:.6f} outside the SBM CI [{low:.6f}, {high:.6f}]")
        if not 0 < sigma < 0.2 or sigma_k != sigma:
            problems.append(f"sigma {sigma} (sigma_k {sigma_k})")
    shear = scene["plate_E"] / (2 * (1 + scene["plate_nu"]))
    expected = shear * scene["plate_v"] / (scene["plate_p"] * reference)
    lz = float(options["-sbm_lz"])
    if abs(lz / expected - 1) > 0.005:
        problems.append(f"l_z {lz:.6e} m, G v/(p slope) {expected:.6e} m")
    if problems:
        print("FAILED: " + "; ".join(problems))
        return 1
    print("calibrated scene OK")
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
