"""validation/fluidised_bed.py, the rows of a fluidised bed's run, on a synthetic run whose
answers are known: a fixed branch that is Ergun's at the bed's voidage, a plateau a set
fraction of the buoyant weight per area, and an expansion on Richardson & Zaki's line."""
import csv
import math
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "validation"))
import drag_laws  # noqa: E402
import fluidised_bed  # noqa: E402
import fluidisation  # noqa: E402  (pipelines/, on the path fluidised_bed.py sets)

D, RHO_P, RHO_F, MU, G = 1e-3, 2500.0, 1000.0, 8.9e-4, 9.81
EPS_MF, W = 0.42, 130.0  # the packed bed's voidage, its buoyant weight per area (Pa)
CASE = f"""species:
  - {{name: glass, diameter: {D}, density: {RHO_P}}}
fluid: {{density: {RHO_F}, viscosity: {MU}}}
drag: {{law: di_felice}}
gravity: [0, 0, -{G}]
"""


def write_run(out_dir, rows):
    """DIR/log.csv from the rows (dicts), DIR/case.yaml the scene's CASE."""
    with open(os.path.join(out_dir, "log.csv"), "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(out_dir, "case.yaml"), "w") as fh:
        fh.write(CASE)


def synthetic_run(out_dir, plateau_ratio):
    """U 0 -> 40 mm/s -> 0; the bed fixed at EPS_MF below Ergun's U_mf, then at the plateau
    and expanded as U = u_t eps^n_RZ (falling: the same points)."""
    umf = drag_laws.u_mf("ergun", D, RHO_P, RHO_F, MU, EPS_MF, G)
    band = drag_laws.rz_band(D, RHO_P, RHO_F, MU, 0.5, 0.0, G)
    u_t, n_rz = band[2], band[4]
    h_of = lambda eps: W / ((RHO_P - RHO_F) * G * (1.0 - eps))  # noqa: E731
    rows = []
    for k in range(401):
        U = 0.04 * (k / 200 if k <= 200 else (400 - k) / 200)
        if U < umf:
            eps, dp = EPS_MF, drag_laws.ergun_gradient(D, RHO_F, MU, EPS_MF, U) * h_of(EPS_MF)
        else:
            eps, dp = max(EPS_MF, (U / u_t) ** (1.0 / n_rz)), plateau_ratio * W
        rows.append({"time": 0.01 * k, "superficial_velocity": U, "pressure_drop": dp,
                     "bed_height": h_of(eps), "bed_weight": W})
    write_run(out_dir, rows)
    return umf


def stepped_run(out_dir, hold):
    """U up a ramp to 20 mm/s, then held `hold` s at 20, 30 and 40 mm/s (ramps of 0.1 s
    between): below U_mf the fixed bed at EPS_MF; above it the bed relaxes to Richardson &
    Zaki's eps over 0.1 s, eps = eps_RZ - (eps_RZ - eps_before) exp(-(t - t_step) / 0.1)."""
    band = drag_laws.rz_band(D, RHO_P, RHO_F, MU, 0.5, 0.0, G)
    u_t, n_rz = band[2], band[4]
    h_of = lambda eps: W / ((RHO_P - RHO_F) * G * (1.0 - eps))  # noqa: E731
    times, speeds = [0.0, 0.5], [0.0, 0.02]
    for k, u in enumerate((0.02, 0.03, 0.04)):
        if k:
            times.append(times[-1] + 0.1)
            speeds.append(u)
        times.append(times[-1] + hold)
        speeds.append(u)
    rows, eps, t_step, eps_step = [], EPS_MF, 0.0, EPS_MF
    n = int(round(times[-1] / 0.005))
    for k in range(n + 1):
        t = 0.005 * k
        U = speeds[-1] if t >= times[-1] else float(
            next(speeds[i] + (speeds[i + 1] - speeds[i]) * (t - times[i]) / (times[i + 1] - times[i])
                 for i in range(len(times) - 1) if times[i] <= t <= times[i + 1]))
        target = max(EPS_MF, (U / u_t) ** (1.0 / n_rz))
        if rows and U != rows[-1]["superficial_velocity"]:
            t_step, eps_step = t, eps
        eps = target - (target - eps_step) * math.exp(-(t - t_step) / 0.1)
        dp = drag_laws.ergun_gradient(D, RHO_F, MU, EPS_MF, U) * h_of(EPS_MF) if target == EPS_MF else W
        rows.append({"time": t, "superficial_velocity": U, "pressure_drop": min(dp, W),
                     "bed_height": h_of(eps), "bed_weight": W})
    write_run(out_dir, rows)
    return [(u, (u / u_t) ** (1.0 / n_rz)) for u in (0.02, 0.03, 0.04)]


class FluidisedBedRows(unittest.TestCase):
    def rows(self, plateau_ratio):
        with tempfile.TemporaryDirectory() as d:
            umf = synthetic_run(d, plateau_ratio)
            return umf, fluidised_bed.rows(d)

    def test_known_answers(self):
        umf, r = self.rows(1.0)
        self.assertAlmostEqual(r["eps_mf"], EPS_MF, places=9)
        # the fit meets the plateau at Ergun's U_mf (to the schedule's 0.2 mm/s sampling)
        self.assertAlmostEqual(r["U_mf"] / umf, 1.0, delta=1e-6)
        self.assertAlmostEqual(r["U_mf_ergun"] / umf, 1.0, delta=1e-6)
        self.assertAlmostEqual(r["plateau"] / W, 1.0, delta=1e-12)
        for U, eps, dp, law, ergun in r["branch"]:
            self.assertAlmostEqual(dp / ergun, 1.0, delta=1e-9)
        self.assertGreater(len(r["expansion"]), 5)
        self.assertFalse(r["expansion_held"])  # a ramp: its rising rows
        for U, eps, lo, hi, drift, law in r["expansion"]:
            self.assertTrue(lo <= eps <= hi, f"U {U}: eps {eps} outside {lo}-{hi}")
            self.assertTrue(math.isnan(drift))
            self.assertAlmostEqual(law, drag_laws.expanded_voidage("di_felice", D, RHO_P, RHO_F, MU, U, G),
                                   delta=1e-12)

    def test_plateau_short_of_the_weight_reads_so(self):
        umf, r = self.rows(0.97)
        self.assertAlmostEqual(r["plateau"] / r["weight"], 0.97, delta=1e-12)
        # the construction meets the bed's weight, not the plateau read: U_mf is unmoved
        self.assertAlmostEqual(r["U_mf"] / umf, 1.0, delta=1e-6)

    def test_held_steps_read_the_settled_bed(self):
        with tempfile.TemporaryDirectory() as d:
            settled = stepped_run(d, 1.0)
            r = fluidised_bed.rows(d)
        self.assertTrue(r["expansion_held"])
        held = [(U, eps) for U, eps, _, _, _, _ in r["expansion"]]
        expected = [(u, e) for u, e in settled if fluidisation.EXPANDED[0] * r["U_mf"] <= u]
        self.assertEqual([U for U, _ in held], [u for u, _ in expected])
        self.assertGreaterEqual(len(held), 2)
        for (U, eps), (_, e) in zip(held, expected):  # second half: within exp(-5) of settled
            self.assertAlmostEqual(eps, e, delta=0.01 * e)
        for _, _, _, _, drift, _ in r["expansion"]:
            self.assertLess(abs(drift), 0.01)
        with tempfile.TemporaryDirectory() as d:  # holds shorter than MIN_HOLD: the ramp's rows
            stepped_run(d, 0.3)
            self.assertFalse(fluidised_bed.rows(d)["expansion_held"])

    def test_wen_yu(self):  # 1 mm glass in water: Re_mf = sqrt(33.7^2 + 0.0408 Ar) - 33.7
        ar = D ** 3 * RHO_F * (RHO_P - RHO_F) * G / MU ** 2
        re = math.sqrt(33.7 ** 2 + 0.0408 * ar) - 33.7
        _, r = self.rows(1.0)
        self.assertAlmostEqual(r["U_mf_wen_yu"], re * MU / (RHO_F * D), places=12)


if __name__ == "__main__":
    unittest.main()
