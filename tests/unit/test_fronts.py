"""pipelines/fronts.py: the suspension front read from the spheres (ctest fronts_tool)."""
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "pipelines"))
from fronts import FINE, front_height, layer_profile, layer_volumes  # noqa: E402

NB, DZ = 60, 1e-4   # com_tracks' front layers over a 6 mm box


def fine_profile(z, vol):
    """What com_tracks reads a species' front from: the fine deposit's running mean."""
    return layer_profile(layer_volumes(z, vol, np.zeros(z.size, int), 1, 0.0, DZ / FINE, NB * FINE)[0]), DZ / FINE


def in_its_layer(z, vol):
    """The deposit the pipeline used before: each sphere's volume whole to its dz layer."""
    return np.bincount(np.clip((z / DZ).astype(int), 0, NB - 1), weights=vol, minlength=NB), DZ


def front_speeds(z0, profile, speed=2e-3, fall=DZ):
    """The spheres at z0 fall rigidly by `fall` in 16 steps at `speed` (their foot held at
    the floor): the front's speed by a line fit, relative to `speed`, minus one."""
    vol = np.ones(z0.size)
    f, dz = profile(z0, vol)
    c0 = np.median(f[f > 0])
    shifts = np.linspace(0.0, fall, 17)   # steps of 5/4 fine layers: not a grid shift
    zf = [front_height(profile(np.maximum(z0 - s, 0.5 * DZ), vol)[0], c0, 0.0, dz) for s in shifts]
    return -np.polyfit(shifts / speed, zf, 1)[0] / speed - 1


class Fronts(unittest.TestCase):
    def test_a_front_falling_one_layer_reads_its_speed(self):
        # 7000 spheres (one species of the two-density case) uniform to 3 mm, their top
        # sharp or spread over up to 2 layers, starting at 8 phases of a layer: a line fit
        # over a fall of one layer reads the speed within 0.5 %; read on the dz layers
        # themselves (the discriminating row) the same fits are off by up to ~15 %
        rng = np.random.default_rng(7)
        worst_fine, worst_layers = 0.0, 0.0
        for spread in (0.0, 1.0, 2.0):
            for phase in np.arange(8) / 8:
                z0 = rng.uniform(0.0, 3e-3, 7000) + DZ * (phase + spread * rng.uniform(-0.5, 0.5, 7000))
                worst_fine = max(worst_fine, abs(front_speeds(z0, fine_profile)))
                worst_layers = max(worst_layers, abs(front_speeds(z0, in_its_layer)))
        self.assertLess(worst_fine, 0.005)
        self.assertGreater(worst_layers, 0.05)

    def test_the_profile_is_the_solid_fraction_away_from_the_front(self):
        # 40000 spheres uniform to 3 mm: the running mean reads the mean fraction inside
        # (the count per dz layer, 1333, has a 2.7 % spread) and zero above
        rng = np.random.default_rng(3)
        f, dz = fine_profile(rng.uniform(0.0, 3e-3, 40000), np.ones(40000))
        z = (np.arange(f.size) + 0.5) * dz
        inside = f[(z > 5 * DZ) & (z < 25 * DZ)] * FINE
        self.assertLess(abs(np.mean(inside) / (40000 / 30) - 1), 0.01)
        self.assertEqual(np.max(f[z > 3e-3 + DZ]), 0.0)

    def test_each_species_in_its_own_layers_and_no_volume_lost(self):
        # conservation check (holds for any split of a sphere between two layers): every
        # sphere's volume lands in its species' row; the splits themselves discriminate
        z = np.array([-1e-4, 0.0, 0.5 * DZ, 0.75 * DZ, 5.25 * DZ, (NB - 0.5) * DZ, NB * DZ + 1e-4])
        sp = np.array([0, 1, 0, 1, 0, 1, 0])
        v = layer_volumes(z, np.ones(z.size), sp, 2, 0.0, DZ, NB)
        self.assertEqual(v.shape, (2, NB))
        self.assertAlmostEqual(v[0].sum(), 4.0)
        self.assertAlmostEqual(v[1].sum(), 3.0)
        self.assertAlmostEqual(v[0, 0], 2.0)          # below the first centre, on it
        self.assertAlmostEqual(v[1, 0], 1.75)         # below it; a quarter layer above it
        self.assertAlmostEqual(v[1, 1], 0.25)
        self.assertAlmostEqual(v[0, 4], 0.25)
        self.assertAlmostEqual(v[0, 5], 0.75)
        self.assertAlmostEqual(v[0, NB - 1], 1.0)
        self.assertAlmostEqual(v[1, NB - 1], 1.0)

    def test_the_running_mean_keeps_the_volume_and_its_ends(self):
        # the mean over FINE fine layers: a constant stays constant to both ends (they are
        # reflected), one fine layer's volume spreads evenly over FINE of them
        self.assertTrue(np.allclose(layer_profile(np.full(100, 3.0)), 3.0))
        spike = np.zeros(100)
        spike[50] = 1.0
        p = layer_profile(spike)
        self.assertAlmostEqual(p.sum(), 1.0)
        self.assertEqual(np.count_nonzero(p), FINE)
        self.assertAlmostEqual(p.max(), 1.0 / FINE)


if __name__ == "__main__":
    unittest.main()
