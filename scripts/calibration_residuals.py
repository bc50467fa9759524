#!/usr/bin/env python3
"""What the calibrated spring blocks differ from the FEM by, against the grading (docs/calibration.md).

Takes gradfric ensemble files of linear gradings on the FEM's undispersed surface (one realisation
per point: every realisation is the same) and the FEM's study table (docs/fem_study.tsv, read at
run time), and writes one row per grading point present in both, at the FEM's default mesh
(TSV on stdout):

  property  delta  sbm_mu_s  fem_mu_s  sbm_reduction  fem_reduction  difference

reduction = mu_s / mu_s,0 - 1 against each model's own non-graded plate (per cent); difference =
SBM - FEM of the reduction, in points of per cent. The FEM's bars are those of its ladders
(docs/accuracy_fem.md), not repeated here.
Usage: calibration_residuals.py fem_study.tsv sbm.h5 [sbm.h5 ...] > rows.tsv
"""
import sys

import h5py

MESH = "100x100x10"  # the FEM's default mesh


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def fem_rows(path):
    """{(property, delta): mu_s} of the linear gradings at the default mesh, sliding along x."""
    out = {}
    for line in open(path, encoding="utf-8"):
        if line.startswith("#") or not line.strip():
            continue
        cells = line.rstrip("\n").split("\t")
        if cells[0] != "mu_s" or cells[1] != MESH:
            continue
        scene = {} if cells[5] == "-" else dict(item.split("=", 1) for item in cells[5].split(","))
        if not set(scene) <= {"grading_delta", "grading_profile", "grading_property"}:
            continue  # another law, mesh option, angle or profile
        if scene and scene.get("grading_profile") != "linear":
            continue
        delta = float(scene.get("grading_delta", 0))
        out[(scene.get("grading_property", "E") if delta else "-", delta)] = float(cells[2])
    return out


def main(study, *sbm_paths):
    fem = fem_rows(study)
    print("property\tdelta\tsbm_mu_s\tfem_mu_s\tsbm_reduction\tfem_reduction\tdifference")
    for path in sbm_paths:
        with h5py.File(path, "r") as f:
            mu = f["statistics/mu_s_mean"][...]
            reference = f["sweep/reference_point"][...]
            for p in range(len(mu)):
                delta = float(f["sweep/delta"][p])
                key = (text(f["sweep/property"][p]), delta)
                if delta == 0.0 or key not in fem or reference[p] < 0:
                    continue
                sbm_red = 100 * (mu[p] / mu[reference[p]] - 1)
                fem_red = 100 * (fem[key] / fem[("-", 0.0)] - 1)
                print(f"{key[0]}\t{delta:+.1f}\t{mu[p]:.6f}\t{fem[key]:.6f}\t{sbm_red:+.2f}\t{fem_red:+.2f}\t"
                      f"{sbm_red - fem_red:+.2f}")


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
