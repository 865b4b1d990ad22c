# script-version: 2
"""snapshots: off-screen PNG renders of the column every SPHDEM_SNAPSHOT_EVERY
analyses: spheres as points coloured by species, and a translucent slice of the
voidage field through the middle of the column. DIR/insitu/snapshots/column_NNNNNN.png.
Loaded only when a display is available (sphdem starts Xvfb when DISPLAY is unset)."""
import os
import sys

sys.path.insert(0, os.environ.get("SPHDEM_PIPELINES_DIR", "."))
from paraview import catalyst
from paraview.simple import (ColorBy, CreateView, GetColorTransferFunction, GetScalarBar, ResetCamera,
                             SaveScreenshot, Show, Slice, TrivialProducer)

import sphdem_insitu as si

particles = TrivialProducer(registrationName="particles")
voidage = TrivialProducer(registrationName="voidage")
options = catalyst.Options()
options.GlobalTrigger = "TimeStep"

OUT = os.path.join(si.OUT, "snapshots")
if si.RANK == 0:
    os.makedirs(OUT, exist_ok=True)

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

spheres = Show(particles, view)
spheres.SetRepresentationType("Points")
spheres.RenderPointsAsSpheres = 1
spheres.PointSize = 4.0
ColorBy(spheres, ("POINTS", "species"))
species_lut = GetColorTransferFunction("species")
species_lut.ApplyPreset("Set1", True) if hasattr(species_lut, "ApplyPreset") else None

state = {"count": 0}


def catalyst_execute(info):
    k = state["count"]
    state["count"] += 1
    if k % si.SNAPSHOT_EVERY:
        return
    data = si.local_data(voidage, info.time)
    box = si.field(data, "box")
    cut.SliceType.Origin = [0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3]), 0.5 * (box[4] + box[5])]
    if not state.get("camera"):
        H = float(si.field(data, "column_height")[0])
        view.CameraPosition = [0.5 * (box[0] + box[1]), box[2] - 10 * H, 0.5 * H]
        view.CameraFocalPoint = [0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3]), 0.5 * H]
        view.CameraViewUp = [0.0, 0.0, 1.0]
        view.CameraParallelScale = 0.55 * H
        state["camera"] = True
    SaveScreenshot(os.path.join(OUT, "column_%06d.png" % info.timestep), view, ImageResolution=[480, 640])
