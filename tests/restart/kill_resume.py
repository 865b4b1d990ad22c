#!/usr/bin/python3
"""Faults injected into a run, each survived with nothing lost (issue 16).

    kill_resume.py --sphdem BUILD/app/sphdem [--kills 5] [--seed 1] [--work DIR]

On tests/restart/scene.yaml (a small settling suspension with friction), against one
uninterrupted run:
  1. SIGKILL at random moments, `sphdem resume` after each (--kills times, then to the end);
  2. SIGTERM: a checkpoint, exit 143 and how to resume; then resume to the end;
  3. a full disk (a file-size limit below a checkpoint's size): the run stops with a clear
     error, the previous checkpoint stays whole; resumed without the limit;
  4. the newest checkpoint damaged (a flipped byte) and cut short: resume warns, takes the
     one before and goes on;
and each continued run must end with log.csv and the final checkpoint identical, bit for
bit, to the uninterrupted run's. Also: resuming a finished run says so; a --set that
would change the run's state is refused. Prints a line per fault and the totals.
The soak (tests/restart/README.md) is the same with more kills.
"""
import argparse
import os
import random
import resource
import shutil
import signal
import subprocess
import sys
import time

import h5py

print = __import__("functools").partial(print, flush=True)  # progress as it happens

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "scene.yaml")


def checkpoints(run):
    d = os.path.join(run, "checkpoints")
    if not os.path.isdir(d):
        return []
    return sorted(os.path.join(d, f) for f in os.listdir(d) if f.startswith("ckpt_") and f.endswith(".h5"))


def start(args, cmd, run, limit_bytes=None):
    def preexec():
        os.setsid()
        if limit_bytes:
            resource.setrlimit(resource.RLIMIT_FSIZE, (limit_bytes, limit_bytes))

    log = open(os.path.join(args.work, os.path.basename(run) + ".out"), "a")
    return subprocess.Popen([args.sphdem] + cmd, stdout=log, stderr=subprocess.STDOUT, preexec_fn=preexec)


def run_to_end(args, cmd, run, limit_bytes=None):
    p = start(args, cmd, run, limit_bytes)
    return p.wait()


def output(args, run):
    with open(os.path.join(args.work, os.path.basename(run) + ".out")) as f:
        return f.read()


def step_of(checkpoint):
    return int(os.path.basename(checkpoint)[5:-3])


def last_step(run):
    """The step of the last whole row of the run's log.csv (0 before there is one)."""
    try:
        with open(os.path.join(run, "log.csv"), "rb") as f:
            f.seek(0, os.SEEK_END)
            f.seek(max(0, f.tell() - 4096))
            rows = f.read().decode(errors="replace").split("\n")
        for row in reversed(rows[:-1]):  # the text after the last newline may be cut
            cols = row.split(",")
            if len(cols) > 2 and cols[1].isdigit():
                return int(cols[1])
    except OSError:
        pass
    return 0


def first_checkpoint_step(run):
    """The step of a run's first checkpoint: the first logged step past checkpoint.every,
    plus the up to 20 steps to the next rebuild of the lists (kills before it restart the
    run from scratch, which is not a resume)."""
    every = None
    with open(os.path.join(run, "case.yaml")) as f:
        section = ""
        for line in f:
            if not line.startswith(" "):
                section = line.split(":")[0]
            elif section == "checkpoint" and line.strip().startswith("every:"):
                every = float(line.split(":")[1])
    with open(os.path.join(run, "log.csv")) as f:
        next(f)
        for row in f:
            t, step = row.split(",")[:2]
            if float(t) >= every:
                return int(step) + 20
    return 1


def final_checkpoint(run):
    c = checkpoints(run)
    assert c, run + ": no checkpoint"
    return c[-1]


def same_state(a, b):
    """Every dataset of two checkpoints, byte for byte (the names that differ, if any)."""
    diff = []
    with h5py.File(a, "r") as fa, h5py.File(b, "r") as fb:
        names = []
        fa.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
        other = []
        fb.visititems(lambda n, o: other.append(n) if isinstance(o, h5py.Dataset) else None)
        if sorted(names) != sorted(other):
            return ["<the entries differ>"]
        for n in names:
            if fa[n][()].tobytes() != fb[n][()].tobytes():
                diff.append(n)
    return diff


def expect_identical(ref, run, what):
    with open(os.path.join(ref, "log.csv"), "rb") as f:
        log_ref = f.read()
    with open(os.path.join(run, "log.csv"), "rb") as f:
        log_run = f.read()
    if log_ref != log_run:
        sys.exit("FAIL %s: log.csv differs from the uninterrupted run's" % what)
    if os.path.basename(final_checkpoint(ref)) != os.path.basename(final_checkpoint(run)):
        sys.exit("FAIL %s: the final checkpoint is %s, not %s" % (what, final_checkpoint(run), final_checkpoint(ref)))
    diff = same_state(final_checkpoint(ref), final_checkpoint(run))
    if diff:
        sys.exit("FAIL %s: final state differs in %s" % (what, ", ".join(diff[:8])))
    print("  %s: log.csv (%d bytes) and the final state (%s) identical bit for bit" %
          (what, len(log_run), os.path.basename(final_checkpoint(run))))


def wait_for(pred, timeout, proc=None):
    t0 = time.time()
    while time.time() - t0 < timeout:
        if pred():
            return True
        if proc is not None and proc.poll() is not None:
            return pred()
        time.sleep(0.05)
    return False


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sphdem", required=True)
    ap.add_argument("--kills", type=int, default=5)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--work", default="restart_test")
    args = ap.parse_args()
    rng = random.Random(args.seed)
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    new = lambda run: ["run", SCENE, "--out", run, "--no-insitu"]
    resume = lambda run, *extra: ["resume", run, "--no-insitu", *extra]
    faults = 0

    # the uninterrupted run
    ref = os.path.join(args.work, "reference")
    t0 = time.time()
    if run_to_end(args, new(ref), ref) != 0:
        sys.exit("FAIL: the uninterrupted run failed:\n" + output(args, ref))
    wall = time.time() - t0
    print("uninterrupted run: %.1f s, %d checkpoints kept, final %s" %
          (wall, len(checkpoints(ref)), os.path.basename(final_checkpoint(ref))))

    # 1. SIGKILL at random moments: at random steps of the run (after its first
    # checkpoint), each a random fraction of a second after the step is logged, so that
    # kills also land inside checkpoint writes; `sphdem resume` after each
    run = os.path.join(args.work, "killed")
    first = first_checkpoint_step(ref)
    targets = sorted(rng.sample(range(first + 1, last_step(ref)), args.kills))
    proc = start(args, new(run), run)
    for k, target in enumerate(targets):
        if not wait_for(lambda: last_step(run) >= target, 10 * wall + 60, proc) or proc.poll() is not None:
            sys.exit("FAIL: the run ended before step %d:\n%s" % (target, output(args, run)))
        time.sleep(rng.uniform(0.0, 0.3))
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()
        newest = checkpoints(run)
        print("  SIGKILL %d near step %d; the newest checkpoint %s" %
              (k + 1, target, os.path.basename(newest[-1]) if newest else "none"))
        proc = start(args, resume(run) if newest else new(run), run)
    if proc.wait() != 0:
        sys.exit("FAIL: the resumed run failed:\n" + output(args, run))
    faults += len(targets)
    expect_identical(ref, run, "%d SIGKILLs" % len(targets))

    # 2. SIGTERM: a checkpoint at once, exit 128 + 15, the way to resume
    run = os.path.join(args.work, "terminated")
    proc = start(args, new(run), run)
    wait_for(lambda: checkpoints(run), 10 * wall + 60, proc)
    time.sleep(0.2 * wall)
    os.kill(proc.pid, signal.SIGTERM)
    code = proc.wait()
    text = output(args, run)
    if code != 128 + signal.SIGTERM or "Continue with: sphdem resume " + run not in text:
        sys.exit("FAIL SIGTERM: exit %d, output:\n%s" % (code, text[-2000:]))
    print("  SIGTERM: exit %d, '%s'" % (code, [l for l in text.splitlines() if "Continue with" in l][0]))
    if run_to_end(args, resume(run), run) != 0:
        sys.exit("FAIL: resume after SIGTERM:\n" + output(args, run))
    faults += 1
    expect_identical(ref, run, "SIGTERM")

    # 3. a full disk: no file may grow past a limit below a checkpoint's size
    run = os.path.join(args.work, "full_disk")
    proc = start(args, new(run), run)
    wait_for(lambda: checkpoints(run), 10 * wall + 60, proc)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    before = checkpoints(run)
    size = os.path.getsize(before[-1])
    code = run_to_end(args, resume(run), run, limit_bytes=size // 2)
    text = output(args, run)
    if code == 0 or "File too large" not in text or "is whole" not in text:
        sys.exit("FAIL full disk: exit %d, output:\n%s" % (code, text[-2000:]))
    line = [l for l in text.splitlines() if "File too large" in l][0]
    print("  full disk: exit %d, '%s'" % (code, line[:160] + ("..." if len(line) > 160 else "")))
    if checkpoints(run) != before or any(f.endswith(".tmp") for f in os.listdir(os.path.join(run, "checkpoints"))):
        sys.exit("FAIL full disk: the checkpoints changed: %s -> %s" % (before, checkpoints(run)))
    if run_to_end(args, resume(run), run) != 0:
        sys.exit("FAIL: resume after the full disk:\n" + output(args, run))
    faults += 1
    expect_identical(ref, run, "full disk")

    # 4. the newest checkpoint damaged, then cut short
    for fault in ("a flipped byte", "cut short"):
        run = os.path.join(args.work, "damaged" if fault == "a flipped byte" else "cut")
        proc = start(args, new(run), run)
        wait_for(lambda: len(checkpoints(run)) >= 2, 10 * wall + 60, proc)
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()
        newest = checkpoints(run)[-1]
        size = os.path.getsize(newest)
        with open(newest, "r+b") as f:
            if fault == "a flipped byte":
                f.seek(size // 2)
                b = f.read(1)
                f.seek(size // 2)
                f.write(bytes([b[0] ^ 0x01]))
            else:
                f.truncate(size * 2 // 3)
        if run_to_end(args, resume(run), run) != 0:
            sys.exit("FAIL %s: resume failed:\n%s" % (fault, output(args, run)))
        text = output(args, run)
        if "skipped a checkpoint" not in text or os.path.basename(newest) not in text:
            sys.exit("FAIL %s: no warning about %s:\n%s" % (fault, newest, text[-2000:]))
        print("  newest checkpoint %s: '%s'" % (fault, [l for l in text.splitlines() if "skipped" in l][0][:150]))
        faults += 1
        expect_identical(ref, run, "newest checkpoint " + fault)

    # a finished run, and a change of state on resume
    code = run_to_end(args, resume(ref), ref)
    if code != 0 or "is complete" not in output(args, ref):
        sys.exit("FAIL: resuming a finished run: exit %d" % code)
    code = run_to_end(args, resume(ref, "--set", "fluid.viscosity=0.002"), ref)
    if code != 2 or "can change only" not in output(args, ref):
        sys.exit("FAIL: a state key on resume was not refused (exit %d)" % code)
    print("faults injected %d, survived %d, lost nothing (every run identical to the uninterrupted one)" %
          (faults, faults))


if __name__ == "__main__":
    main()
