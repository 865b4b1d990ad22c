"""Checks of test insitu_two_ranks (run by two_ranks.sh with Debian's /usr/bin/python3).

    compare_ranks.py NP1_DIR NP2_DIR

NP1_DIR and NP2_DIR are the output directories of two_rank_driver run on one and on
two MPI ranks. Asserts that
  * voidage_height.h5 (time, z, voidage), interfaces.csv and com.csv agree between the
    runs (numpy allclose, rtol 1e-12, atol 1e-14, nan == nan);
  * com.csv equals the mass-weighted centre of mass of the known particle set,
    regenerated here from the driver's seed (and the driver's own known_com.csv);
  * the voidage profile integrates to the solid volume:
    Lx Ly sum_z (1 - eps(z)) dz = total sphere volume within 1 %.
Exits 1 with a message naming every mismatch.
"""
import csv
import math
import os
import sys

import h5py
import numpy as np

RTOL, ATOL = 1e-12, 1e-14
# com.csv is printed with 12 significant digits
RTOL_PRINTED = 1e-11

# The known particle set: keep in step with two_rank_driver.cpp (the driver's
# known_com.csv, compared below, catches any drift).
SEED = 20240607
N_SPHERES = 400
N_BAND = 370
LX, LY, LZ = 0.0016, 0.0016, 0.004
BAND = (0.0016, 0.0024)
SPREAD = (0.0005, 0.0035)
DROP = 2e-4
DIAMETER = (1.0e-4, 1.6e-4)
DENSITY = (2500.0, 4000.0)
SPECIES = ("small", "large")
TIMES = (0.0, 1e-3, 2e-3)

failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg)


def known_set():
    """(species, z, mass, volume) of the spheres at t = 0, as the driver builds them:
    per sphere four uniforms (species, x, y, z), each numpy's random_sample formula
    (genrand_res53) on two raw mt19937 outputs."""
    raw = np.random.RandomState(SEED)._bit_generator.random_raw(8 * N_SPHERES)
    raw = [int(v) for v in raw]

    def u(k):
        a, b = raw[2 * k] >> 5, raw[2 * k + 1] >> 6
        return (a * 67108864 + b) / 9007199254740992.0

    sp = np.zeros(N_SPHERES, dtype=int)
    z = np.zeros(N_SPHERES)
    mass = np.zeros(N_SPHERES)
    vol = np.zeros(N_SPHERES)
    for i in range(N_SPHERES):
        s = 0 if u(4 * i) < 0.5 else 1
        lo, hi = BAND if i < N_BAND else SPREAD
        sp[i] = s
        z[i] = lo + (hi - lo) * u(4 * i + 3)
        r = 0.5 * DIAMETER[s]
        vol[i] = 4.0 / 3.0 * math.pi * r * r * r
        mass[i] = DENSITY[s] * vol[i]
    return sp, z, mass, vol


def known_com():
    """Rows (time, com small, com large, com all) of the known set over the frames."""
    sp, z, mass, vol = known_set()
    rows = []
    for f, t in enumerate(TIMES):
        if f > 0:
            z = z - DROP * (1.0 + 0.1 * sp)
        row = [t]
        for s in range(len(SPECIES)):
            m = sp == s
            row.append(float(np.sum(mass[m] * z[m]) / np.sum(mass[m])))
        row.append(float(np.sum(mass * z) / np.sum(mass)))
        rows.append(row)
    return np.array(rows), float(np.sum(vol))


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header = rows[0]
    data = np.array([[float(v) for v in r] for r in rows[1:] if r], dtype=float)
    return header, data.reshape(-1, len(header))


def close(a, b, rtol=RTOL, atol=ATOL):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.allclose(a, b, rtol=rtol, atol=atol, equal_nan=True))


def describe(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        return "shapes %s vs %s" % (a.shape, b.shape)
    d = np.abs(a - b)
    d[np.isnan(a) & np.isnan(b)] = 0
    d[np.isnan(a) != np.isnan(b)] = np.inf
    k = np.unravel_index(int(np.argmax(d)), d.shape)
    return "largest difference %.3g at index %s: %r vs %r" % (d[k], tuple(int(i) for i in k), a[k], b[k])


def main(np1, np2):
    runs = {"np1": os.path.join(np1, "insitu"), "np2": os.path.join(np2, "insitu")}
    for name, d in runs.items():
        for f in ("voidage_height.h5", "interfaces.csv", "com.csv"):
            if not os.path.isfile(os.path.join(d, f)):
                fail("%s: %s missing" % (name, os.path.join(d, f)))
    if failures:
        return 1

    # voidage-height map
    h5 = {}
    for name, d in runs.items():
        with h5py.File(os.path.join(d, "voidage_height.h5"), "r") as h:
            h5[name] = {k: h[k][()] for k in ("time", "z", "voidage")}
            h5[name]["attrs"] = dict(h.attrs)
    for k in ("time", "z", "voidage"):
        if not close(h5["np1"][k], h5["np2"][k]):
            fail("voidage_height.h5 dataset '%s' differs between 1 and 2 ranks: %s"
                 % (k, describe(h5["np1"][k], h5["np2"][k])))
    if not close(h5["np1"]["time"], TIMES):
        fail("voidage_height.h5 time = %s, expected %s" % (h5["np1"]["time"], TIMES))
    for a in ("column_height",):
        if h5["np1"]["attrs"].get(a) != h5["np2"]["attrs"].get(a):
            fail("voidage_height.h5 attribute %s differs: %r vs %r"
                 % (a, h5["np1"]["attrs"].get(a), h5["np2"]["attrs"].get(a)))

    # interfaces and centres of mass
    tables = {}
    for f in ("interfaces.csv", "com.csv"):
        (h1, d1), (h2, d2) = (read_csv(os.path.join(runs[n], f)) for n in ("np1", "np2"))
        tables[f] = (h1, d1)
        if h1 != h2:
            fail("%s header differs between 1 and 2 ranks: %s vs %s" % (f, h1, h2))
        elif not close(d1, d2):
            fail("%s differs between 1 and 2 ranks: %s" % (f, describe(d1, d2)))
        if d1.shape[0] != len(TIMES):
            fail("%s has %d rows, expected %d" % (f, d1.shape[0], len(TIMES)))
    h_int, d_int = tables["interfaces.csv"]
    if d_int.size and not np.all(np.isfinite(d_int)):
        fail("interfaces.csv has non-finite interface heights on this known set:\n%s" % d_int)

    expected, solid = known_com()
    want_header = (["time"] + ["com_z:" + s for s in SPECIES] + ["com_z:all"] + ["vz_mean:" + s for s in SPECIES]
                   + ["front_z:" + s for s in SPECIES])
    for name, d in runs.items():
        header, com = read_csv(os.path.join(d, "com.csv"))
        com = com[:, :expected.shape[1]]  # vz_mean and front_z: compared between 1 and 2 ranks above
        if header != want_header:
            fail("%s com.csv header %s, expected %s" % (name, header, want_header))
        elif not close(com, expected, rtol=RTOL_PRINTED, atol=0):
            fail("%s com.csv differs from the known centre of mass: %s" % (name, describe(com, expected)))
        kpath = os.path.join(os.path.dirname(d), "known_com.csv")
        kh, kd = read_csv(kpath)
        if not close(kd[:, :4], expected, rtol=RTOL, atol=0):
            fail("%s known_com.csv (driver) differs from the set regenerated here (seed or constants "
                 "out of step with two_rank_driver.cpp?): %s" % (name, describe(kd[:, :4], expected)))
        if not close(kd[:, 4], np.full(kd.shape[0], solid), rtol=RTOL, atol=0):
            fail("%s known_com.csv solid volume %r, regenerated %r" % (name, kd[0, 4], solid))

    # the profile integrates to the solid volume
    z = h5["np1"]["z"]
    dz = np.diff(z)
    if dz.size == 0 or not np.allclose(dz, dz[0], rtol=1e-9):
        fail("voidage_height.h5 z is not a uniform grid: %s" % z)
    else:
        for name in runs:
            for f, t in enumerate(h5[name]["time"]):
                integral = LX * LY * float(np.sum(1.0 - h5[name]["voidage"][f])) * dz[0]
                rel = integral / solid - 1.0
                print("%s t=%g: Lx Ly sum (1 - eps) dz = %.6e m^3, sphere volume %.6e m^3 (%+.3f %%)"
                      % (name, t, integral, solid, 100 * rel))
                if abs(rel) > 0.01:
                    fail("%s t=%g: the voidage profile integrates to %.6e m^3 of solid, the spheres hold "
                         "%.6e m^3 (%+.2f %%, allowed 1 %%)" % (name, t, integral, solid, 100 * rel))

    print("com.csv (np2):")
    print(open(os.path.join(runs["np2"], "com.csv")).read().rstrip())
    print("interfaces.csv (np2):")
    print(open(os.path.join(runs["np2"], "interfaces.csv")).read().rstrip())
    if failures:
        print("insitu_two_ranks: %d check(s) failed" % len(failures))
        return 1
    print("insitu_two_ranks: 1 and 2 ranks agree; centre of mass and solid volume match the known set")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
