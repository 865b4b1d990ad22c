"""Tests of pipelines/figures.py on a synthetic run directory.

Run from the repository root with Debian's interpreter:
    /usr/bin/python3 -m unittest discover -s tests/insitu -p 'test_figures.py'
"""

import contextlib
import io
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np
import h5py
import matplotlib.image as mpimg

PIPELINES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                         "pipelines")
sys.path.insert(0, os.path.abspath(PIPELINES))
import figures  # noqa: E402

SCRIPT = os.path.join(os.path.abspath(PIPELINES), "figures.py")

# Synthetic settling suspension (Kynch): a suspension of solids fraction PHI0 fills
# 0..H0; its upper interface falls at V; the sediment (solids fraction PHIS) grows
# from the bottom at V * PHI0 / (PHIS - PHI0) = 2 V by mass conservation, until the
# two interfaces meet at t = H0 / (3 V) = 1 s.
V = 5e-3          # m/s
H0 = 15e-3        # m
DOMAIN = 20e-3    # m
PHI0, PHIS = 0.4, 0.6
T_END = 1.3       # s


def synthetic_fields(nt=131, nz=80):
    t = np.linspace(0.0, T_END, nt)
    dz = DOMAIN / nz
    z = (np.arange(nz) + 0.5) * dz
    t_meet = H0 / (3 * V)
    z_top = np.where(t < t_meet, H0 - V * t, H0 * PHI0 / PHIS)
    z_bot = np.where(t < t_meet, 2 * V * t, H0 * PHI0 / PHIS)
    w = 0.4e-3  # interface width
    step_top = 0.5 * (1 - np.tanh((z[None, :] - z_top[:, None]) / w))  # 1 below top
    step_bot = 0.5 * (1 - np.tanh((z[None, :] - z_bot[:, None]) / w))  # 1 in sediment
    phi = PHI0 * step_top + (PHIS - PHI0) * step_bot
    rng = np.random.default_rng(1)
    eps = 1.0 - phi + 0.004 * rng.standard_normal(phi.shape)
    return t, z, eps, z_top, z_bot


def write_run(run_dir, nt=131, v_ref=V, name="synthetic"):
    """A run directory as the solver leaves it: case.yaml and insitu/ files."""
    insitu = os.path.join(run_dir, "insitu")
    os.makedirs(insitu, exist_ok=True)
    with open(os.path.join(run_dir, "case.yaml"), "w") as f:
        f.write("name: %s\ndescription: synthetic settling column\n"
                "domain:\n  size: [0.004, 0.004, 0.02]\n" % name)
    t, z, eps, z_top, z_bot = synthetic_fields(nt)
    with h5py.File(os.path.join(insitu, "voidage_height.h5"), "w") as f:
        f["time"] = t
        f["z"] = z
        f["voidage"] = eps
        if v_ref is not None:
            f.attrs["reference_interface_velocity"] = v_ref
        f.attrs["column_height"] = DOMAIN
    # Interfaces as a detector reports them: the top not found in the first samples,
    # no sediment at t = 0.
    zt = z_top + 1e-4 * np.sin(40 * t)
    zt[:3] = np.nan
    zb = z_bot.copy()
    zb[0] = np.nan
    with open(os.path.join(insitu, "interfaces.csv"), "w") as f:
        f.write("time,z_top,z_bottom\n")
        for row in zip(t, zt, zb):
            f.write(",".join("nan" if math.isnan(x) else "%.9g" % x for x in row) + "\n")
    # Two species: the large ones settle faster.
    c_large = 0.5 * H0 - (0.5 * H0 - 2.5e-3) * (1 - np.exp(-t / 0.3))
    c_small = 0.5 * H0 - (0.5 * H0 - 4.5e-3) * (1 - np.exp(-t / 0.6))
    c_all = 0.5 * (c_large + c_small)
    with open(os.path.join(insitu, "com.csv"), "w") as f:
        f.write("time,com_z:small,com_z:large,com_z:all\n")
        for row in zip(t, c_small, c_large, c_all):
            f.write(",".join("%.9g" % x for x in row) + "\n")
    return run_dir


def truncate_csv(path, keep_rows):
    with open(path) as f:
        lines = f.readlines()
    with open(path, "w") as f:
        f.writelines(lines[:1 + keep_rows])


def load_rgb(path):
    img = mpimg.imread(path)  # float RGBA in [0, 1] for PNG
    return img[..., :3]


def non_background_fraction(rgb):
    # Background = the most frequent colour (white figure face).
    q = np.round(rgb.reshape(-1, 3) * 255).astype(np.int32)
    keys = q[:, 0] * 65536 + q[:, 1] * 256 + q[:, 2]
    vals, counts = np.unique(keys, return_counts=True)
    bg = vals[np.argmax(counts)]
    return float(np.mean(keys != bg)), len(vals)


class FiguresTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="sphdem_figures_")
        self.run_dir = write_run(os.path.join(self.tmp, "run"))
        self.insitu = os.path.join(self.run_dir, "insitu")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def make(self):
        err = io.StringIO()
        with contextlib.redirect_stderr(err):
            paths = figures.make_figures(self.run_dir)
        return paths, err.getvalue()

    def names(self, paths):
        return sorted(os.path.basename(p) for p in paths)

    def test_full_run_writes_three_readable_figures(self):
        paths, err = self.make()
        self.assertEqual(err, "")
        self.assertEqual(self.names(paths), sorted(
            ["voidage_height_time.png", "interfaces.png", "com_tracks.png"]))
        for p in paths:
            self.assertTrue(os.path.isfile(p), p)
            self.assertEqual(os.path.dirname(p), os.path.join(self.run_dir, "figures"))
            rgb = load_rgb(p)
            frac, ncol = non_background_fraction(rgb)
            self.assertGreater(frac, 0.05, "%s looks blank" % p)
            # About 7 x 4.5 in at 120 dpi.
            self.assertGreater(rgb.shape[1], rgb.shape[0], p)
        rgb = load_rgb(os.path.join(self.run_dir, "figures", "voidage_height_time.png"))
        frac, ncol = non_background_fraction(rgb)
        self.assertGreater(frac, 0.4, "the map should fill most of the figure")
        self.assertGreater(ncol, 200, "the map should show many colours")

    def test_cli_exit_codes(self):
        r = subprocess.run([sys.executable, SCRIPT, self.run_dir],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(len(r.stdout.split()), 3)
        # No insitu/: a bad run directory.
        bad = os.path.join(self.tmp, "not_a_run")
        os.makedirs(bad)
        r = subprocess.run([sys.executable, SCRIPT, bad], capture_output=True, text=True)
        self.assertEqual(r.returncode, 2)
        self.assertIn("insitu", r.stderr)
        self.assertFalse(os.path.exists(os.path.join(bad, "figures")))
        r = subprocess.run([sys.executable, SCRIPT, os.path.join(self.tmp, "missing")],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 2)
        # insitu/ present but empty: nothing can be drawn.
        os.makedirs(os.path.join(bad, "insitu"))
        r = subprocess.run([sys.executable, SCRIPT, bad], capture_output=True, text=True)
        self.assertEqual(r.returncode, 1)
        self.assertEqual(r.stderr.count("skipped"), 3, r.stderr)

    def test_bad_dir_raises_in_api(self):
        with self.assertRaises(figures.BadRunDir):
            figures.make_figures(os.path.join(self.tmp, "missing"))

    def test_missing_h5(self):
        os.remove(os.path.join(self.insitu, "voidage_height.h5"))
        paths, err = self.make()
        self.assertEqual(self.names(paths), ["com_tracks.png", "interfaces.png"])
        self.assertIn("voidage_height_time.png", err)
        self.assertEqual(err.count("\n"), 1, err)

    def test_header_only_csv(self):
        truncate_csv(os.path.join(self.insitu, "interfaces.csv"), 0)
        truncate_csv(os.path.join(self.insitu, "com.csv"), 0)
        paths, err = self.make()
        # The map is still drawn (without interface lines).
        self.assertEqual(self.names(paths), ["voidage_height_time.png"])
        self.assertEqual(err.count("\n"), 2, err)
        self.assertIn("only a header", err)

    def test_empty_files(self):
        open(os.path.join(self.insitu, "com.csv"), "w").close()
        open(os.path.join(self.insitu, "voidage_height.h5"), "w").close()
        paths, err = self.make()
        self.assertEqual(self.names(paths), ["interfaces.png"])
        self.assertEqual(err.count("\n"), 2, err)

    def test_single_row_everywhere(self):
        write_run(self.run_dir, nt=1)
        truncate_csv(os.path.join(self.insitu, "interfaces.csv"), 1)
        truncate_csv(os.path.join(self.insitu, "com.csv"), 1)
        paths, err = self.make()
        self.assertEqual(paths, [])
        self.assertEqual(err.count("skipped"), 3, err)
        r = subprocess.run([sys.executable, SCRIPT, self.run_dir],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 1)

    def test_interrupted_mid_write(self):
        # A CSV line cut off half-way, and an h5 whose voidage has fewer rows than time.
        with open(os.path.join(self.insitu, "com.csv"), "a") as f:
            f.write("1.31,0.0071,0.00")
        with open(os.path.join(self.insitu, "interfaces.csv"), "a") as f:
            f.write("1.31,0.0")
        t, z, eps, _, _ = synthetic_fields(40)
        with h5py.File(os.path.join(self.insitu, "voidage_height.h5"), "w") as f:
            f["time"] = t
            f["z"] = z
            f["voidage"] = eps[:25]
            f.attrs["reference_interface_velocity"] = float("nan")
        paths, err = self.make()
        self.assertEqual(len(paths), 3, err)
        self.assertEqual(err, "")

    def test_corrupt_h5(self):
        with open(os.path.join(self.insitu, "voidage_height.h5"), "wb") as f:
            f.write(b"\x89HDF\r\n\x1a\n" + b"\0" * 100)
        paths, err = self.make()
        self.assertEqual(len(paths), 2)
        self.assertIn("cannot read", err)

    def test_all_nan_interfaces_and_no_reference(self):
        write_run(self.run_dir, v_ref=None)
        with open(os.path.join(self.insitu, "interfaces.csv"), "w") as f:
            f.write("time,z_top,z_bottom\n0,nan,nan\n0.1,nan,nan\n")
        paths, err = self.make()
        self.assertEqual(self.names(paths), ["com_tracks.png", "voidage_height_time.png"])
        self.assertIn("interfaces.png", err)

    def test_reference_velocity_attribute(self):
        vh = figures.read_voidage(os.path.join(self.insitu, "voidage_height.h5"))
        self.assertAlmostEqual(vh["v_ref"], V)
        self.assertEqual(figures._kynch_label(V), "Kynch: v = 5 mm/s")
        for v in (None, float("nan"), -1.0):
            write_run(self.run_dir, v_ref=v)
            vh = figures.read_voidage(os.path.join(self.insitu, "voidage_height.h5"))
            self.assertIsNone(vh["v_ref"], v)
            paths, err = self.make()
            self.assertEqual(len(paths), 3, err)

    def test_scene_name(self):
        self.assertEqual(figures.scene_name(self.run_dir), "synthetic")
        with open(os.path.join(self.run_dir, "case.yaml"), "w") as f:
            f.write('# comment\ndomain: {size: [1, 1, 1]}\nname: "quoted name"  # c\n')
        self.assertEqual(figures.scene_name(self.run_dir), "quoted name")
        os.remove(os.path.join(self.run_dir, "case.yaml"))
        self.assertEqual(figures.scene_name(self.run_dir), "run")

    def test_restart_duplicates_sorted(self):
        # A restart that rewrote some times: rows out of order and repeated.
        path = os.path.join(self.insitu, "interfaces.csv")
        with open(path, "w") as f:
            f.write("time,z_top,z_bottom\n0,0.015,nan\n0.2,0.014,0.002\n"
                    "0.1,0.0145,0.001\n0.2,0.0139,0.0021\n")
        d = figures.read_csv_columns(path)
        np.testing.assert_array_equal(d["time"], [0, 0.1, 0.2])
        np.testing.assert_array_equal(d["z_top"], [0.015, 0.0145, 0.0139])

    def write_log(self, bed_weight):
        # a bed that fluidises at U = 10 mm/s: the drop rises linearly to 100 Pa, holds, and
        # U falls back
        t = np.linspace(0.0, 4.0, 81)
        U = np.where(t < 2.0, 0.01 * t, 0.01 * (4.0 - t))
        dp = np.minimum(100.0, 1e4 * U)
        with open(os.path.join(self.run_dir, "log.csv"), "w") as f:
            f.write("time,step,superficial_velocity,pressure_drop,bed_height,bed_weight\n")
            for k in range(t.size):
                f.write("%.17g,%d,%.9g,%.9g,%.9g,%.9g\n" % (t[k], k, U[k], dp[k],
                                                          0.01 + 0.1 * max(0.0, U[k] - 0.01),
                                                          bed_weight))

    def test_a_bed_adds_its_fluidisation_curve_and_height(self):
        self.write_log(100.0)
        paths, err = self.make()
        self.assertEqual(err, "")
        self.assertEqual(self.names(paths), sorted(
            ["voidage_height_time.png", "interfaces.png", "com_tracks.png",
             "fluidisation_curve.png", "bed_height.png"]))
        for name in ("fluidisation_curve.png", "bed_height.png"):
            frac, _ = non_background_fraction(load_rgb(os.path.join(self.run_dir, "figures", name)))
            self.assertGreater(frac, 0.03, "%s looks blank" % name)

    def test_no_bed_no_fluidisation_figures(self):
        self.write_log(0.0)  # a suspension or a walled column: the columns are 0
        paths, err = self.make()
        self.assertEqual(err, "")
        self.assertNotIn("fluidisation_curve.png", self.names(paths))


if __name__ == "__main__":
    unittest.main()
