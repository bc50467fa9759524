#!/usr/bin/env python3
"""Runs gradfric-fem with output on a coarse plate and checks the files: the history with h5py,
the field snapshots in PETSc's VIZ layout, the .xmf beside them, and the refusal to overwrite."""
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import h5py

driver = sys.argv[1]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
work = tempfile.mkdtemp(prefix="gradfric_fem_out_")
out = os.path.join(work, "run.h5")
base = [driver, "-fem_nx", "8", "-fem_ny", "8", "-fem_nz", "2", "-fem_output", out,
        "-fem_snapshot_times", "0,1e-4"]
mpi = ["mpiexec", "--oversubscribe", "-n", "2"]

r = subprocess.run(mpi + base, env=env, capture_output=True, text=True)
assert r.returncode == 0, r.stdout + r.stderr
with h5py.File(out, "r") as f:
    assert f.attrs["complete"] == 1.0
    t, mu = f["history/time"][:], f["history/mu"][:]
    assert len(t) == len(mu) > 100, len(t)
    res = f["results"].attrs
    assert abs(res["mu_s"] - mu.max()) < 1e-12, (res["mu_s"], mu.max())
    assert 0.5 < res["mu_s"] <= 1.02
    assert "fem_nx" in f["parameters"].attrs
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
# ParaView itself, when installed (Debian's paraview + python3-paraview provide pvbatch).
pvbatch = "/usr/bin/pvbatch"
if os.path.exists(pvbatch):
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "paraview_open.py")
    r = subprocess.run([pvbatch, script, xmf, str(8 * 8 * 2)], env=env, capture_output=True, text=True)
    assert r.returncode == 0 and "paraview OK" in r.stdout, r.stdout + r.stderr
    print(r.stdout.strip())
# No overwrite without the flag; nothing half-written left behind.
r = subprocess.run(mpi + base, env=env, capture_output=True, text=True)
assert r.returncode == 2 and "-fem_output_overwrite" in r.stderr, r.stdout + r.stderr
r = subprocess.run(mpi + base + ["-fem_output_overwrite"], env=env, capture_output=True, text=True)
assert r.returncode == 0, r.stderr
assert not [n for n in os.listdir(work) if n.endswith(".tmp")], os.listdir(work)
shutil.rmtree(work)
print("fem output OK")
