"""validation/report.py (its package vreport/: runs.py, rows.py): a run is reused only when
the solver, the scene file and the in-situ scripts are the ones it was made with; the
safeguard line a run prints at its end is read and marks the rows of that run; --strict
turns a missed target into a failing exit; a missed target is a MISS only with its evidence
among the report's rows; the summary counts the rows' kinds apart.

A stand-in `sphdem` (a script that writes a log.csv, prints the safeguard line and counts
its calls) takes the solver's place, so this runs in a second."""
import os
import shutil
import stat
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "validation"))
from vreport import runs  # noqa: E402
from vreport.rows import (Row, exit_status, mark_safeguard_hits, safeguard_rows, settle_misses,  # noqa: E402
                          summary_line)

FAKE = """#!/bin/sh
# stand-in sphdem: run CASE --out DIR ...
out="$4"
mkdir -p "$out"
echo x >> "{calls}"
printf 'time,step,voidage_clamped,omega_bounded,max_density_error\\n0,0,0,0,0.001\\n0.1,10,{floor},0,0.002\\n' > "$out/log.csv"
echo "sphdem: safeguards over 10 steps: voidage floor hit in {floor} steps (largest {floor} particles, 1 % of particle-steps), Omega clamp hit in 0 steps (largest 0 particles, 0 % of particle-steps)"
"""


class Reuse(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, self.tmp)
        self.repo = os.path.join(self.tmp, "repo")
        os.makedirs(os.path.join(self.repo, "cases"))
        self.case = os.path.join(self.repo, "cases", "scene.yaml")
        open(self.case, "w").write("name: scene\n")
        self.calls = os.path.join(self.tmp, "calls")
        self.sphdem = os.path.join(self.tmp, "sphdem")
        self.write_solver(floor=0)
        self.old_repo, runs.REPO = runs.REPO, self.repo
        self.addCleanup(setattr, runs, "REPO", self.old_repo)
        self.run_ = runs.Run("scene_run", "cases/scene.yaml", {"time.end": 0.1})
        self.runs_dir = os.path.join(self.tmp, "runs")

    def write_solver(self, floor, comment=""):
        open(self.sphdem, "w").write(FAKE.format(calls=self.calls, floor=floor) + comment)
        os.chmod(self.sphdem, os.stat(self.sphdem).st_mode | stat.S_IXUSR)

    def calls_made(self):
        return len(open(self.calls).read().split()) if os.path.exists(self.calls) else 0

    def execute(self):
        return runs.execute(self.run_, self.sphdem, self.runs_dir, reuse=True, nice=0)

    def test_same_solver_and_scene_reuse(self):
        self.execute()
        self.execute()
        self.assertEqual(self.calls_made(), 1)

    def test_changed_solver_runs_again(self):
        self.execute()
        self.write_solver(floor=0, comment="# rebuilt\n")
        self.execute()
        self.assertEqual(self.calls_made(), 2)

    def test_changed_scene_runs_again(self):
        self.execute()
        open(self.case, "a").write("# edited\n")
        self.execute()
        self.assertEqual(self.calls_made(), 2)

    def test_record_without_solver_hash_runs_again(self):
        import json
        r = self.execute()
        stamp = os.path.join(r.dir, "report_run.json")
        meta = json.load(open(stamp))
        del meta["solver_sha256"]
        json.dump(meta, open(stamp, "w"))
        self.execute()
        self.assertEqual(self.calls_made(), 2)

    def test_in_situ_run_again_when_a_script_it_runs_changed(self):
        # an in-situ run depends on its pipelines and the modules they import, not others
        pipes = os.path.join(self.repo, "pipelines")
        os.makedirs(pipes)
        for name, text in (("interfaces", "import helper\n"), ("helper", "x = 1\n"), ("com_tracks", "y = 2\n")):
            open(os.path.join(pipes, name + ".py"), "w").write(text)
        self.run_ = runs.Run("scene_insitu", "cases/scene.yaml", {"insitu.pipelines": "[interfaces]"}, insitu=True)
        self.execute()
        open(os.path.join(pipes, "com_tracks.py"), "a").write("# not run by this scene\n")
        self.execute()
        self.assertEqual(self.calls_made(), 1)
        open(os.path.join(pipes, "helper.py"), "a").write("# imported by interfaces\n")
        self.execute()
        self.assertEqual(self.calls_made(), 2)

    def test_safeguard_line_read_and_rows_marked(self):
        self.write_solver(floor=3)
        r = self.execute()
        self.assertEqual(r.safeguards["floor_steps"], 3)
        self.assertEqual(r.safeguards["steps"], 10)
        rows = [Row("scene", "slip", "1", "src", "1", 0.0, 0.01, r, kind="comparison", reference_kind="independent")]
        rows += safeguard_rows("scene", {"k": r})
        mark_safeguard_hits(rows)
        self.assertIn("voidage floor in 3", rows[0].note)
        floor_row = [x for x in rows if "Ω clamp" in x.quantity][0]
        self.assertEqual(floor_row.status, "FAIL")       # target 0
        self.assertNotIn("voidage floor in", floor_row.note)

    def test_quiet_run_leaves_rows_alone(self):
        r = self.execute()
        rows = [Row("scene", "slip", "1", "src", "1", 0.0, 0.01, r, kind="comparison", reference_kind="independent")]
        mark_safeguard_hits(rows)
        self.assertEqual(rows[0].note, "")


class RunDir(unittest.TestCase):
    """--run-dir KEY=DIR takes a run made by hand: finished when its log reaches the scene's
    time.end, stopped before it otherwise; another scene's directory is refused."""

    def setUp(self):
        self.tmp = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, self.tmp)
        os.makedirs(os.path.join(self.tmp, "cases"))
        open(os.path.join(self.tmp, "cases", "scene.yaml"), "w").write("name: scene\n")
        self.old_repo, runs.REPO = runs.REPO, self.tmp
        self.addCleanup(setattr, runs, "REPO", self.old_repo)
        self.run_ = runs.Run("scene_long", "cases/scene.yaml", {}, long=True)

    def made(self, name, reached, end=1.0):
        d = tempfile.mkdtemp(dir=self.tmp)
        open(os.path.join(d, "case.yaml"), "w").write(f"name: {name}\ntime: {{end: {end}}}\n")
        open(os.path.join(d, "log.csv"), "w").write(f"time,step\n0,0\n{reached},10\n")
        return d

    def test_finished_and_stopped(self):
        self.assertTrue(runs.adopt(self.run_, self.made("scene", 1.0)).ok)
        stopped = runs.adopt(self.run_, self.made("scene", 0.4))
        self.assertFalse(stopped.ok)
        self.assertEqual(stopped.log["time"][-1], 0.4)

    def test_other_scene_refused(self):
        with self.assertRaises(SystemExit) as e:
            runs.adopt(self.run_, self.made("other", 1.0))
        self.assertIn("its scene is 'other'", str(e.exception))


class Strict(unittest.TestCase):
    def rows(self, *statuses):
        out = []
        for s in statuses:
            r = Row("scene", "q", "1", "src", "1", 0.0, 0.01, kind="comparison", reference_kind="own-closure")
            r.status = s
            out.append(r)
        return out

    def test_miss_fails_only_when_strict(self):
        rows = self.rows("PASS", "MISS", "INFO")
        self.assertEqual(exit_status(rows, strict=False), 0)
        self.assertEqual(exit_status(rows, strict=True), 1)
        self.assertEqual(exit_status(self.rows("PASS", "FAIL"), strict=False), 1)
        self.assertEqual(summary_line(rows), "3 rows: comparisons with an independent reference 0 (0 pass, 0 fail, "
                                             "0 miss, 0 informative), with the solver's own closure 3 (1 pass, 0 fail, "
                                             "1 miss, 1 informative); health checks 0 (0 pass, 0 fail, 0 miss, 0 "
                                             "informative); theory.py's self-checks 0 (0 pass, 0 fail, 0 miss, 0 "
                                             "informative); 0 skipped")


class Miss(unittest.TestCase):
    """A target missed for a known reason is a MISS only when rows of the same report measure
    it; the kinds are declared and counted apart."""

    def row(self, error, target, **kw):
        return Row("scene", "q", "1", "src", "1", error, target, kind="comparison", reference_kind="own-closure", **kw)

    def test_miss_needs_evidence_in_the_same_report(self):
        shown = self.row(0.01, None)
        miss = self.row(0.08, 0.04, known="the faces", evidence=[shown])
        elsewhere = self.row(0.08, 0.04, known="the faces", evidence=[self.row(0.01, None)])
        none = self.row(0.08, 0.04, known="the faces", evidence=[])
        rows = [miss, shown, elsewhere, none]
        settle_misses(rows)
        self.assertEqual([r.status for r in rows], ["MISS", "INFO", "FAIL", "FAIL"])
        self.assertIn("target missed: the faces; shown by", miss.note)
        self.assertIn("no row of this report shows it", none.note)

    def test_known_without_evidence_and_undeclared_kinds_refused(self):
        with self.assertRaises(ValueError):
            self.row(0.08, 0.04, known="a sentence")
        with self.assertRaises(ValueError):
            Row("scene", "q", "1", "src", "1", 0.0, 0.01, kind="comparison")
        with self.assertRaises(ValueError):
            Row("scene", "q", "1", "src", "1", 0.0, 0.01, kind="health", reference_kind="independent")

    def test_summary_counts_kinds_apart(self):
        rows = [self.row(0.0, 0.01), Row("s", "q", "1", "src", "1", 0.0, 0.0, kind="health", count=True),
                Row("s", "q", "1", "src", "1", 0.0, 1e-9, kind="self-check"),
                Row("s", "q", "1", "src", "1", 0.0, 0.01, kind="comparison", reference_kind="independent",
                    skip="not run")]
        self.assertEqual([r.kind_label() for r in rows], ["cmp·own", "health", "self", "cmp·ind"])
        line = summary_line(rows, matrix=[(None, [], "PART"), (None, [], "PASS")])
        self.assertIn("with the solver's own closure 1 (1 pass", line)
        self.assertIn("health checks 1 (1 pass", line)
        self.assertIn("theory.py's self-checks 1 (1 pass", line)
        self.assertIn("independent reference 0 (", line)
        self.assertTrue(line.endswith("1 skipped; regime matrix: 1 of 2 PART"))


if __name__ == "__main__":
    unittest.main()
