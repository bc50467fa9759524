"""pvbatch paraview_open.py run_fields.xmf run_fields.h5 ncells

Opens the FEM snapshots with ParaView's XDMF reader and checks that ParaView shows the numbers in
the file: at every snapshot time, every point and cell array ParaView builds equals what h5py
reads from the HDF5 file (so a field declared with the wrong shape, which ParaView would spread
over other cells, fails), and ProbeLocation at a few cell centres and nodes returns the stored
values of the cell or node there. Exit 0 and "paraview OK" on success.
"""
import sys

import h5py
import numpy as np
from paraview import servermanager as sm
from paraview.simple import ProbeLocation, UpdatePipeline, XDMFReader
from vtk.util.numpy_support import vtk_to_numpy

xmf, fields, ncells = sys.argv[1], sys.argv[2], int(sys.argv[3])
h5 = h5py.File(fields, "r")
stored_times = h5["time"][:].ravel()

# What each ParaView array must hold, from the file: (ParaView name, point/cell, function of step).
stress_as_tensor9 = [0, 1, 2, 1, 3, 4, 2, 4, 5]  # Tensor6 xx xy xz yy yz zz -> xx xy xz yx yy yz zx zy zz
expected = {
    "state_displacement": ("point", lambda s: h5["vertex_fields/state_displacement"][s]),
    "state_velocity": ("point", lambda s: h5["vertex_fields/state_velocity"][s]),
    "cell_stress": ("cell", lambda s: h5["cell_fields/cell_stress"][s][:, stress_as_tensor9]),
}
for c, name in enumerate(h5["vertex_fields/bottom_contact"].attrs["components"].split(",")):
    expected["bottom_contact_" + name] = ("point", lambda s, c=c: h5["vertex_fields/bottom_contact"][s][:, c])

reader = XDMFReader(FileNames=[xmf])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
assert np.allclose(times, stored_times, rtol=1e-12, atol=0), (times, stored_times)
compared = 0
for step, t in enumerate(times):
    UpdatePipeline(time=t, proxy=reader)
    data = sm.Fetch(reader)
    assert data.GetNumberOfCells() == ncells, data.GetNumberOfCells()
    points = vtk_to_numpy(data.GetPoints().GetData())
    assert np.array_equal(points, h5["geometry/vertices"][:]), "node coordinates differ"
    for name, (where, values) in expected.items():
        arrays = data.GetPointData() if where == "point" else data.GetCellData()
        array = arrays.GetArray(name)
        assert array is not None, (name, [arrays.GetArrayName(i) for i in range(arrays.GetNumberOfArrays())])
        shown = vtk_to_numpy(array)
        want = values(step)
        assert shown.shape == want.shape, (name, shown.shape, want.shape)
        assert np.array_equal(shown, want), (name, step, np.argwhere(shown != want)[:5])
        compared += want.size

# Probes at the last time: a few cell centres (cell data of the cell there) and nodes (point data).
UpdatePipeline(time=times[-1], proxy=reader)
last = len(times) - 1
cells = h5["viz/topology/cells"][:].astype(int)
x = h5["geometry/vertices"][:]
stress = h5["cell_fields/cell_stress"][last]
contact = h5["vertex_fields/bottom_contact"][last]
bottom = np.flatnonzero(contact[:, 0] > 0)
probes = 0
for cell in (0, ncells // 3, 2 * ncells // 3, ncells - 1):
    probe = ProbeLocation(Input=reader, ProbeType="Fixed Radius Point Source")
    probe.ProbeType.Center = list(x[cells[cell]].mean(axis=0))
    probe.UpdatePipeline(times[-1])
    value = vtk_to_numpy(sm.Fetch(probe).GetPointData().GetArray("cell_stress"))[0]
    assert np.array_equal(value, stress[cell][stress_as_tensor9]), (cell, value, stress[cell])
    sxz = value[2]
    probes += 1
for node in bottom[[0, len(bottom) // 2, -1]]:
    probe = ProbeLocation(Input=reader, ProbeType="Fixed Radius Point Source")
    probe.ProbeType.Center = list(x[node])
    probe.UpdatePipeline(times[-1])
    fetched = sm.Fetch(probe).GetPointData()
    pressure = vtk_to_numpy(fetched.GetArray("bottom_contact_pressure"))[0]
    # Point data is interpolated at the probe: within 1e-6 of the node value (neighbours differ by ~1e-4).
    assert np.isclose(pressure, contact[node, 0], rtol=1e-6, atol=0), (node, pressure, contact[node, 0])
    probes += 1
print("paraview OK: %d times, %d cells; %d values equal to the file, %d probes (cells: sigma_xz %.6g Pa; "
      "nodes: contact pressure %.6g Pa)" % (len(times), ncells, compared, probes, sxz, pressure))
