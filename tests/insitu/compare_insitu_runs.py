"""Checks of test insitu_on_ranks (Debian's /usr/bin/python3):

    compare_insitu_runs.py A_INSITU B_INSITU TOL

A_INSITU and B_INSITU are two runs' insitu folders. Asserts that voidage_height.h5
(time, z, voidage), interfaces.csv and com.csv have the same rows and agree within TOL
(absolute: metres, m/s and voidage; NaN == NaN). Exits 1 naming every mismatch."""
import sys

import h5py
import numpy as np


def table(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    return header, np.atleast_2d(np.genfromtxt(path, delimiter=",", skip_header=1))


def main(a_dir, b_dir, tol):
    problems = []

    def close(what, a, b):
        a, b = np.asarray(a, float), np.asarray(b, float)
        if a.shape != b.shape:
            problems.append(f"{what}: shapes {a.shape} and {b.shape}")
            return
        if not np.allclose(a, b, rtol=0, atol=tol, equal_nan=True):
            worst = np.nanmax(np.abs(a - b))
            problems.append(f"{what}: differ by up to {worst:.3g} (tolerance {tol:g})")
        else:
            print(f"{what}: {a.size} values within {tol:g} (largest {np.nanmax(np.abs(a - b)):.3g})")

    with h5py.File(f"{a_dir}/voidage_height.h5") as a, h5py.File(f"{b_dir}/voidage_height.h5") as b:
        for name in ("time", "z", "voidage"):
            close(f"voidage_height.h5:{name}", a[name][:], b[name][:])
    for name in ("interfaces.csv", "com.csv"):
        ha, ta = table(f"{a_dir}/{name}")
        hb, tb = table(f"{b_dir}/{name}")
        if ha != hb:
            problems.append(f"{name}: columns {ha} and {hb}")
            continue
        close(name, ta, tb)
    for p in problems:
        print("FAIL:", p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], float(sys.argv[3])))
