"""Run with pvpython: `pvpython validation/snapshots_npz.py RUN_DIR`. Reads the run's VTK
snapshots (RUN_DIR/vtk/particles.pvd, fluid.pvd: `output.vtk.every`) and writes
RUN_DIR/vtk/snapshots.npz with, per frame k, the arrays the report reads:
  time                      (frames,)
  s{k}_z, s{k}_vz, s{k}_d   the spheres' height, vertical velocity, diameter
  s{k}_fz, s{k}_rho         the spheres' vertical fluid force (2.68) and density
  f{k}_z, f{k}_P, f{k}_eps, f{k}_rho, f{k}_kind   the SPH particles' (kind 0 fluid, 1 wall)
report.py (system python, no VTK) calls it for the sand column's 1 m run."""
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


def frames(pvd):
    """[(time, file)] of a .pvd collection."""
    root = ET.parse(pvd).getroot()
    base = os.path.dirname(pvd)
    return [(float(d.get("timestep")), os.path.join(base, d.get("file"))) for d in root.iter("DataSet")]


def read(path):
    r = vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    pd = r.GetOutput()
    pts = vtk_to_numpy(pd.GetPoints().GetData())
    arrays = {pd.GetPointData().GetArrayName(i): vtk_to_numpy(pd.GetPointData().GetArray(i))
              for i in range(pd.GetPointData().GetNumberOfArrays())}
    return pts, arrays


def main(run_dir):
    vtk_dir = os.path.join(run_dir, "vtk")
    spheres, fluid = frames(os.path.join(vtk_dir, "particles.pvd")), frames(os.path.join(vtk_dir, "fluid.pvd"))
    out = {"time": np.array([t for t, _ in spheres])}
    for k, ((_, sf), (_, ff)) in enumerate(zip(spheres, fluid)):
        pts, a = read(sf)
        out[f"s{k}_z"], out[f"s{k}_vz"], out[f"s{k}_d"] = pts[:, 2], a["velocity"][:, 2], a["diameter"]
        out[f"s{k}_fz"], out[f"s{k}_rho"] = a["fluid_force"][:, 2], a["density"]
        pts, a = read(ff)
        out[f"f{k}_z"], out[f"f{k}_P"], out[f"f{k}_eps"] = pts[:, 2], a["pressure"], a["voidage"]
        out[f"f{k}_rho"], out[f"f{k}_kind"] = a["density"], a["kind"]
    np.savez_compressed(os.path.join(vtk_dir, "snapshots.npz"), **out)


if __name__ == "__main__":
    main(sys.argv[1])
