"""Renders a FEM snapshot with ParaView: sigma_xz of the cells (the plate seen from below: the bottom
layer of cells) beside the contact pressure on the contact face (seen from below).

    xvfb-run -a pvbatch scripts/render_fem_fields.py run_fields.xmf out.png [time]

time: the snapshot time [s] to show (default: the last). Needs Debian's paraview and
python3-paraview (and xvfb for xvfb-run on a machine without a display).
"""
import sys

from paraview.simple import (ColorBy, CreateLayout, CreateView, ExtractSurface, GetColorTransferFunction, GetScalarBar,
                             Render, SaveScreenshot, Show, Text, Threshold, XDMFReader)

xmf, png = sys.argv[1], sys.argv[2]
reader = XDMFReader(FileNames=[xmf])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
time = min(times, key=lambda t: abs(t - float(sys.argv[3]))) if len(sys.argv) > 3 else times[-1]


def view_of(source, array, where, component, title, from_below):
    view = CreateView("RenderView")
    view.ViewSize = [700, 640]
    view.ViewTime = time
    view.OrientationAxesVisibility = 1
    view.OrientationAxesLabelColor = [0, 0, 0]
    view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    display = Show(source, view)
    ColorBy(display, (where, array))
    lut = GetColorTransferFunction(array)
    if component is not None:  # cell_stress is a 9-component tensor xx xy xz yx yy yz zx zy zz in ParaView
        lut.VectorMode = "Component"
        lut.VectorComponent = component
    lut.ApplyPreset("Cool to Warm", True)
    display.RescaleTransferFunctionToDataRange(False, True)
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.RangeLabelFormat = "%-#6.3g"
    view.CameraPosition = [0.0025, 0.0025, -0.02 if from_below else 0.02]
    view.CameraFocalPoint = [0.0025, 0.0025, 0.0]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 0.0031
    label = Text(Text="%s, t = %.3g s after the start of sliding" % (title, time))
    text = Show(label, view)
    text.Color = [0, 0, 0]
    text.FontSize = 14
    text.WindowLocation = "Upper Center"
    return view


stress = view_of(reader, "cell_stress", "CELLS", 2, "sigma_xz [Pa]", from_below=True)
# The contact face: nodes in contact (pressure > 0) on the bottom.
bottom = Threshold(Input=ExtractSurface(Input=reader), Scalars=["POINTS", "bottom_contact_pressure"])
bottom.LowerThreshold = 1e-12
bottom.UpperThreshold = 1e30
pressure = view_of(bottom, "bottom_contact_pressure", "POINTS", None, "contact pressure [Pa]", from_below=True)
layout = CreateLayout("fields")
layout.SplitHorizontal(0, 0.5)
layout.AssignView(1, stress)
layout.AssignView(2, pressure)
Render(stress)
Render(pressure)
SaveScreenshot(png, layout, ImageResolution=[1400, 640])
print("wrote", png, "at t =", time)
