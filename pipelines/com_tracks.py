# script-version: 2
"""com_tracks: centre of mass (height) of each species and of all spheres over time,
each species' mean vertical velocity and the height of its suspension front.
DIR/insitu/com.csv: time, com_z:S for each species S, com_z:all (m), mass-weighted;
vz_mean:S (m/s), mass-weighted; front_z:S (m), the height where the species' solid
fraction, averaged over layers of 1/FRONT_BINS of the box height (fronts.py), falls to
half its value in the initial suspension (the median of the occupied layers at
the first analysis): the per-species interface of a suspension of two densities or sizes
(Kynch), which the voidage profile cannot tell apart. All sums over MPI ranks."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # sphdem_insitu
import numpy as np
from paraview import catalyst
from paraview.simple import TrivialProducer

import sphdem_insitu as si
from fronts import FINE, front_height, layer_profile, layer_volumes

particles = TrivialProducer(registrationName="particles")
options = catalyst.Options()
options.GlobalTrigger = "TimeStep"

state = {}
FRONT_BINS = 60


def catalyst_execute(info):
    data = si.local_data(particles, info.time)
    names = si.species_names(data)
    ns = len(names)
    box = si.field(data, "box")  # field data travels with every rank's piece, empty or not
    nb = FRONT_BINS * FINE
    dz = (box[5] - box[4]) / nb
    # [sum m z, sum m, sum m vz per species, solid volume per species and fine layer]
    sums = np.zeros(3 * ns + ns * nb)
    if data.GetNumberOfPoints() > 0:
        pts = np.asarray(data.Points)
        d = np.asarray(data.PointData["diameter"])
        vol = np.pi * d ** 3 / 6.0
        m = np.asarray(data.PointData["density"]) * vol
        vz = np.asarray(data.PointData["velocity"])[:, 2]
        sp = np.asarray(data.PointData["species"]).astype(int)
        sums[:ns] = np.bincount(sp, weights=m * pts[:, 2], minlength=ns)
        sums[ns:2 * ns] = np.bincount(sp, weights=m, minlength=ns)
        sums[2 * ns:3 * ns] = np.bincount(sp, weights=m * vz, minlength=ns)
        sums[3 * ns:] = layer_volumes(pts[:, 2], vol, sp, ns, box[4], dz, nb).ravel()
    sums = si.allreduce_sum(sums)
    if si.RANK != 0:
        return
    mz, mass, mvz = sums[:ns], sums[ns:2 * ns], sums[2 * ns:3 * ns]
    com = [mz[k] / mass[k] if mass[k] > 0 else float("nan") for k in range(ns)]
    vz_mean = [mvz[k] / mass[k] if mass[k] > 0 else float("nan") for k in range(ns)]
    com_all = mz.sum() / mass.sum() if mass.sum() > 0 else float("nan")
    frac = [layer_profile(v) / ((box[1] - box[0]) * (box[3] - box[2]) * dz) for v in sums[3 * ns:].reshape(ns, nb)]
    path = os.path.join(si.OUT, "com.csv")
    si.resume_csv_pipeline(state, "com_tracks", path)  # rows and c0 of the run before
    if "c0" not in state:
        state["c0"] = [float(np.median(frac[k][frac[k] > 0])) if np.any(frac[k] > 0) else 0.0 for k in range(ns)]
        si.save_state("com_tracks", {"c0": state["c0"]})
    fronts = [front_height(frac[k], state["c0"][k], box[4], dz) for k in range(ns)]
    new = "header" not in state
    with open(path, "w" if new else "a") as f:
        if new:
            f.write(",".join(["time"] + ["com_z:" + n for n in names] + ["com_z:all"] +
                             ["vz_mean:" + n for n in names] + ["front_z:" + n for n in names]) + "\n")
            state["header"] = True
        f.write(",".join(["%.17g" % info.time] + ["%.17g" % c for c in com] + ["%.17g" % com_all] +
                         ["%.17g" % v for v in vz_mean] + ["%.17g" % z for z in fronts]) + "\n")
