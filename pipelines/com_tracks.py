# script-version: 2
"""com_tracks: centre of mass (height) of each species and of all spheres over time.
DIR/insitu/com.csv: time, com_z:S for each species S, com_z:all (m), mass-weighted,
summed over MPI ranks."""
import os
import sys

sys.path.insert(0, os.environ.get("SPHDEM_PIPELINES_DIR", "."))
import numpy as np
from paraview import catalyst
from paraview.simple import TrivialProducer

import sphdem_insitu as si

particles = TrivialProducer(registrationName="particles")
options = catalyst.Options()
options.GlobalTrigger = "TimeStep"

state = {}


def catalyst_execute(info):
    data = si.local_data(particles, info.time)
    names = si.species_names(data)
    ns = len(names)
    sums = np.zeros(2 * ns)  # [sum m z per species, sum m per species]
    if data.GetNumberOfPoints() > 0:
        pts = np.asarray(data.Points)
        d = np.asarray(data.PointData["diameter"])
        m = np.asarray(data.PointData["density"]) * np.pi * d ** 3 / 6.0
        sp = np.asarray(data.PointData["species"]).astype(int)
        sums[:ns] = np.bincount(sp, weights=m * pts[:, 2], minlength=ns)
        sums[ns:] = np.bincount(sp, weights=m, minlength=ns)
    sums = si.allreduce_sum(sums)
    if si.RANK != 0:
        return
    mz, mass = sums[:ns], sums[ns:]
    com = [mz[k] / mass[k] if mass[k] > 0 else float("nan") for k in range(ns)]
    com_all = mz.sum() / mass.sum() if mass.sum() > 0 else float("nan")
    path = os.path.join(si.OUT, "com.csv")
    new = "header" not in state
    with open(path, "w" if new else "a") as f:
        if new:
            f.write(",".join(["time"] + ["com_z:" + n for n in names] + ["com_z:all"]) + "\n")
            state["header"] = True
        f.write(",".join(["%.17g" % info.time] + ["%.17g" % c for c in com] + ["%.17g" % com_all]) + "\n")
