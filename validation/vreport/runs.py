"""Runs and their outputs: Run (one `sphdem run`: a case file, its --set overrides, with or
without in-situ analysis) and RunResult (what the run wrote: log.csv, the resolved
case.yaml, insitu/interfaces.csv, the safeguard line of sphdem.out); the readers of a run's
files; `execute`, which makes a run or, with --reuse, takes it from its directory when the
solver, the scene file, the in-situ scripts and the command are the ones it was made with
(the reuse rule), or resumes a stopped one from its checkpoints; and `adopt`, a run made by
hand (--run-dir KEY=DIR)."""
import csv
import glob
import hashlib
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import time

import numpy as np
import yaml

import theory

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))   # validation/
REPO = os.path.dirname(HERE)


class Run:
    """One `sphdem run`: a case file, --set overrides, with or without in-situ analysis."""

    def __init__(self, key, case, sets, insitu=False, long=False):
        self.key, self.case, self.sets, self.insitu = key, case, dict(sets), insitu
        self.long = long   # hours: made only with --long (resumable from its checkpoints)
        if insitu:
            # only the reduced data the report reads: no rendering, so no Xvfb needed
            self.sets.setdefault("insitu.pipelines", "[voidage_height, interfaces]")

    def case_path(self):
        return os.path.join(REPO, self.case)

    def command(self, sphdem, out_dir):
        cmd = [sphdem, "run", self.case_path(), "--out", out_dir]
        for k, v in self.sets.items():
            cmd += ["--set", f"{k}={v}"]
        if not self.insitu:
            cmd.append("--no-insitu")
        return cmd


class RunResult:
    def __init__(self, run, out_dir, wall, returncode, cmd):
        self.run, self.dir, self.wall, self.returncode, self.cmd = run, out_dir, wall, returncode, cmd
        self.ok = returncode == 0
        self.log = read_csv(os.path.join(out_dir, "log.csv"))
        case_path = os.path.join(out_dir, "case.yaml")
        self.case = yaml.safe_load(open(case_path)) if os.path.exists(case_path) else None
        self.interfaces = read_csv(os.path.join(out_dir, "insitu", "interfaces.csv"))
        self.safeguards = read_safeguards(os.path.join(out_dir, "sphdem.out"))

    # resolved scene numbers
    def species(self, i=0):
        return self.case["species"][i]

    def resolution(self):
        sp = self.species()
        dx = self.case["fluid"]["spacing"]
        if "diameter" in sp:
            return f"h/d = {dx / sp['diameter']:.3g} (dx = {dx * 1e6:.0f} µm)"
        law = sp["size_distribution"]   # a size law: h/d of the mean of its bounds
        d = 0.5 * (law["min"] + law["max"])
        return f"h/d_mean = {dx / d:.3g} (dx = {dx * 1e6:.0f} µm, d in [{law['min'] * 1e3:g}, {law['max'] * 1e3:g}] mm)"

    def hd(self):
        return self.case["fluid"]["spacing"] / self.species()["diameter"]

    def fluid(self):
        f = self.case["fluid"]
        return f["density"], f["viscosity"]

    def g(self):
        return abs(self.case["gravity"][2])

    def acoustic_period(self):
        f = self.case["fluid"]
        return theory.acoustic_period(f["fill_height"], f["sound_speed"])


def snapshot_arrays(run_dir):
    """The run's VTK snapshots as numpy arrays (validation/snapshots_npz.py, run with
    pvpython once per run: the system python has no VTK); None without snapshots."""
    vtk_dir = os.path.join(run_dir, "vtk")
    npz = os.path.join(vtk_dir, "snapshots.npz")
    pvd = os.path.join(vtk_dir, "particles.pvd")
    if not os.path.exists(pvd):
        return None
    script = os.path.join(HERE, "snapshots_npz.py")
    if not os.path.exists(npz) or os.path.getmtime(npz) < max(os.path.getmtime(pvd), os.path.getmtime(script)):
        pvpython = shutil.which("pvpython")
        if pvpython is None:
            return None
        subprocess.run([pvpython, script, run_dir], check=True)
    return np.load(npz)


def read_csv(path):
    """Columns of a CSV file as numpy arrays (None if the file is missing or empty)."""
    if not os.path.exists(path):
        return None
    with open(path) as fh:
        rows = list(csv.reader(fh))
    if len(rows) < 2:
        return None
    head, body = rows[0], rows[1:]
    return {h: np.array([float(r[i]) for r in body]) for i, h in enumerate(head)}


SAFEGUARD_LINE = re.compile(
    r"safeguards over (\d+) steps: voidage floor hit in (\d+) steps \(largest (\d+) particles, "
    r"([0-9.eE+-]+) % of particle-steps\), Omega clamp hit in (\d+) steps \(largest (\d+) particles, "
    r"([0-9.eE+-]+) % of particle-steps\)")


def read_safeguards(path):
    """The run's own count of its safeguards over every step (the line `sphdem run` prints at
    its end, solver/run/safeguard_tally.hpp), or None for a run that did not finish."""
    if not os.path.exists(path):
        return None
    m = None
    for line in open(path, errors="replace"):
        m = SAFEGUARD_LINE.search(line) or m
    if m is None:
        return None
    g = m.groups()
    return {"steps": int(g[0]), "floor_steps": int(g[1]), "floor_largest": int(g[2]),
            "floor_share": float(g[3]), "clamp_steps": int(g[4]), "clamp_largest": int(g[5]),
            "clamp_share": float(g[6])}


def safeguards_hit(result):
    """'' for a run whose safeguards never bit, else what bit (for the rows that read it)."""
    sg = getattr(result, "safeguards", None)
    if not sg or (sg["floor_steps"] == 0 and sg["clamp_steps"] == 0):
        return ""
    return (f"its run hit the voidage floor in {sg['floor_steps']} and the Ω clamp in "
            f"{sg['clamp_steps']} of {sg['steps']} steps")


def solver_identity(sphdem):
    """What a reused run must share with this report: the sphdem executable's own bytes (it
    links the solver statically, so any change of the solver's code changes them), and, for
    the reader, the commit it was built at."""
    with open(sphdem, "rb") as fh:
        return hashlib.sha256(fh.read()).hexdigest()


def source_dir(build):
    """The source tree a build was configured from (its CMake cache), None if unknown."""
    cache = os.path.join(build, "CMakeCache.txt")
    if os.path.exists(cache):
        for line in open(cache):
            if line.startswith("sphdem_SOURCE_DIR:"):
                return line.split("=", 1)[1].strip()
    return None


def pipelines_identity(run, sphdem):
    """What a reused in-situ run must share with this report besides the solver: the
    in-situ scripts it executes (its insitu.pipelines, read from the solver's source tree,
    which is where sphdem loads them) and the modules of that folder they import; '' for a
    run without in situ."""
    if not run.insitu:
        return ""
    folder = os.path.join(source_dir(os.path.dirname(os.path.dirname(sphdem))) or REPO, "pipelines")
    todo = [n.strip() for n in str(run.sets["insitu.pipelines"]).strip("[]").split(",") if n.strip()]
    seen, digest = set(), hashlib.sha256()
    while todo:
        name = todo.pop(0)
        path = os.path.join(folder, name + ".py")
        if name in seen or not os.path.exists(path):
            continue
        seen.add(name)
        text = open(path, "rb").read()
        digest.update(name.encode() + b"\0" + text)
        todo += re.findall(r"^(?:from|import)\s+(\w+)", text.decode(), re.M)
    return digest.hexdigest()


def same_command(recorded, cmd):
    """Whether a recorded run was made with this command. The scene file is compared by its
    path inside the repository and, when the recorded one still exists, by its content, so
    that a git worktree can reuse the runs of another checkout of the same scenes."""
    if not recorded or len(recorded) != len(cmd):
        return False
    for a, b in zip(recorded, cmd):
        if a == b:
            continue
        rel = os.path.relpath(b, REPO) if os.path.isabs(b) else None
        if rel is None or rel.startswith("..") or not a.endswith(os.sep + rel):
            return False
        if os.path.exists(a) and os.path.exists(b) and open(a).read() != open(b).read():
            return False
    return True


def execute(run, sphdem, runs_dir, reuse, nice, env=None):
    """Make the run, or with `reuse` take it from its directory when it was made by the same
    solver, scene file, in-situ scripts and command; a run that was stopped before its end (its
    report_partial.json: the same four) continues from its newest
    checkpoint with `sphdem resume`, and its wall time is the parts' sum (a stopped part
    counts up to its last checkpoint, the work after it being redone)."""
    out_dir = os.path.join(runs_dir, run.key)
    cmd = run.command(sphdem, out_dir)
    stamp = os.path.join(out_dir, "report_run.json")
    partial = os.path.join(out_dir, "report_partial.json")
    case_sha = hashlib.sha256(open(run.case_path(), "rb").read()).hexdigest()
    solver_sha = solver_identity(sphdem)
    pipes_sha = pipelines_identity(run, sphdem)

    def same_run(meta):
        """reused (or resumed) only if the scene file (its hash), the solver (the
        executable's hash) and the in-situ scripts are the ones the run had; a record
        without any of them is run again"""
        return (meta.get("case_sha256") == case_sha and meta.get("solver_sha256") == solver_sha
                and meta.get("pipelines_sha256", None if pipes_sha else "") == pipes_sha
                and same_command(meta.get("cmd"), cmd))
    if reuse and os.path.exists(stamp):
        meta = json.load(open(stamp))
        if same_run(meta):
            print(f"[report] reuse {run.key} ({meta['wall']:.1f} s, commit {meta.get('commit', '?')})", flush=True)
            return RunResult(run, out_dir, meta["wall"], meta["returncode"], cmd)
        print(f"[report] not reusing {run.key}: "
              + ("the solver changed" if meta.get("solver_sha256") != solver_sha else
                 "the scene file changed" if meta.get("case_sha256") != case_sha else
                 "the in-situ scripts changed" if meta.get("pipelines_sha256", "") != pipes_sha else "another command"),
              flush=True)
    wall_before, checkpoints = 0.0, glob.glob(os.path.join(out_dir, "checkpoints", "ckpt_*.h5"))
    resume = False
    if reuse and os.path.exists(partial) and checkpoints:
        meta = json.load(open(partial))
        if same_run(meta):
            newest = max(os.path.getmtime(c) for c in checkpoints)
            wall_before = meta["wall_before"] + max(0.0, newest - meta["started"])
            resume = True
    os.makedirs(out_dir, exist_ok=True)
    identity = {"cmd": cmd, "case_sha256": case_sha, "solver_sha256": solver_sha, "pipelines_sha256": pipes_sha,
                "commit": sh(["git", "rev-parse", "--short", "HEAD"]) or "?"}
    json.dump(dict(identity, wall_before=wall_before, started=time.time()), open(partial, "w"))
    if resume:
        cmd_now = [sphdem, "resume", out_dir] + ([] if run.insitu else ["--no-insitu"])
        print(f"[report] resume {run.key} from its newest checkpoint ({wall_before:.0f} s before)", flush=True)
    else:
        cmd_now = cmd   # a fresh run: no older run's checkpoint may be resumed in its place
        shutil.rmtree(os.path.join(out_dir, "checkpoints"), ignore_errors=True)
        print(f"[report] run {run.key}: {' '.join(shlex.quote(c) for c in cmd)}", flush=True)
    full = (["nice", "-n", str(nice)] if nice else []) + cmd_now
    t0 = time.perf_counter()
    with open(os.path.join(out_dir, "sphdem.out"), "a" if resume else "w") as fh:
        rc = subprocess.call(full, stdout=fh, stderr=subprocess.STDOUT, env=env)
    wall = wall_before + time.perf_counter() - t0
    json.dump(dict(identity, wall=wall, returncode=rc, resumed=resume), open(stamp, "w"))
    os.remove(partial)
    print(f"[report]   {run.key}: exit {rc}, {wall:.1f} s", flush=True)
    return RunResult(run, out_dir, wall, rc, cmd)


def adopt(run, out_dir):
    """A run made by hand (`sphdem run CASE --out DIR`, resumed over several sittings), taken as
    run `run.key` (--run-dir KEY=DIR): its case.yaml must be the run's scene (by name); it counts as
    finished (exit 0) when its log reaches the scene's time.end, else as stopped (exit 1) with the
    rows of what it reached. Its wall time is the progress lines' (sphdem.out or RUN.md beside
    it are the record); the report adds 0 s."""
    case = yaml.safe_load(open(run.case_path()))
    if not os.path.exists(os.path.join(out_dir, "case.yaml")):
        sys.exit(f"report.py: --run-dir {run.key}={out_dir}: no case.yaml there (not a sphdem run directory)")
    result = RunResult(run, out_dir, 0.0, 1, ["(made by hand)", out_dir])
    theirs = result.case
    if theirs.get("name") != case.get("name"):
        sys.exit(f"report.py: --run-dir {run.key}={out_dir}: its scene is '{theirs.get('name')}', "
                 f"{run.key} runs '{case.get('name')}' ({run.case})")
    end = float(theirs["time"]["end"])
    log = result.log
    reached = float(log["time"][-1]) if log is not None and len(log["time"]) else 0.0
    result.returncode = 0 if reached >= end * (1 - 1e-9) else 1
    result.ok = result.returncode == 0
    print(f"[report] {run.key} from {out_dir}: t = {reached:.4g} of {end:g} s"
          + ("" if result.ok else " (stopped before its end)"), flush=True)
    return result


def sh(cmd):
    try:
        return subprocess.run(cmd, capture_output=True, text=True, cwd=REPO).stdout.strip()
    except OSError:
        return ""
