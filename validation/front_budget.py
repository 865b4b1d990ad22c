"""What carries a suspension's upper interface: its speed against the bulk's, from the run's VTK
snapshots (`output.vtk.every`). Run with pvpython:

    pvpython validation/front_budget.py RUN_DIR [--window 0.2 1.6]

Speeds are displacements between frames, each sphere followed by its id, so an acoustic
oscillation of the column (period 4H/c0, a few ms) sampled by the frames does not bias them
as the snapshots' velocities do. Per pair of frames it prints, in mm/s downward:
  interface   the mean height of the top half layer (the highest spheres of a layer d/2 thick);
  bulk        the spheres between the sediment and 1.5 mm under the interface;
  top 1 mm    the spheres within 1 mm under the interface;
  columns     the spread of the bulk's mean speed over columns 1 mm wide (a convection
              cell across the periodic box shows here), and sd the spheres' own spread;
  skin        the solid fraction of the 1 mm under the interface (against the suspension's);
  eps seen    the voidage the drag reads (the `voidage` array), at the top and in the bulk.
The sediment's top is the highest d-thick layer from the floor up whose solid fraction is
past the midpoint of the suspension's (frame 0) and 0.6. Then the means over --window.
"""
import argparse
import os
import xml.etree.ElementTree as ET

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


def frames(pvd):
    root = ET.parse(pvd).getroot()
    base = os.path.dirname(pvd)
    return [(float(d.get("timestep")), os.path.join(base, d.get("file"))) for d in root.iter("DataSet")]


def spheres(path):
    """Centres, the voidage their drag read (None in runs made before it was written) and
    diameters, ordered by id."""
    r = vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    pd = r.GetOutput()
    arrays = {pd.GetPointData().GetArrayName(i): vtk_to_numpy(pd.GetPointData().GetArray(i))
              for i in range(pd.GetPointData().GetNumberOfArrays())}
    order = np.argsort(arrays["id"])
    pts = vtk_to_numpy(pd.GetPoints().GetData())[order]
    eps = arrays["voidage"][order] if "voidage" in arrays else None
    return pts, eps, arrays["diameter"][order]


def solid_fraction_layers(z, d, area, layer):
    edges = np.arange(0.0, z.max() + layer, layer)
    counts, _ = np.histogram(z, edges)
    return counts * np.pi / 6 * d ** 3 / (area * layer), edges


def sediment_top(z, d, area, phi_mid):
    phi, edges = solid_fraction_layers(z, d, area, d)
    k = 0
    while k < len(phi) and phi[k] > phi_mid:
        k += 1
    return edges[k]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run")
    ap.add_argument("--window", nargs=2, type=float, default=(0.2, 1.6))
    a = ap.parse_args()
    pp = frames(os.path.join(a.run, "vtk", "particles.pvd"))
    p0, _, diam = spheres(pp[0][1])
    d = float(np.median(diam))
    lo, hi = p0[:, 0].min(), p0[:, 0].max()
    width = hi - lo  # the periodic width, to within the largest gap between spheres
    area = width * width
    n_col = max(1, int(round(width / 1e-3)))
    phi0 = float(np.median(solid_fraction_layers(p0[:, 2], d, area, 4 * d)[0][1:-2]))
    n_top = max(8, int(phi0 * area * 0.5 * d / (np.pi / 6 * d ** 3)))
    phi_mid = 0.5 * (phi0 + 0.6)
    print(f"{a.run}: d {1e3 * d:.3f} mm, width {1e3 * width:.2f} mm, suspension solid fraction {phi0:.3f}")
    rows = []
    prev = (pp[0][0], p0, None)
    for t1, path in pp[1:]:
        p1, e1, _ = spheres(path)
        t0, p0, e0 = prev
        if e0 is None:
            e0 = e1
        v = -(p1[:, 2] - p0[:, 2]) / (t1 - t0)
        z = p0[:, 2]
        top0 = np.sort(z)[-n_top:].mean()
        top1 = np.sort(p1[:, 2])[-n_top:].mean()
        z_sed = sediment_top(z, d, area, phi_mid)
        bulk = (z > z_sed + 1.5e-3) & (z < top0 - 1.5e-3)
        top = z > top0 - 1e-3
        col = (np.floor((p0[bulk, 0] - lo) / width * n_col) % n_col * n_col
               + np.floor((p0[bulk, 1] - lo) / width * n_col) % n_col).astype(int)
        counts = np.bincount(col, minlength=n_col * n_col)
        means = np.bincount(col, v[bulk], minlength=n_col * n_col) / np.maximum(counts, 1)
        skin = (top & (z < top0)).sum() * np.pi / 6 * d ** 3 / (area * 1e-3)
        line = (f"{t0:5.2f}-{t1:5.2f} s: interface {-1e3 * (top1 - top0) / (t1 - t0):6.3f}  bulk {1e3 * v[bulk].mean():6.3f}"
                f"  top 1 mm {1e3 * v[top].mean():6.3f}  columns {1e3 * means.std():5.2f} sd {1e3 * v[bulk].std():5.2f}"
                f"  sediment {1e3 * z_sed:5.2f} mm  skin {skin:.3f}")
        if e0 is not None:
            line += f"  eps seen top {e0[top].mean():.3f} bulk {e0[bulk].mean():.3f}"
        print(line)
        rows.append((t0, t1, -(top1 - top0) / (t1 - t0), v[bulk].mean(), v[top].mean()))
        prev = (t1, p1, e1)
    r = np.array(rows)
    m = (r[:, 0] >= a.window[0] - 1e-6) & (r[:, 1] <= a.window[1] + 1e-6)
    if m.any():
        print(f"{a.window[0]}-{a.window[1]} s: interface {1e3 * r[m, 2].mean():.3f}, bulk {1e3 * r[m, 3].mean():.3f}, "
              f"top 1 mm {1e3 * r[m, 4].mean():.3f} mm/s")


if __name__ == "__main__":
    main()
