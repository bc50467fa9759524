#!/usr/bin/env python3
"""Runs gradfric-fem with output on a coarse plate and checks the files: the history with h5py
(units and descriptions, dimension scales, forces, properties, provenance), the field snapshots in
PETSc's VIZ layout, the .xmf beside them, and the refusal to overwrite.
With --paraview, also opens the .xmf in ParaView (pvbatch, under xvfb-run when present) and
compares what ParaView shows with the file (paraview_open.py); ParaView must then be installed."""
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import h5py
import numpy as np

driver = sys.argv[1]
with_paraview = "--paraview" in sys.argv[2:]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
work = tempfile.mkdtemp(prefix="gradfric_fem_out_")
out = os.path.join(work, "run.h5")
base = [driver, "-fem_nx", "8", "-fem_ny", "8", "-fem_nz", "2", "-output", out,
        "-fem_snapshot_times", "0,1e-4", "-friction_history_interval", "1e-10"]
mpi = ["mpiexec", "--oversubscribe", "-n", "2"]

r = subprocess.run(mpi + base, env=env, capture_output=True, text=True)
assert r.returncode == 0, r.stdout + r.stderr
with h5py.File(out, "r") as f:
    # The campaign layout of one point, one realisation (docs/ensemble.md), with the FEM's extras under /fem.
    assert f.attrs["complete"] == 1 and f.attrs["format"] == "gradfric-fem-run" and f.attrs["format_version"] == 5
    assert f.attrs["points"] == 1 and f.attrs["realisations"] == 1 and f["realisations/done"][0, 0] == 1
    assert f["fem"].attrs["format_version"] == 5 and f["fem"].attrs["fields_xdmf"] == "run_fields.xmf"
    n = int(f["history/length"][0, 0])
    t, mu = f["history/time"][0, 0, :n], f["history/mu"][0, 0, :n]
    assert n > 100 and np.isnan(f["history/mu"][0, 0, n:]).all(), n
    res = dict(f["fem/results"].attrs)
    mu_s, mu_k = f["realisations/mu_s"][0, 0], f["realisations/mu_k"][0, 0]
    assert mu_s == f["statistics/mu_s_mean"][0] and mu_k == f["statistics/mu_k_mean"][0]
    # Sampled at every step here (-friction_history_interval below dt): the peak is a sample.
    assert abs(mu_s - mu.max()) < 1e-12, (mu_s, mu.max())
    assert 0.5 < mu_s <= 1.02
    # The mu_k window as stored: mu_k is the history's mean over it, the spread its quarters' means
    # (max - min)/mean, the steady flag that spread against the tolerance, and the run stopped at its end.
    a, b = res["mu_k_window_start"], res["mu_k_window_end"]
    inside = (t >= a) & (t <= b)
    assert abs(mu[inside].mean() - mu_k) < 1e-12, (mu[inside].mean(), mu_k)
    edges = a + (b - a) * np.arange(5) / 4
    quarters = [mu[(t >= edges[k]) & ((t < edges[k + 1]) if k < 3 else (t <= b))].mean() for k in range(4)]
    spread = (max(quarters) - min(quarters)) / mu_k
    assert abs(spread - res["mu_k_window_spread"]) < 1e-9, (spread, res["mu_k_window_spread"])
    assert res["mu_k_window_steady"] == (1 if spread <= res["mu_k_steady_tolerance"] else 0), res
    assert res["mu_k_steady_tolerance"] > 0 and abs(t[-1] - b) < 2 * res["dt"], (t[-1], b)
    assert f["fem/results/units"].attrs["dt"] == "s"
    scene = f["scene"].attrs
    assert "fem_nx" in scene and f["scene/units"].attrs["fem_nx"] == "1", dict(f["scene/units"].attrs)
    assert f["scene/origin"].attrs["fem_nx"] == "set"
    # The conventions: strings as str, flags as integers, every dataset with units and description.
    assert isinstance(f.attrs["format"], str)
    assert res["kinetic_window_complete"].dtype.kind == "i", res["kinetic_window_complete"].dtype

    def described(name, obj):
        if isinstance(obj, h5py.Dataset):
            assert isinstance(obj.attrs.get("units"), str) and obj.attrs.get("description") is not None, name

    f.visititems(described)
    # Axes as dimension scales.
    assert [d.keys()[0] for d in f["history/mu"].dims] == ["point", "realisation", "sample"]
    assert [d.keys()[0] for d in f["fem/history/normal_force"].dims] == ["point", "realisation", "sample"]
    assert f["fem/properties/E"].dims[0].keys() == ["cell_x"]
    # The contact's own coefficients, per bottom node.
    assert f["fem/properties/mu_s"].dims[0].keys() == ["node_x"]
    # The force components give mu: |(Fx, Fy)| / (p L^2); the normal force at the same samples.
    p = float(scene["plate_p"])
    side = float(scene["plate_L"])
    fx, fy = f["history/force_x"][0, 0, :n], f["history/force_y"][0, 0, :n]
    assert np.allclose(np.hypot(fx, fy) / (p * side**2), mu, rtol=1e-12, atol=1e-15)
    fn = f["fem/history/normal_force"][0, 0, :n]
    assert np.isfinite(fn).all() and abs(fn[-1] - 1) < 0.05, fn[-1]
    assert np.allclose(f["fem/properties/E"][:], float(scene["plate_E"]))
    assert np.allclose(f["properties/E"][0], float(scene["plate_E"]))
    assert f["fem/pressure_response/g"].shape == (9, 9)
    # The bottom nodes' first slips (first_slip is in the default -friction_observables): the
    # earliest is the observer's first slip, the nodes' positions are the axes.
    first = f["fem/first_slip/time"]
    assert first.shape == (9, 9) and [d.keys()[0] for d in first.dims] == ["node_y", "node_x"]
    assert np.nanmin(first[:]) == res["first_slip_time"], (np.nanmin(first[:]), res["first_slip_time"])
    assert np.allclose(first.dims[1][0][:], f["fem/properties/node_x"][:])
    prov = f["run"].attrs
    assert prov["ranks"] == 2 and prov["software_version"] and prov["software_commit"], dict(prov)
    assert "-output" in prov["command_line"] and prov["date"].endswith("Z"), dict(prov)
fields = os.path.join(work, "run_fields.h5")
with h5py.File(fields, "r") as f:
    for name in ("state_displacement", "state_velocity", "bottom_contact"):
        d = f["vertex_fields/" + name]
        assert d.shape[0] == 2 and d.shape[1] == 9 * 9 * 3, (name, d.shape)
    s = f["cell_fields/cell_stress"]
    assert s.shape[0] == 2 and s.shape[1] == 8 * 8 * 2, s.shape
    assert len(f["time"][:]) == 2
    # Cells in VTK hexahedron order (what the .xmf's "Hexahedron" means to ParaView).
    x = f["geometry/vertices"][:]
    for cell in f["viz/topology/cells"][:5]:
        p = x[cell.astype(int)]
        p = (p - p.min(0)) / (p.max(0) - p.min(0))
        assert p.round().astype(int).tolist() == [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                                                   [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], p
    pressure = f["vertex_fields/bottom_contact"][1, :, 0]
    assert pressure.max() > 0.5 * 1e4, pressure.max()  # contact pressure near p on the bottom
xmf = os.path.join(work, "run_fields.xmf")
ET.parse(xmf)  # well-formed XML
# The fields: units, description and component names.
with h5py.File(fields, "r") as f:
    assert f["cell_fields/cell_stress"].attrs["components"] == "xx,xy,xz,yy,yz,zz"
    assert f["vertex_fields/bottom_contact"].attrs["components"] == "pressure,tx,ty,state"
    assert f["vertex_fields/state_displacement"].attrs["units"] == "m"
if with_paraview:  # ParaView itself (Debian's paraview + python3-paraview provide pvbatch)
    pvbatch = shutil.which("pvbatch")
    assert pvbatch, "pvbatch not found: install paraview, python3-paraview and xvfb (scripts/setup.sh --tests)"
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "paraview_open.py")
    command = [pvbatch, script, xmf, fields, str(8 * 8 * 2)]
    if shutil.which("xvfb-run"):
        command = ["xvfb-run", "-a"] + command
    r = subprocess.run(command, env=env, capture_output=True, text=True)
    assert r.returncode == 0 and "paraview OK" in r.stdout, r.stdout + r.stderr
    print(r.stdout.strip().splitlines()[-1])
# No overwrite without the flag; nothing half-written left behind.
r = subprocess.run(mpi + base, env=env, capture_output=True, text=True)
assert r.returncode == 2 and "-output_overwrite" in r.stderr, r.stdout + r.stderr
r = subprocess.run(mpi + base + ["-output_overwrite", "-friction_observables", "mu_s,mu_k"], env=env,
                   capture_output=True, text=True)
assert r.returncode == 0, r.stderr
with h5py.File(out, "r") as f:  # an observable not asked for is not recorded
    assert "first_slip" not in f["fem"] and "pressure_response" in f["fem"], list(f["fem"])
assert not [n for n in os.listdir(work) if n.endswith(".tmp")], os.listdir(work)
shutil.rmtree(work)
print("fem output OK")
