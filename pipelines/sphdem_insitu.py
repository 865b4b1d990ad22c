"""Shared helpers of the sphdem Catalyst pipelines (imported by the V2 scripts).

Every reduction here is parallel-aware: each rank holds only the particles it owns
and its piece of the voidage grid, so sums are all-reduced over MPI ranks (inside
Catalyst, GetDataInformation()/GetRange() are rank-local). Rank 0 writes the files.
"""
import json
import math
import os

import numpy as np
from paraview.vtk.numpy_interface import dataset_adapter as dsa

try:
    from mpi4py import MPI

    COMM = MPI.COMM_WORLD
except Exception:  # no mpi4py: a single rank
    COMM = None

RANK = COMM.Get_rank() if COMM is not None else 0
# The run's options travel with every frame as field data (catalyst/insitu.cpp), read by
# the first frame a pipeline looks at (local_data): DIR/insitu (the analyses between
# snapshots, the scene's insitu.snapshot_every, are read by snapshots.py from each frame).
OUT = "."
# A resumed run (sphdem resume): the time and step of its checkpoint. Each pipeline keeps
# its rows up to that time, drops later ones (written before the run stopped) and takes
# back its state (load_state) at its first analysis after the resume. NaN: a new run.
RESUME_TIME = math.nan
RESUME_STEP = -1


def _configure(data):
    global OUT, RESUME_TIME, RESUME_STEP
    fd = data.VTKObject.GetFieldData()
    out = fd.GetAbstractArray("insitu_dir")
    if out is not None and out.GetNumberOfValues():
        OUT = out.GetValue(0)
    resume = fd.GetArray("resume_time")
    if resume is not None and resume.GetNumberOfTuples():
        RESUME_TIME = float(resume.GetValue(0))
    step = fd.GetArray("resume_step")
    if step is not None and step.GetNumberOfTuples():
        RESUME_STEP = int(step.GetValue(0))


def resumed():
    """True in a resumed run (the pipeline then continues its files)."""
    return not math.isnan(RESUME_TIME)


def before_resume(t):
    """Whether a row of time t was written before the checkpoint the run resumed from."""
    return t <= RESUME_TIME * (1.0 + 1e-12)


def _state_path(name):
    return os.path.join(OUT, "state", name + ".json")


def save_state(name, state):
    """A pipeline's state that a resumed run must take back (values fixed at the first
    analysis, such as the initial suspension's voidage): DIR/insitu/state/NAME.json."""
    os.makedirs(os.path.join(OUT, "state"), exist_ok=True)

    def write(tmp):
        with open(tmp, "w") as f:
            json.dump(state, f)

    write_atomic(_state_path(name), write)


def load_state(name):
    """The state save_state wrote, or {} when there is none."""
    try:
        with open(_state_path(name)) as f:
            return json.load(f)
    except (OSError, ValueError):
        return {}


def resume_csv_pipeline(state, name, path):
    """Once, at a resumed run's first analysis: a CSV pipeline takes back the state it saved
    (values fixed at the first analysis) and continues its CSV (rows up to the checkpoint)."""
    if not resumed() or "resumed" in state:
        return
    state["resumed"] = True
    state.update(load_state(name))
    if continue_csv(path):
        state["header"] = True


def continue_csv(path):
    """A resumed run's CSV: the header and the rows of times up to the checkpoint are
    kept (first column: time), later rows cut. Returns whether the file had a header."""
    if not os.path.exists(path):
        return False
    with open(path) as f:
        lines = f.readlines()
    if not lines:
        return False
    kept = [lines[0]]
    for line in lines[1:]:
        try:
            if not line.endswith("\n") or not before_resume(float(line.split(",", 1)[0])):
                break
        except ValueError:
            break
        kept.append(line)

    def write(tmp):
        with open(tmp, "w") as f:
            f.writelines(kept)

    write_atomic(path, write)
    return True


def allreduce_sum(a):
    """Element-wise sum of a numpy array over ranks."""
    a = np.ascontiguousarray(a, dtype=np.float64)
    if COMM is None or COMM.Get_size() == 1:
        return a
    out = np.empty_like(a)
    COMM.Allreduce(a, out, op=MPI.SUM)
    return out


def local_data(producer, time):
    """The rank-local dataset of a Catalyst channel, wrapped for numpy."""
    producer.UpdatePipeline(time)
    data = dsa.WrapDataObject(producer.GetClientSideObject().GetOutputDataObject(0))
    _configure(data)
    return data


def field(data, name):
    return np.asarray(data.FieldData[name])


def species_names(data):
    arr = data.VTKObject.GetFieldData().GetAbstractArray("species_names")
    return [arr.GetValue(i) for i in range(arr.GetNumberOfValues())]


_profile_cache = {}


def voidage_profile(producer, time):
    """Laterally averaged voidage eps(z) over the whole grid: (z, eps), cached per time
    so that every pipeline of one analysis shares one reduction."""
    if time in _profile_cache:
        return _profile_cache[time]
    img = local_data(producer, time)
    obj = img.VTKObject
    ext = obj.GetExtent()
    whole = field(img, "whole_extent").astype(int)
    origin, spacing = obj.GetOrigin(), obj.GetSpacing()
    nz_whole = whole[5] - whole[4] + 1
    sums = np.zeros(nz_whole)
    counts = np.zeros(nz_whole)
    eps = np.asarray(img.PointData["voidage"])
    if eps.size:
        ni, nj, nk = ext[1] - ext[0] + 1, ext[3] - ext[2] + 1, ext[5] - ext[4] + 1
        block = eps.reshape(nk, nj, ni)
        k0 = ext[4] - whole[4]
        sums[k0:k0 + nk] += block.sum(axis=(1, 2))
        counts[k0:k0 + nk] += ni * nj
    sums = allreduce_sum(sums)
    counts = allreduce_sum(counts)
    z = origin[2] + spacing[2] * np.arange(whole[4], whole[5] + 1)
    prof = (z, sums / np.maximum(counts, 1))
    _profile_cache.clear()
    _profile_cache[time] = prof
    return prof


def write_atomic(path, writer):
    """Write through a temporary file and rename, so readers (and an interrupted run)
    never see half a file."""
    tmp = path + ".tmp"
    writer(tmp)
    os.replace(tmp, path)
