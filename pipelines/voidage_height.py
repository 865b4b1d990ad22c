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
state = {}


def take_back_rows(path):
    """A resumed run: the map's rows up to the checkpoint's time."""
    import h5py

    if not os.path.exists(path):
        return
    with h5py.File(path, "r") as h:
        for t, row in zip(h["time"][()], h["voidage"][()]):
            if si.before_resume(float(t)):
                times.append(float(t))
                profiles.append(np.asarray(row))
        attrs.update({k: float(v) for k, v in h.attrs.items()})


def catalyst_execute(info):
    z, eps = si.voidage_profile(voidage, info.time)
    if si.RANK != 0:
        return
    path = os.path.join(si.OUT, "voidage_height.h5")
    if si.resumed() and "resumed" not in state:
        state["resumed"] = True
        take_back_rows(path)
    if not attrs:
        img = si.local_data(voidage, info.time)
        attrs["column_height"] = float(si.field(img, "column_height")[0])
        v = float(si.field(img, "reference_velocity")[0])
        attrs["reference_interface_velocity"] = v if v > 0 else float("nan")
    times.append(info.time)
    profiles.append(eps)

    def write(tmp):
        import h5py

        with h5py.File(tmp, "w") as h:
            h["time"] = np.asarray(times)
            h["z"] = z
            h["voidage"] = np.vstack(profiles)
            for k, val in attrs.items():
                h.attrs[k] = val

    si.write_atomic(path, write)
