"""validation/vreport/scenes/sand_column.py: each size class's contact push is read from its
momentum balance in the snapshots (f_fluid,z / (m g) - 1 + (1/g) d(speed)/dt), the pushes
cancel over the mixture (a health row), and a class that misses Masliyah is a MISS only
when Masliyah with its measured push meets the speed; without a push in the fluid force the
same speeds stay a FAIL. Synthetic snapshots (snapshots.npz), no solver run."""
import os
import shutil
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "validation"))
import theory  # noqa: E402
from vreport.rows import settle_misses  # noqa: E402
from vreport.runs import Run, RunResult  # noqa: E402
from vreport.scenes.sand_column import SandColumn  # noqa: E402

CASE = """name: sand_column
domain: {size: [0.05, 0.05, 1.0]}
gravity: [0, 0, -9.81]
fluid: {density: 1000, viscosity: 1.0e-3, fill_height: 1.0, sound_speed: 44.3, spacing: 0.0055}
species:
  - {name: sand, size_distribution: {law: uniform, min: 0.0018, max: 0.0038}, density: 2650}
particles:
  - {type: random, species: sand, voidage: 0.89}
"""
PUSH = np.linspace(0.10, -0.03, 10)   # the contacts' downward push per class, of its weight


class SandPushes(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, self.dir)
        with open(os.path.join(self.dir, "case.yaml"), "w") as fh:
            fh.write(CASE)
        self.species, _ = theory.uniform_size_species(0.0018, 0.0038, 2650, 0.11)
        self.ds = np.array([d for d, _, _ in self.species])
        self.edges = np.linspace(self.ds[0] - 5e-6, self.ds[-1] + 5e-6, 11)

    def masliyah(self, push=None):
        return theory.masliyah_velocities(self.species, 1000, 1e-3, g=9.81, drag=theory.brown_lawler_drag,
                                          push=push)[0]

    def rows(self, push_in_force):
        """Grains falling at Masliyah's speed with PUSH; their fluid force carries the push
        (push_in_force) or not. Returns the speed rows, misses settled."""
        rng = np.random.default_rng(1)
        d = rng.uniform(0.0018, 0.0038, 2000)
        cls = np.clip(np.digitize(d, self.edges) - 1, 0, 9)
        w = self.masliyah([PUSH[min(9, int(np.digitize(x, self.edges)) - 1)] for x in self.ds])
        speed = np.interp(d, self.ds, w)
        m = 2650 * np.pi * d ** 3 / 6
        fz = m * 9.81 * (1 + (PUSH[cls] if push_in_force else 0.0))
        times = np.linspace(0.12, 0.3, 10)
        arrays = {"time": times}
        for k in range(len(times)):
            arrays.update({f"s{k}_z": np.full_like(d, 0.5), f"s{k}_vz": -speed, f"s{k}_d": d, f"s{k}_fz": fz,
                           f"s{k}_rho": np.full_like(d, 2650.0)})
        vtk = os.path.join(self.dir, "vtk")
        os.makedirs(vtk, exist_ok=True)
        with open(os.path.join(vtk, "particles.pvd"), "w") as fh:
            fh.write("<VTKFile/>\n")
        np.savez(os.path.join(vtk, "snapshots.npz"), **arrays)
        r = RunResult(Run("sand_column_1m", "cases/sand_column.yaml", {}), self.dir, 0.0, 0, [])
        rows = SandColumn().mixture_speed_rows(r, self.species, self.masliyah(), self.masliyah, 0.26, "Masliyah")
        settle_misses(rows)
        return rows

    def test_measured_pushes_explain_the_finest_class(self):
        rows = self.rows(push_in_force=True)
        cancel = [x for x in rows if x.quantity.startswith("the contacts' downward pushes")]
        self.assertEqual(len(cancel), 1)
        self.assertEqual(cancel[0].kind, "health")
        finest = [x for x in rows if x.quantity.startswith("same, size class 1 of 10") and "push" not in x.quantity]
        pushed = [x for x in rows if x.quantity.startswith("same, size class 1 of 10") and "push" in x.quantity]
        self.assertGreater(finest[0].error, 0.10)   # past Masliyah's 10 %
        self.assertLess(abs(pushed[0].error), 0.01)
        self.assertEqual(finest[0].status, "MISS")
        self.assertIn("push this class down with 10.0% of its weight", finest[0].note)

    def test_without_the_push_in_the_fluid_force_the_miss_is_a_fail(self):
        rows = self.rows(push_in_force=False)
        finest = [x for x in rows if x.quantity.startswith("same, size class 1 of 10") and "push" not in x.quantity]
        self.assertEqual(finest[0].status, "FAIL")


if __name__ == "__main__":
    unittest.main()
