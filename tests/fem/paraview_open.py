"""pvbatch paraview_open.py file.xmf ncells: opens the FEM snapshots with ParaView's XDMF reader."""
import sys

from paraview import servermanager as sm
from paraview.simple import UpdatePipeline, XDMFReader

reader = XDMFReader(FileNames=[sys.argv[1]])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
UpdatePipeline(time=times[-1], proxy=reader)
data = sm.Fetch(reader)
point = [data.GetPointData().GetArrayName(i) for i in range(data.GetPointData().GetNumberOfArrays())]
cell = [data.GetCellData().GetArrayName(i) for i in range(data.GetCellData().GetNumberOfArrays())]
assert data.GetNumberOfCells() == int(sys.argv[2]), data.GetNumberOfCells()
assert {"state_displacement", "state_velocity", "bottom_contact"} <= set(point), point
assert "cell_stress" in cell, cell
print("paraview OK:", len(times), "times", data.GetNumberOfCells(), "cells")
