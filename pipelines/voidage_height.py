# script-version: 2
"""voidage_height: the laterally averaged voidage eps(z) at each analysis time,
accumulated into a voidage-height-time map: DIR/insitu/voidage_height.h5 with datasets
time (nt), z (nz, m) and voidage (nt x nz), rewritten after every analysis."""
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

times, profiles = [], []
attrs = {}


def catalyst_execute(info):
    z, eps = si.voidage_profile(voidage, info.time)
    if si.RANK != 0:
        return
    if not attrs:
        img = si.local_data(voidage, info.time)
        attrs["column_height"] = float(si.field(img, "column_height")[0])
        v = float(si.field(img, "reference_velocity")[0])
        attrs["reference_interface_velocity"] = v if v > 0 else float("nan")
    times.append(info.time)
    profiles.append(eps)
    path = os.path.join(si.OUT, "voidage_height.h5")

    def write(tmp):
        import h5py

        with h5py.File(tmp, "w") as h:
            h["time"] = np.asarray(times)
            h["z"] = z
            h["voidage"] = np.vstack(profiles)
            for k, val in attrs.items():
                h.attrs[k] = val

    si.write_atomic(path, write)
