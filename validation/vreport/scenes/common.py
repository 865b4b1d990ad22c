"""Measurements more than one scene makes: a time average over a window, a run's last
whole acoustic periods, a block's error extrapolated to a block without faces, a front's
speed with the lattice's beat, and a suspension's equivalent sharp interface."""
import os

import numpy as np


def time_average(t, y, t0, t1):
    """Trapezoidal mean of y(t) over [t0, t1] (y linearly interpolated at the ends)."""
    ts = np.concatenate(([t0], t[(t > t0) & (t < t1)], [t1]))
    ys = np.interp(ts, t, y)
    return np.trapz(ys, ts) / (t1 - t0)


def whole_periods(r, startup):
    """(t0, t1, n): the run's last n whole acoustic periods 4H/c0 after `startup` (the
    column rings at that period, so the blocks' slips are averaged over whole ones)."""
    period = r.acoustic_period()
    t1 = r.log["time"][-1]
    n = int((t1 - startup) // period)
    return t1 - n * period, t1, n


def face_extrapolation(short, tall, slip_and_reference):
    """A block's error at two heights H_b fitted as a + b/H_b (the faces' share goes as
    1/H_b); a is the error of a block without faces. slip_and_reference(run) gives the
    run's (slip, reference). Returns (h1, e1, h2, e2, a, b)."""
    pts = []
    for r in (short, tall):
        slip, ref = slip_and_reference(r)
        g0 = r.case["particles"][0]
        pts.append((g0["max"][2] - g0["min"][2], slip / ref - 1))
    (h1, e1), (h2, e2) = pts
    b = (e1 - e2) / (1 / h1 - 1 / h2)
    return h1, e1, h2, e2, e1 - b / h1, b


def front_speed_with_beat(t, z, dx):
    """(speed -dz/dt, beat amplitude) of an interface z(t) fitted as a line plus the beat of
    the fluid's lattice: a front crossing fluid layers dx apart at speed u wobbles with period
    dx/u (validation/README.md, session 40), and a line alone over a window that is not a whole
    number of those periods tilts with the beat's phase. z = a − u t + c sin(ωt) + s cos(ωt),
    ω = 2π u/dx, u found by iterating from the line's. A window shorter than one period gets
    the line alone (amplitude nan)."""
    u = -np.polyfit(t, z, 1)[0]
    if u <= 0 or (t[-1] - t[0]) * u < dx:
        return u, float("nan")
    for _ in range(5):
        w = 2 * np.pi * u / dx
        coef = np.linalg.lstsq(np.c_[np.ones_like(t), t, np.sin(w * t), np.cos(w * t)], z, rcond=None)[0]
        u = -coef[1]
    return u, float(np.hypot(coef[2], coef[3]))


def equivalent_interface(r, t_lo, t_hi):
    """A suspension's equivalent sharp interface from the in-situ voidage map: the solid
    volume above a level z_ref inside the homogeneous suspension, spread at its initial
    voidage eps_s, z_eq = z_ref + int_{z_ref} (1 - eps) dz / (1 - eps_s). By mass
    conservation it falls at the flux through z_ref over (1 - eps_s), i.e. the speed of the
    bulk spheres, whatever the shape of the front. z_ref is midway between the lowest upper
    interface and the highest sediment top of [t_lo, t_hi], each a kernel support away.
    Returns (z_ref, eps_s, times, z_eq) over the window, or None without the map, or where
    front and sediment come within two supports, or with fewer than 4 maps in the window."""
    vh = os.path.join(r.dir, "insitu", "voidage_height.h5")
    if not os.path.exists(vh) or t_hi <= t_lo:
        return None
    import h5py
    with h5py.File(vh, "r") as f:
        tv, zv, ev = f["time"][:], f["z"][:], f["voidage"][:]
    zt, zb = r.interfaces["z_top"], r.interfaces["z_bottom"]
    sel = (tv >= t_lo - 1e-9) & (tv <= t_hi + 1e-9)
    h2 = 2 * r.case["fluid"]["smoothing_factor"] * r.case["fluid"]["spacing"]   # kernel support
    z_ref = 0.5 * (np.nanmin(zt[sel]) - h2 + np.nanmax(zb[sel]) + h2)
    eps_s = np.median(ev[0][(zv > h2) & (zv < zt[0] - h2)])
    if not (np.nanmin(zt[sel]) - h2 > np.nanmax(zb[sel]) + h2 and sel.sum() >= 4):
        return None
    above = zv >= z_ref
    z_eq = np.array([z_ref + np.trapz(1 - e[above], zv[above]) / (1 - eps_s) for e in ev[sel]])
    return z_ref, eps_s, tv[sel], z_eq
