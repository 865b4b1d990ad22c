"""A run stopped by SIGTERM and resumed leaves the same in-situ data and VTK output as
the run that was never stopped; a watchdog stop leaves a dump that opens in ParaView.

The scene is tests/restart/scene.yaml, shortened, with every pipeline, VTK snapshots and
checkpoints. Run A goes through; run B gets SIGTERM once its second checkpoint exists,
then `sphdem resume`. Compared byte for byte: log.csv, insitu/interfaces.csv and com.csv,
the datasets of insitu/voidage_height.h5, vtk/*.pvd and every .vtp, the snapshot names.
Run by ctest (label insitu) with SPHDEM_BIN set, or by hand:
    SPHDEM_BIN=build/app/sphdem /usr/bin/python3 -m unittest discover -s tests/insitu -p test_resume.py
"""

import glob
import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest

import h5py

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", ".."))
SCENE = os.path.join(REPO, "tests", "restart", "scene.yaml")
SPHDEM = os.environ.get("SPHDEM_BIN", os.path.join(REPO, "build", "app", "sphdem"))
SETS = ["time.end=0.006", "insitu.every=0.0005", "insitu.snapshot_every=3",
        "output.vtk.every=0.001", "checkpoint.every=0.001"]


def sphdem(*args, **kw):
    cmd = [SPHDEM, *args]
    env = dict(os.environ)
    env.pop("DISPLAY", None)  # sphdem starts its own Xvfb
    return subprocess.Popen(cmd, stdout=kw.get("out"), stderr=subprocess.STDOUT, env=env)


def run_args(out):
    args = ["run", SCENE, "--out", out]
    for s in SETS:
        args += ["--set", s]
    return args


class ResumeContinuesTheInSituData(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="sphdem_resume_")
        cls.a = os.path.join(cls.tmp, "a")
        cls.b = os.path.join(cls.tmp, "b")
        with open(os.path.join(cls.tmp, "a.out"), "w") as out:
            cls.code_a = sphdem(*run_args(cls.a), out=out).wait()
        with open(os.path.join(cls.tmp, "b.out"), "w") as out:
            p = sphdem(*run_args(cls.b), out=out)
            t0 = time.time()
            # the first checkpoint, then the stop: it is written at the next re-sort (every
            # 100 steps), before the run's end
            while len(glob.glob(os.path.join(cls.b, "checkpoints", "ckpt_*.h5"))) < 1 and p.poll() is None:
                if time.time() - t0 > 600:
                    break
                time.sleep(0.05)
            p.send_signal(signal.SIGTERM)
            cls.code_b_stop = p.wait()
            cls.code_b = sphdem("resume", cls.b, out=out).wait()
        with open(os.path.join(cls.tmp, "b.out")) as f:
            cls.out_b = f.read()

    @classmethod
    def tearDownClass(cls):
        if os.environ.get("SPHDEM_KEEP_OUTPUT"):
            print("run directories kept in", cls.tmp)
        else:
            shutil.rmtree(cls.tmp, ignore_errors=True)

    def same_bytes(self, rel):
        with open(os.path.join(self.a, rel), "rb") as f:
            a = f.read()
        with open(os.path.join(self.b, rel), "rb") as f:
            b = f.read()
        self.assertEqual(a, b, rel + " differs between the uninterrupted and the resumed run")
        return a

    def test_the_stop_and_the_resume(self):
        self.assertEqual(self.code_a, 0)
        self.assertEqual(self.code_b_stop, 128 + signal.SIGTERM, self.out_b[-2000:])
        self.assertIn("Continue with: sphdem resume " + self.b, self.out_b)
        self.assertIn("sphdem: resuming from", self.out_b)
        self.assertEqual(self.code_b, 0, self.out_b[-2000:])

    def test_log_and_reduced_data_continue_without_gaps_or_repeats(self):
        for rel in ("log.csv", "insitu/interfaces.csv", "insitu/com.csv"):
            text = self.same_bytes(rel).decode()
            times = [float(r.split(",")[0]) for r in text.splitlines()[1:]]
            self.assertEqual(times, sorted(set(times)), rel + ": repeated or unordered rows")
        with h5py.File(os.path.join(self.a, "insitu", "voidage_height.h5")) as ha, \
                h5py.File(os.path.join(self.b, "insitu", "voidage_height.h5")) as hb:
            self.assertEqual(sorted(ha.keys()), sorted(hb.keys()))
            for k in ha:
                self.assertEqual(ha[k][()].tobytes(), hb[k][()].tobytes(), "voidage_height.h5 " + k)
            self.assertEqual(len(ha["time"]), 13)  # t = 0 and every 0.5 ms to 6 ms

    def test_vtk_collections_and_snapshots_continue(self):
        for rel in ("vtk/fluid.pvd", "vtk/particles.pvd"):
            self.same_bytes(rel)
        names = sorted(os.path.basename(p) for p in glob.glob(os.path.join(self.a, "vtk", "*.vtp")))
        self.assertEqual(names, sorted(os.path.basename(p) for p in glob.glob(os.path.join(self.b, "vtk", "*.vtp"))))
        for n in names:
            self.same_bytes(os.path.join("vtk", n))
        snaps = lambda d: sorted(os.path.basename(p) for p in glob.glob(os.path.join(d, "insitu", "snapshots", "*.png")))
        self.assertEqual(snaps(self.a), snaps(self.b))
        self.assertGreaterEqual(len(snaps(self.a)), 4)


class WatchdogDumpOpensInParaView(unittest.TestCase):
    def test_a_sphere_thrown_out_of_the_box(self):
        tmp = tempfile.mkdtemp(prefix="sphdem_watchdog_")
        try:
            scene = os.path.join(tmp, "thrown.yaml")
            with open(scene, "w") as f:
                f.write("name: thrown\ndomain: {size: [0.0016, 0.0016, 0.01]}\nfluid: {enabled: false}\n"
                        "species: [{name: glass, diameter: 1.0e-4, density: 2500}]\n"
                        "particles:\n  - {type: lattice, species: glass, min: [0, 0, 0], "
                        "max: [0.0016, 0.0016, 0.0001001], voidage: 0.4765, velocity: [0, 0, 0.08]}\n"
                        "gravity: [0, 0, 0]\ncontact: {stiffness: 0.1}\ntime: {end: 0.2}\n"
                        "checkpoint: {every: 0.0005}\ninsitu: {enabled: false}\n")
            out = os.path.join(tmp, "run")
            p = subprocess.run([SPHDEM, "run", scene, "--out", out], capture_output=True, text=True)
            self.assertEqual(p.returncode, 1, p.stderr[-2000:])
            self.assertIn("watchdog at step", p.stderr)
            self.assertIn("left the domain", p.stderr)
            self.assertIn("the last good checkpoint is", p.stderr)
            dumps = glob.glob(os.path.join(out, "watchdog", "step_*.vtp"))
            self.assertEqual(len(dumps), 1)
            script = os.path.join(tmp, "read.py")
            with open(script, "w") as f:
                f.write("import sys\nfrom paraview.simple import XMLPolyDataReader\n"
                        "from paraview import servermanager as sm\n"
                        "r = XMLPolyDataReader(FileName=[sys.argv[1]])\nr.UpdatePipeline()\n"
                        "d = sm.Fetch(r)\npd = d.GetPointData()\nc = pd.GetArray('culprit')\n"
                        "print('points', d.GetNumberOfPoints(), 'culprits',"
                        " sum(c.GetValue(i) for i in range(c.GetNumberOfTuples())))\n")
            r = subprocess.run(["pvpython", script, dumps[0]], capture_output=True, text=True)
            self.assertIn("points 256 culprits 1", r.stdout, r.stdout + r.stderr)
        finally:
            shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    unittest.main()
