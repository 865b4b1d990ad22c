"""Measurements more than one scene makes: a time average over a window, a run's last
whole acoustic periods, and a block's error extrapolated to a block without faces."""
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
