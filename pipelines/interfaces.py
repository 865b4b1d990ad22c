# script-version: 2
"""interfaces: heights of the clear-liquid/suspension interface (z_top) and of the
suspension/sediment interface (z_bottom) over time, from the laterally averaged
voidage eps(z) restricted to 0 <= z <= H. DIR/insitu/interfaces.csv: time,z_top,z_bottom.

Criterion (documented in pipelines/README.md):
  eps_s  = voidage of the suspension, the median of eps(z) where eps < 0.99 at the
           first analysis (the initial suspension or block);
  z_top  = highest z where eps(z) falls below (1 + eps_s)/2, linearly interpolated;
  z_bottom = going down from z_top, the first z where eps leaves the suspension band:
           below eps_s - (eps_s - 0.36)/2 (top of a sediment; 0.36 = random close
           packing) or above (1 + eps_s)/2 (clear liquid under a falling block); the
           wall (0) when the suspension reaches it. nan when there is no suspension.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # sphdem_insitu
import numpy as np
from paraview import catalyst
from paraview.simple import TrivialProducer

import sphdem_insitu as si

voidage = TrivialProducer(registrationName="voidage")
options = catalyst.Options()
options.GlobalTrigger = "TimeStep"

EPS_RCP = 0.36
state = {}


def crossing(z, eps, i, level):
    """z where eps crosses level between samples i and i+1 (linear)."""
    e0, e1 = eps[i], eps[i + 1]
    if e1 == e0:
        return z[i]
    return z[i] + (level - e0) * (z[i + 1] - z[i]) / (e1 - e0)


def find_interfaces(z, eps, eps_s):
    top_level = 0.5 * (1.0 + eps_s)
    sed_level = eps_s - 0.5 * (eps_s - EPS_RCP)
    below = np.nonzero(eps < top_level)[0]
    if below.size == 0:
        return math.nan, math.nan
    k = below[-1]
    z_top = crossing(z, eps, k, top_level) if k + 1 < len(z) else z[k]
    z_bottom = 0.0
    for i in range(k, 0, -1):
        if eps[i - 1] < sed_level:
            z_bottom = crossing(z, eps, i - 1, sed_level)
            break
        if eps[i - 1] > top_level:
            z_bottom = crossing(z, eps, i - 1, top_level)
            break
    return z_top, z_bottom


def catalyst_execute(info):
    z, eps = si.voidage_profile(voidage, info.time)
    if si.RANK != 0:
        return
    img = si.local_data(voidage, info.time)
    H = float(si.field(img, "column_height")[0])
    inside = (z >= 0.0) & (z <= H)
    z, eps = z[inside], eps[inside]
    path = os.path.join(si.OUT, "interfaces.csv")
    si.resume_csv_pipeline(state, "interfaces", path)  # rows and eps_s of the run before
    if "eps_s" not in state:
        occupied = eps[eps < 0.99]
        state["eps_s"] = float(np.median(occupied)) if occupied.size else math.nan
        si.save_state("interfaces", {"eps_s": state["eps_s"]})
    eps_s = state["eps_s"]
    z_top, z_bottom = (math.nan, math.nan) if math.isnan(eps_s) else find_interfaces(z, eps, eps_s)
    new = not os.path.exists(path) or "header" not in state
    with open(path, "w" if new else "a") as f:
        if new:
            f.write("time,z_top,z_bottom\n")
            state["header"] = True
        # the time to the last bit: a resumed run keeps the rows up to its checkpoint by it
        f.write("%.17g,%.9g,%.9g\n" % (info.time, z_top, z_bottom))
