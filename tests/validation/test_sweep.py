"""validation/sweep.py: a two-point sweep of the single sphere, and the Pareto front.

The sweep varies the spheres' kernel width (coupling.sphere_kernel_scale 1 and 2) over
the first 2 ms of the single-particle scene: the evaluator's rows must come out for both
points with the parameters in their columns, the two points' slip errors must differ
(the width moves the drag: a sweep that ignored --vary would give equal rows), and the
stability columns must be read from each run's log and its end-of-run safeguard line.
"""
import csv
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "validation"))
import sweep  # noqa: E402


class ParetoFront(unittest.TestCase):
    def test_front_keeps_points_no_other_beats(self):
        # (wall, score): (2, 5) is beaten by (1, 4); (3, 1) and (1, 4) and (5, 0.5) stay
        points = [(1.0, 4.0), (2.0, 5.0), (3.0, 1.0), (5.0, 0.5), (6.0, 0.5)]
        self.assertEqual(sweep.pareto_front(points), [0, 2, 3])

    def test_vary_keeps_bracketed_lists(self):
        self.assertEqual(sweep.parse_vary("a.b=1,[2, 3],x"), ("a.b", ["1", "[2, 3]", "x"]))


class SweepOfTheSingleSphere(unittest.TestCase):
    def test_two_widths(self):
        build = os.environ["SPHDEM_BUILD"]
        with tempfile.TemporaryDirectory() as out:
            p = subprocess.run(
                [sys.executable, os.path.join(REPO, "validation", "sweep.py"), "single_particle",
                 "--vary", "coupling.sphere_kernel_scale=1,2", "--set", "time.end=0.002",
                 "--build", build, "--out", out],
                capture_output=True, text=True, timeout=600)
            self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
            self.assertTrue(os.path.getsize(os.path.join(out, "pareto.png")) > 0)
            rows = list(csv.DictReader(open(os.path.join(out, "sweep.csv"))))
            points = sorted({r["point"] for r in rows})
            self.assertEqual(points, ["p000", "p001"])
            slip = {r["coupling.sphere_kernel_scale"]: float(r["error"]) for r in rows
                    if r["quantity"].startswith("superficial slip")}
            self.assertEqual(sorted(slip), ["1", "2"])
            self.assertNotAlmostEqual(slip["1"], slip["2"], delta=1e-4)
            for r in rows:
                self.assertGreater(int(r["steps"]), 0)
                self.assertGreater(float(r["wall_s"]), 0.0)
                self.assertLess(float(r["max_density_error"]), 0.05)
                # the run's own count over every step (its end-of-run line): one sphere in
                # clear water never reaches the voidage floor nor the Omega clamp
                self.assertEqual(r["voidage_floor_steps"], "0")
                self.assertEqual(r["omega_clamp_steps"], "0")
                self.assertEqual(r["scene"], "single_particle")


if __name__ == "__main__":
    unittest.main()
