# script-version: 2
"""snapshots: off-screen PNG renders of the column every insitu.snapshot_every
analyses: the spheres drawn as spheres of their own diameter, coloured by speed, a
translucent slice of the voidage field through the middle of the column, and the time.
DIR/insitu/snapshots/column_NNNNNN.png.
Loaded only when a display is available (sphdem starts Xvfb when DISPLAY is unset)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # sphdem_insitu
from paraview import catalyst
from paraview.simple import (ColorBy, CreateView, GetColorTransferFunction, GetScalarBar, ResetCamera,
                             SaveScreenshot, Show, Slice, Text, TrivialProducer)

import sphdem_insitu as si

particles = TrivialProducer(registrationName="particles")
voidage = TrivialProducer(registrationName="voidage")
options = catalyst.Options()
options.GlobalTrigger = "TimeStep"


view = CreateView("RenderView")
view.ViewSize = [480, 640]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [1.0, 1.0, 1.0]
view.CameraParallelProjection = 1

cut = Slice(Input=voidage)
cut.SliceType = "Plane"
cut.SliceType.Normal = [0.0, 1.0, 0.0]
cut_display = Show(cut, view)
ColorBy(cut_display, ("POINTS", "voidage"))
eps_lut = GetColorTransferFunction("voidage")
eps_lut.ApplyPreset("Blues", True)
eps_lut.InvertTransferFunction()
eps_lut.RescaleTransferFunction(0.4, 1.0)
cut_display.Opacity = 0.55
cut_display.SetScalarBarVisibility(view, True)
bar = GetScalarBar(eps_lut, view)
bar.Title = "voidage"
bar.ComponentTitle = ""
bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]

# Each sphere a shaded sphere of radius d/2 (point Gaussian with the sphere shader: one
# impostor per sphere, no glyph geometry), coloured by |v|.
spheres = Show(particles, view)
spheres.SetRepresentationType("Point Gaussian")
spheres.ShaderPreset = "Sphere"
spheres.ScaleByArray = 1
spheres.UseScaleFunction = 0
spheres.SetScaleArray = ["POINTS", "diameter"]
spheres.GaussianRadius = 0.5
ColorBy(spheres, ("POINTS", "velocity", "Magnitude"))
speed_lut = GetColorTransferFunction("velocity")
speed_lut.ApplyPreset("Viridis (matplotlib)", True)
spheres.SetScalarBarVisibility(view, True)
speed_bar = GetScalarBar(speed_lut, view)
speed_bar.Title = "sphere speed (m/s)"
speed_bar.ComponentTitle = ""
speed_bar.TitleColor = speed_bar.LabelColor = [0.0, 0.0, 0.0]
speed_bar.WindowLocation = "Any Location"
speed_bar.Position = [0.02, 0.62]

clock = Text(registrationName="clock")
clock_display = Show(clock, view)
clock_display.Color = [0.0, 0.0, 0.0]
clock_display.FontSize = 16
clock_display.WindowLocation = "Upper Left Corner"  # the tests read the middle columns

state = {}


def drop_later_snapshots(out):
    """A resumed run: the images of steps after the checkpoint go (the run makes them again)."""
    if si.RANK != 0 or not os.path.isdir(out):
        return
    for name in os.listdir(out):
        if name.startswith("column_") and name.endswith(".png"):
            try:
                if int(name[7:-4]) > si.RESUME_STEP:
                    os.remove(os.path.join(out, name))
            except ValueError:
                pass


def catalyst_execute(info):
    data = si.local_data(voidage, info.time)
    out = os.path.join(si.OUT, "snapshots")  # si.OUT is known once a frame was read
    if si.resumed() and "resumed" not in state:
        state["resumed"] = True
        drop_later_snapshots(out)
    # every insitu.snapshot_every-th analysis of the run (counted over resumes by the solver)
    if int(si.field(data, "analysis")[0]) % int(si.field(data, "snapshot_every")[0]):
        return
    view.ViewTime = info.time  # the producers' time: VTK warns when the view asks for an older one
    clock.Text = "t = %.3f s" % info.time
    # the speed scale: up to twice the Kynch speed where the scene gives one, else the frame's
    u_ref = float(si.field(data, "reference_velocity")[0])
    if u_ref > 0:
        speed_lut.RescaleTransferFunction(0.0, 2.0 * u_ref)
    else:
        spheres.RescaleTransferFunctionToDataRange(False, True)
    box = si.field(data, "box")
    cut.SliceType.Origin = [0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3]), 0.5 * (box[4] + box[5])]
    if not state.get("camera"):
        H = float(si.field(data, "column_height")[0])
        view.CameraPosition = [0.5 * (box[0] + box[1]), box[2] - 10 * H, 0.5 * H]
        view.CameraFocalPoint = [0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3]), 0.5 * H]
        view.CameraViewUp = [0.0, 0.0, 1.0]
        view.CameraParallelScale = 0.55 * H
        state["camera"] = True
    if si.RANK == 0:
        os.makedirs(out, exist_ok=True)
    SaveScreenshot(os.path.join(out, "column_%06d.png" % info.timestep), view, ImageResolution=[480, 640])
