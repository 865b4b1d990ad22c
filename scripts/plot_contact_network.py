#!/usr/bin/python3
"""Draw the contact-force network of a finished run (Zhao, Houlsby & Utili 2014, Fig. 16).

Usage: /usr/bin/python3 scripts/plot_contact_network.py DIR [--out PNG]

Reads DIR/contact_network.csv (written by sphdem at the end of a run: one row per
contact, id_a,id_b,xa,ya,za,xb,yb,zb,overlap,normal_force) and draws every contact as a
line between the two centres in the x-z projection, its width and colour proportional
to the normal force. Forces are shown normalised as in Zhao's eq. 17 when DIR/case.yaml
gives the column: [F] = F / ((rho_s - rho_f) g H d_mean^2); otherwise in newtons.
Writes DIR/contact_network.png (or --out).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402


def force_scale(case_path):
    """(scale, label) from case.yaml, or (1, 'N') when it cannot be read."""
    try:
        import yaml  # optional: only for the normalisation
    except ImportError:
        return 1.0, "normal force (N)"
    try:
        with open(case_path) as f:
            case = yaml.safe_load(f)
        sp = case["species"][0]
        dist = sp.get("size_distribution")
        if sp.get("diameter"):
            d = float(sp["diameter"])
        else:
            d = 0.5 * (float(dist["min"]) + float(dist["max"]))
        rho_s, rho_f = float(sp["density"]), float(case["fluid"]["density"])
        g = abs(float(case["gravity"][2]))
        H = float(case["fluid"]["fill_height"]) or float(case["domain"]["size"][2])
        return 1.0 / ((rho_s - rho_f) * g * H * d * d), "[F] = F / ((rho_s - rho_f) g H d_mean^2)"
    except (OSError, KeyError, TypeError, ValueError, IndexError):
        return 1.0, "normal force (N)"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir")
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    path = os.path.join(a.dir, "contact_network.csv")
    if not os.path.exists(path):
        sys.exit(f"{path}: not found (run sphdem first)")
    c = np.genfromtxt(path, delimiter=",", names=True, ndmin=1)
    if c.size == 0:
        sys.exit(f"{path}: no contacts")
    scale, label = force_scale(os.path.join(a.dir, "case.yaml"))
    f = c["normal_force"] * scale
    segs = np.stack([np.column_stack([c["xa"], c["za"]]), np.column_stack([c["xb"], c["zb"]])], axis=1)
    order = np.argsort(f)  # strong chains on top
    fmax = f.max() if f.max() > 0 else 1.0
    lc = LineCollection(segs[order] * 1e3, linewidths=0.3 + 3.0 * f[order] / fmax, cmap="viridis",
                        array=f[order], capstyle="round")
    zmax = max(c["za"].max(), c["zb"].max()) * 1e3
    fig, ax = plt.subplots(figsize=(4, max(4, min(12, 4 * zmax / 25.0))))
    ax.add_collection(lc)
    ax.set_xlim(min(c["xa"].min(), c["xb"].min()) * 1e3 - 1, max(c["xa"].max(), c["xb"].max()) * 1e3 + 1)
    ax.set_ylim(0, zmax + 2)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("z (mm)")
    ax.set_title(f"contact forces, {c.size} contacts")
    fig.colorbar(lc, ax=ax, label=label, shrink=0.8)
    out = a.out or os.path.join(a.dir, "contact_network.png")
    fig.savefig(out, dpi=150, bbox_inches="tight")
    print(f"wrote {out}: {c.size} contacts, max {f.max():.4g} ({label})")


if __name__ == "__main__":
    main()
