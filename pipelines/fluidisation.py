"""A fluidisation curve's readings, one definition for the figure (figures.py) and the
validation rows (validation/fluidised_bed.py). numpy only.

  rising      the log rows where U has only risen so far and is positive (the rising
              branch; U held after rising counts, U falling does not)
  fit_branch  least squares dP = a U + b U^2 (Ergun's form) over the rising rows whose dP
              is under FIT_BELOW of the buoyant weight per area W (the fixed bed)
  u_mf        where that fit meets W: the experimentalists' construction of U_mf (the
              fixed-bed line against the plateau)
  plateau     the mean dP of the rising rows with U in EXPANDED x U_mf (the fluidised bed)
  holds       the stretches where U is held at a positive value, each as its U and the rows
              of its second half (where the bed has had time to settle at that U)
"""
import numpy as np

FIT_BELOW = 0.8  # of W: the rising points the fixed-bed fit takes
EXPANDED = (1.5, 5.0)  # of U_mf: the fluidised bed's plateau and expansion (issue 37)


def rising(U):
    """Indices of the rising branch: U > 0 and U at its running maximum."""
    U = np.asarray(U, dtype=float)
    return np.nonzero((U > 0.0) & (U >= np.maximum.accumulate(U)))[0]


def fit_branch(U, dP):
    """(a, b) of dP = a U + b U^2 by least squares."""
    A = np.column_stack((U, np.asarray(U) ** 2))
    (a, b), *_ = np.linalg.lstsq(A, np.asarray(dP), rcond=None)
    return float(a), float(b)


def u_mf(U, dP, weight):
    """(U_mf, a, b): the rising branch's fixed-bed fit (points under FIT_BELOW weight)
    meeting the buoyant weight per area; None when fewer than 3 points are under it."""
    U, dP = np.asarray(U, dtype=float), np.asarray(dP, dtype=float)
    up = rising(U)
    fixed = up[dP[up] < FIT_BELOW * weight]
    if fixed.size < 3:
        return None
    a, b = fit_branch(U[fixed], dP[fixed])
    root = (-a + np.sqrt(a * a + 4.0 * b * weight)) / (2.0 * b) if b > 0 else weight / a
    return float(root), a, b


def expanded(U, umf):
    """Indices of the rising rows with U in EXPANDED x U_mf."""
    U = np.asarray(U, dtype=float)
    up = rising(U)
    return up[(U[up] >= EXPANDED[0] * umf) & (U[up] <= EXPANDED[1] * umf)]


def plateau(U, dP, umf):
    """The mean dP over expanded(U, umf); nan when no row is there."""
    sel = expanded(U, umf)
    return float(np.mean(np.asarray(dP)[sel])) if sel.size else float("nan")


def holds(t, U, min_duration=0.0):
    """[(U, rows)] for each stretch of rows at one positive U lasting at least min_duration
    (s): rows are those of its second half in time."""
    t, U = np.asarray(t, dtype=float), np.asarray(U, dtype=float)
    out, start = [], 0
    for k in range(1, len(U) + 1):
        if k < len(U) and U[k] == U[start]:
            continue
        if U[start] > 0.0 and t[k - 1] - t[start] >= max(min_duration, 0.0) and k - 1 > start:
            half = 0.5 * (t[start] + t[k - 1])
            out.append((float(U[start]), np.arange(start, k)[t[start:k] >= half]))
        start = k
    return out
