#!/usr/bin/env python3
"""Checks of gradfric-design's files (tests/design/design_checks.sh).

  check_design.py status <design.h5> <status>             the search ended so
  check_design.py meets <design.h5> <target> <tolerance>   the design's CI holds the target, within the tolerance
  check_design.py known <design.h5> <sweep.h5> <target>    the design recovers the Delta a gradfric sweep gives
  check_design.py unreachable <design.h5> <target> <x>     the closest value is at x and its CI misses the target
  check_design.py variants <design.h5> <k> <m>            variant k is the scene (the verification, bit for bit); m moves mu_s
  check_design.py same <a.h5> <b.h5>                       every dataset and attribute alike (but -output, /provenance)
"""
import sys

import h5py
import numpy as np


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def design_row(f, group="design"):
    return {name: float(f[group][name][0]) for name in f[group]}


def main(argv):
    check = argv[1]
    if check == "status":
        with h5py.File(argv[2], "r") as f:
            status = text(f.attrs["status"])
            assert f.attrs["format"] == b"gradfric-design" or text(f.attrs["format"]) == "gradfric-design"
            assert status == argv[3], f"status {status}, expected {argv[3]}"
    elif check == "meets":
        target, tolerance = float(argv[3]), float(argv[4])
        with h5py.File(argv[2], "r") as f:
            d = design_row(f)
            assert d["ci95_low"] <= target <= d["ci95_high"], d
            assert 0.5 * (d["ci95_high"] - d["ci95_low"]) <= tolerance * (1 + 1e-9), d
            assert "verification" in f, "no verification ensemble"
            v = design_row(f, "verification")
            # an independent ensemble: its mean agrees with the search's within their CIs
            assert abs(v["value"] - d["value"]) <= (v["ci95_high"] - v["ci95_low"]) / 2 + (d["ci95_high"] - d["ci95_low"]) / 2, (v, d)
    elif check == "known":
        target = float(argv[4])
        with h5py.File(argv[3], "r") as s:
            delta = s["sweep/delta"][()]
            mean = s["statistics/mu_s_mean"][()]
            half = 0.5 * (s["statistics/mu_s_ci95_high"][()] - s["statistics/mu_s_ci95_low"][()])
        order = np.argsort(delta)
        delta, mean, half = delta[order], mean[order], half[order]
        i = next(k for k in range(len(delta) - 1) if (mean[k] - target) * (mean[k + 1] - target) <= 0)
        slope = (mean[i + 1] - mean[i]) / (delta[i + 1] - delta[i])
        known = delta[i] + (target - mean[i]) / slope
        known_half = max(half[i], half[i + 1]) / abs(slope)  # the sweep's own uncertainty on Delta
        with h5py.File(argv[2], "r") as f:
            d = design_row(f)
            x = d["x_grading_delta"]
            x_half = 0.5 * (d["x_ci95_high"] - d["x_ci95_low"])
        print(f"sweep: Delta = {known:.5f} +- {known_half:.5f}; design: Delta = {x:.5f} +- {x_half:.5f}")
        assert abs(x - known) <= x_half + known_half, "the design does not recover the sweep's Delta"
        assert x_half < 0.02, "the design's Delta is not resolved"
    elif check == "unreachable":
        target, expected = float(argv[3]), float(argv[4])
        with h5py.File(argv[2], "r") as f:
            d = design_row(f)
            name = [k for k in d if k.startswith("x_")][0]
            assert abs(d[name] - expected) < 1e-12, f"closest at {d[name]}, expected {expected}"
            assert not (d["ci95_low"] <= target <= d["ci95_high"]), d
    elif check in ("same", "reused"):
        # reused: the second file took FEM runs from the first's kind (-design_reuse): the same
        # numbers, but for the record of which runs were taken.
        skipped = {"evaluations/reused", "design/reused"} if check == "reused" else set()
        with h5py.File(argv[2], "r") as a, h5py.File(argv[3], "r") as b:
            if check == "reused":
                taken, ran = int(text(a.attrs["fem_runs_reused"])), int(text(a.attrs["fem_runs"]))
                assert taken >= int(a["evaluations/reused"][()].sum()) > 0, taken  # the references count too
                assert int(text(b.attrs["fem_runs_reused"])) == 0 and not b["evaluations/reused"][()].any()
                assert ran + taken == int(text(b.attrs["fem_runs"])), (ran, taken, text(b.attrs["fem_runs"]))
                print(f"{taken} FEM run(s) taken, {text(a.attrs['fem_runs'])} run against {text(b.attrs['fem_runs'])}")
            names = []
            a.visit(names.append)
            other = []
            b.visit(other.append)
            assert names == other, (names, other)
            scales = {"DIMENSION_LIST", "REFERENCE_LIST"}  # object references: compared as the axes' names
            for n in names:
                if n.startswith("provenance") or n in skipped:  # the ranks, date and command line differ by design
                    continue
                if isinstance(a[n], h5py.Dataset):
                    nan = a[n].dtype.kind == "f"  # a source not measured is NaN in both
                    assert np.array_equal(a[n][()], b[n][()], equal_nan=nan), n
                    assert [d.keys() for d in a[n].dims] == [d.keys() for d in b[n].dims], n
                assert {k: v for k, v in a[n].attrs.items() if k not in scales} == \
                    {k: v for k, v in b[n].attrs.items() if k not in scales}, n
            skip = {"output"} | ({"fem_runs", "fem_runs_reused", "design_reuse"} if check == "reused" else set())
            ka = {k: text(v) for k, v in a.attrs.items() if k not in skip}
            kb = {k: text(v) for k, v in b.attrs.items() if k not in skip}
            assert ka == kb, set(ka.items()) ^ set(kb.items())
    elif check == "table_reused":
        # A design that took study-table rows against its fresh run: each row taken is the fresh
        # design's run at that point to 6 decimals (both are gradfric-fem's runs), the decoy row of
        # another scene is taken nowhere, and the design follows the fresh one to the rows' precision.
        rows = {}
        for line in open(argv[4]):
            if not line.startswith("#"):
                _, mesh, value, _, _, scene = line.rstrip("\n").split("\t")
                rows[(mesh, scene)] = float(value)
        with h5py.File(argv[2], "r") as a, h5py.File(argv[3], "r") as b:
            ea, eb = a["evaluations"], b["evaluations"]
            taken = int(text(a.attrs["fem_runs_reused"]))
            assert taken == 4 and int(text(a.attrs["fem_runs"])) + taken == int(text(b.attrs["fem_runs"])), taken
            assert len(ea["mu_s"]) == len(eb["mu_s"])
            for i in range(len(ea["mu_s"])):
                mesh = "%dx%dx%d" % (ea["fem_nx"][i], ea["fem_ny"][i], ea["fem_nz"][i])
                x = ea["x_grading_delta"][i]
                assert abs(x - eb["x_grading_delta"][i]) < 1e-5 and abs(ea["value"][i] - eb["value"][i]) < 1e-5, i
                assert ea["mu_s"][i] != 0.5 and ea["fem_reference_mu_s"][i] == rows[(mesh, "-")], i
                if ea["reused"][i]:
                    scene = "-" if x == 0 else "grading_delta=%g,grading_profile=linear,grading_property=friction" % x
                    assert ea["mu_s"][i] == rows[(mesh, scene)] == round(eb["mu_s"][i], 6), (i, ea["mu_s"][i])
            assert int(ea["reused"][()].sum()) == 2  # -0.4 and 0 on the coarse mesh
            assert abs(a["design/x_grading_delta"][0] - b["design/x_grading_delta"][0]) < 1e-5
        print(f"{taken} rows taken; the design follows the fresh one to the rows' 6 decimals")
    elif check == "femrun":
        # A FEM design against gradfric-fem's own run at its parameter: the same mu_s bit for bit,
        # within the tolerance of the target; with a coarse search, its fine runs last and few.
        target, most_fine = float(argv[4]), int(argv[5])
        with h5py.File(argv[2], "r") as m, h5py.File(argv[3], "r") as g:
            design, run = m["design/mu_s"][0], g["realisations/mu_s"][0, 0]
            assert m["design/realisations"][0] == 1 and m["design/ci95_low"][0] == m["design/ci95_high"][0]
            phases = text(m["evaluations"].attrs["phases"]).split(",")
            # and the nodes that slid at mu > 1 before the peak (the flutter flag), as gradfric-fem counts them
            above = (m["design/nodes_slid_above_one"][0], m["design/area_slid_above_one"][0])
            above_run = (g["fem/results"].attrs["nodes_slid_above_one"], g["fem/results"].attrs["area_slid_above_one"])
        print(f"FEM design: mu_s {design!r}, gradfric-fem at its parameter {run!r}; phases {phases}; "
              f"nodes slid at mu > 1 {above} and {above_run}")
        assert design == run, "the design's FEM value is not gradfric-fem's"
        assert above == above_run, "the design's flutter count is not gradfric-fem's"
        assert abs(design - target) <= 0.002, "not within the tolerance of the target"
        if most_fine:
            fine = [p for p in phases if p == "fine"]
            assert 1 <= len(fine) <= most_fine and phases[-len(fine):] == fine, phases
    elif check == "uncertainty":
        # Each source's interval of the parameter recomputed from the file's own numbers
        # (docs/design.md, "The whole uncertainty of a design").
        close = lambda a, b: abs(a - b) <= 1e-12 * max(1.0, abs(a), abs(b))
        with h5py.File(argv[2], "r") as f:
            d = design_row(f)
            x = next(v for k, v in d.items() if k.startswith("x_") and k not in ("x_ci95_low", "x_ci95_high"))
            slope, value = d["slope"], d["value"]
            stat = 0.5 * (d["ci95_high"] - d["ci95_low"]) / abs(slope)  # 0 for the FEM's deterministic runs
            assert close(d["statistical_low"], x - stat) and close(d["statistical_high"], x + stat), d
            if "fem_verification" in f or "model_form" in f:
                if "fem_verification" in f:  # the spring blocks' design, checked in the FEM
                    fv = design_row(f, "fem_verification")
                    variation = text(f.attrs["target_type"]) == "variation"
                    expected = fv["mu_s"] / fv["reference_mu_s"] - 1 if variation else fv["mu_s"]
                    assert close(fv["value"], expected), fv
                else:  # the FEM's design, checked by a spring-block ensemble
                    assert text(f.attrs["model"]) == "fem"
                    expected = design_row(f, "model_form")["value"]
                assert close(d["other_model_value"], expected), (d, expected)
                x_fem = x - (d["other_model_value"] - value) / slope
                assert close(d["model_form_low"], min(x, x_fem)) and close(d["model_form_high"], max(x, x_fem)), d
                core = (d["model_form_low"], d["model_form_high"])
            else:
                assert np.isnan(d["other_model_value"]) and np.isnan(d["model_form_low"]), d
                assert "-design_verify_fem" in text(f["design"].attrs["model_form_note"])
                core = (x, x)
            if "variants" in f:  # each variant where it reaches the reference value, with its CI
                v = f["variants"]
                reference = design_row(f, "verification" if "verification" in f else "design")["value"]
                low = high = x
                for k in range(len(v["value"])):
                    reach = x - (v["value"][k] - reference) / slope
                    assert close(v["reaches_target_at"][k], reach), (k, reach)
                    spread = 0.5 * (v["ci95_high"][k] - v["ci95_low"][k]) / abs(slope)
                    low, high = min(low, reach - spread), max(high, reach + spread)
                assert close(d["variants_low"], low) and close(d["variants_high"], high), (d, low, high)
                core = (min(core[0], low), max(core[1], high))
            else:
                assert np.isnan(d["variants_low"]), d
            disc = 0.0
            if np.isnan(d["discretisation_low"]):
                assert text(f["design"].attrs["discretisation_note"]).startswith("not measured"), d
            else:
                disc = 0.5 * (d["discretisation_high"] - d["discretisation_low"])
            assert close(d["combined_low"], core[0] - stat - disc) and close(d["combined_high"], core[1] + stat + disc), d
            print(f"x {x:.6f}: statistical +-{stat:.6f}, model form [{d['model_form_low']:.6f}, "
                  f"{d['model_form_high']:.6f}], combined [{d['combined_low']:.6f}, {d['combined_high']:.6f}]")
    elif check == "variants":
        # An identical variant is the verification itself (same streams), bit for bit; the
        # state law moves mu_s beyond both CIs.
        identical, moved = int(argv[3]), int(argv[4])
        with h5py.File(argv[2], "r") as f:
            verification = design_row(f, "verification")
            v = f["variants"]
            x = next(float(f["design"][k][0]) for k in f["design"] if k.startswith("x_") and k not in ("x_ci95_low", "x_ci95_high"))
            assert v["value"][identical] == verification["value"], (v["value"][identical], verification)
            assert v["ci95_low"][identical] == verification["ci95_low"], "an identical variant's CI differs"
            assert v["reaches_target_at"][identical] == x, (v["reaches_target_at"][identical], x)
            assert v["ci95_low"][moved] > verification["ci95_high"] or v["ci95_high"][moved] < verification["ci95_low"], \
                (v["value"][moved], verification)
            files = text(v.attrs["files"]).split(",")
            assert len(files) == len(v["value"]), files
            print(f"variants: {files}, values {list(v['value'][()])} against the verification's {verification['value']:.6f}")
    else:
        raise SystemExit(f"unknown check {check}")


if __name__ == "__main__":
    main(sys.argv)
