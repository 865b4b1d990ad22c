"""validation/vreport's convergence and seed tables (issue 38): the observed order and the
extrapolated error through three levels (scenes/convergence.py), and a scene's rows over
several seeds as mean ± sample standard deviation (scenes/seeds.py), on numbers made here."""
import math
import os
import sys
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "validation"))
from vreport.rows import Row  # noqa: E402
from vreport.runs import Run  # noqa: E402
from vreport.scenes.common import front_speed_with_beat  # noqa: E402
from vreport.scenes.convergence import Convergence, observed_order  # noqa: E402
from vreport.scenes.seeds import Seeds  # noqa: E402


class Level:
    """A stand-in RunResult (a level's third element is its run)."""
    case, wall = None, 0.0


class ObservedOrder(unittest.TestCase):
    H = (2e-4, 2e-4 / 1.5, 1e-4)

    def test_recovers_the_order_and_the_limit(self):
        for p in (1.0, 2.0, 3.3):
            e = [0.03 + 4e5 ** (p / 2) * h ** p * 1e-2 for h in self.H]
            self.assertAlmostEqual(observed_order(self.H, e), p, places=6)
            row = Convergence().order_row("x", [(h, x, Level()) for h, x in zip(self.H, e)])
            self.assertAlmostEqual(row.error, 0.03, places=9)   # e_inf
            self.assertEqual(row.status, "INFO")

    def test_oscillating_or_flat_levels_have_no_order(self):
        self.assertIsNone(observed_order(self.H, [0.03, 0.01, 0.02]))
        self.assertIsNone(observed_order(self.H, [0.03, 0.03, 0.02]))
        # the suspension's front, session 40: p = 0.21, not extrapolated (it would read +19.8 %)
        e = [0.0147, 0.0298, 0.0397]
        self.assertAlmostEqual(observed_order(self.H, e), 0.21, delta=0.03)
        row = Convergence().order_row("x", [(h, x, Level()) for h, x in zip(self.H, e)])
        self.assertIn("not in the asymptotic range", row.simulated)
        self.assertAlmostEqual(row.error, 0.0397)
        row = Convergence().order_row("x", [(h, x, Level()) for h, x in zip(self.H, [0.03, 0.01, 0.02])])
        self.assertIn("oscillatory or flat", row.simulated)
        self.assertAlmostEqual(row.error, 0.02)   # the finest level's

    def test_levels_hold_the_coupling_kernel(self):
        runs = {r.key: r.sets for r in Convergence().runs("full")}
        for prefix in ("conv_block", "conv_suspension"):
            for lv in (1.5, 2):
                s = runs[f"{prefix}_dx{lv:g}"]
                h = float(s["fluid.spacing"])
                self.assertAlmostEqual(h * s["coupling.sphere_kernel_scale"], 2e-4 * Convergence.BASE_SCALE[0])
                self.assertAlmostEqual(h * s["coupling.drag_kernel_scale"], 2e-4 * Convergence.BASE_SCALE[1])
            self.assertNotIn("coupling.sphere_kernel_scale", runs[f"{prefix}_dx1"])   # the defaults' choice
        self.assertEqual(Convergence().runs("reduced"), [])


class FrontWithBeat(unittest.TestCase):
    def test_the_lattice_beat_does_not_tilt_the_speed(self):
        dx, u, amp = 5e-4, 1.15e-3, 1.6e-5     # the untuned scene at eps0 0.7 (session 40)
        t = np.arange(0.2, 0.9, 0.002)        # 1.6 periods dx/u: a line alone tilts with the phase
        line = []
        for phase in (0.0, 1.6, 4.7):
            z = 9.7e-3 - u * t + amp * np.sin(2 * np.pi * u * t / dx + phase)
            got, a = front_speed_with_beat(t, z, dx)
            self.assertAlmostEqual(got / u, 1.0, places=6)
            self.assertAlmostEqual(a / amp, 1.0, places=4)
            line.append(abs(-np.polyfit(t, z, 1)[0] / u - 1))
        self.assertGreater(max(line), 0.01)   # what a line alone reads (1.2 % at most here)

    def test_a_window_under_one_period_is_the_line(self):
        t = np.linspace(0, 0.1, 50)
        got, a = front_speed_with_beat(t, 1e-3 - 2e-3 * t, 5e-4)
        self.assertAlmostEqual(got, 2e-3)
        self.assertTrue(math.isnan(a))


class FakeScene:
    """Runs once; its one comparison row's error is the run's number."""
    name = "fake"

    def runs(self, mode):
        return [Run("fake_run", os.path.join(REPO, "cases", "suspension_monodisperse.yaml"), {"time.end": 1})]

    def evaluate(self, results, ctx):
        r = results["fake_run"]
        return [Row(self.name, "front", "1", "ref", "x", r.value, 0.08, kind="comparison",
                    reference_kind="own-closure"),
                Row(self.name, "a counter", "0", "-", "0", 0.0, 0.0, kind="health", count=True)]


class Result:
    ok, log, case, wall = True, {}, None, 0.0

    def __init__(self, value):
        self.value = value


class SeedTable(unittest.TestCase):
    def test_mean_and_sample_spread_held_to_the_target_by_the_mean(self):
        s = Seeds([FakeScene()])
        runs = s.runs("full")
        self.assertEqual([r.sets["particles.0.seed"] for r in runs], [1, 2, 3, 4])   # the case's seed is 1
        values = [0.05, 0.07, 0.09, 0.11]
        rows = s.evaluate({r.key: Result(v) for r, v in zip(runs, values)}, None)
        self.assertEqual(len(rows), 1)   # the comparison only
        self.assertAlmostEqual(rows[0].error, 0.08)
        self.assertIn(f"± {100 * math.sqrt(sum((v - 0.08) ** 2 for v in values) / 3):.2f}", rows[0].simulated)
        self.assertEqual(rows[0].status, "PASS")   # the mean meets 8 % though one seed does not
        self.assertIn("+11.00", rows[0].note)
        self.assertEqual(s.runs("reduced"), [])


if __name__ == "__main__":
    unittest.main()
