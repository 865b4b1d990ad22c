#!/usr/bin/python3
"""Parameter sweep of one validation scene: the trade between accuracy and wall time (issue 14).

    /usr/bin/python3 validation/sweep.py SCENE --vary KEY=v1,v2,... [--vary KEY=...]
        --build BUILD --out DIR [--mode reduced|full] [--set KEY=V ...] [--jobs N]
        [--threads T] [--reuse]

SCENE is a scene of validation/report.py (its name, e.g. `single_particle`, or its case
file, e.g. `cases/sand_column_reduced.yaml`). Every point of the grid (the product of the
--vary lists) runs the scene's runs of the mode with the point's values added to their
--set overrides (--set: the same for every point), and the scene's own evaluator turns
them into rows against theory, as in the report. Runs go to DIR/runs/<point>/, figures
to DIR/figures/<point>/.

DIR/sweep.csv has one line per point and row: the parameters; the check (quantity,
reference, simulated value, error, target, status); the wall time and SPH steps of the
run the row reads; and that run's stability figures from its log.csv: the largest
density error, the largest counts of the voidage floor and the Omega clamp, and the
fluid kinetic energy of the run's last quarter over that of the quarter before (> 1:
still growing). DIR/pareto.png draws each point's worst |error| / target over its
targeted rows against its wall time, with the points no other point beats in both
joined. --jobs N runs N points at once, each with OMP_NUM_THREADS = T (default: the
cores / N); compare wall times only between sweeps made with the same --jobs.
Exit code 0 when every run finished (rows may fail: a sweep looks for where they do).
"""
import argparse
import concurrent.futures
import csv
import itertools
import math
import os
import re
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vreport.figures import Context  # noqa: E402
from vreport.rows import Row, mark_safeguard_hits, safeguard_rows, settle_misses  # noqa: E402
from vreport.runs import Run, execute  # noqa: E402
from vreport.scenes import SCENES  # noqa: E402


def parse_vary(text):
    """KEY=v1,v2,... -> (KEY, [v1, v2, ...]); a value in brackets keeps its commas."""
    if "=" not in text:
        raise argparse.ArgumentTypeError(f"--vary {text!r}: expected KEY=v1,v2,...")
    key, values = text.split("=", 1)
    parts = [v.strip() for v in re.findall(r"\[[^\]]*\]|[^,]+", values)]
    if not key or not parts:
        raise argparse.ArgumentTypeError(f"--vary {text!r}: expected KEY=v1,v2,...")
    return key.strip(), parts


def parse_set(text):
    if "=" not in text:
        raise argparse.ArgumentTypeError(f"--set {text!r}: expected KEY=VALUE")
    key, value = text.split("=", 1)
    return key.strip(), value.strip()


def find_scene(name):
    for s in SCENES:
        if s.name == name or os.path.normpath(getattr(s, "case", "")) == os.path.normpath(name):
            return s
    names = ", ".join(s.name for s in SCENES)
    sys.exit(f"sweep.py: no scene {name!r} in validation/report.py (scenes: {names})")


def point_label(values):
    return ",".join(f"{k}={v}" for k, v in values.items())


def stability(result):
    """Figures of a run's log.csv that say whether it stayed stable (None when absent)."""
    log = result.log
    out = {"steps": None, "max_density_error": None, "voidage_clamped_max": None,
           "omega_bounded_max": None, "voidage_floor_steps": None, "omega_clamp_steps": None,
           "ke_fluid_last_quarter_growth": None}
    sg = getattr(result, "safeguards", None)
    if sg is not None:  # over every step, as the run counted them
        out["voidage_floor_steps"], out["omega_clamp_steps"] = sg["floor_steps"], sg["clamp_steps"]
    if log is None:
        return out
    out["steps"] = int(log["step"][-1]) if "step" in log else None
    for col, key in (("max_density_error", "max_density_error"), ("voidage_clamped", "voidage_clamped_max"),
                     ("omega_bounded", "omega_bounded_max")):
        if col in log:
            out[key] = float(np.max(log[col]))
    ke = log.get("kinetic_energy_fluid")
    if ke is not None and len(ke) >= 8:
        q = len(ke) // 4
        before, last = float(np.mean(ke[-2 * q:-q])), float(np.mean(ke[-q:]))
        out["ke_fluid_last_quarter_growth"] = last / before if before > 0 else None
    return out


def run_point(index, values, scene, args, sphdem, env):
    label = f"p{index:03d}"
    runs_dir = os.path.join(args.out, "runs", label)
    fig_dir = os.path.join(args.out, "figures", label)
    os.makedirs(fig_dir, exist_ok=True)
    results = {}
    for run in scene.runs(args.mode):
        sets = dict(run.sets)
        sets.update(args.fixed)
        sets.update(values)
        varied = Run(run.key, run.case, sets, run.insitu)
        results[run.key] = execute(varied, sphdem, runs_dir, args.reuse, args.nice, env)
    ctx = Context(fig_dir)
    try:
        rows = scene.evaluate(results, ctx)
    except Exception as e:  # noqa: BLE001  a broken evaluation is a failed row
        rows = [Row(scene.name, "evaluation", "–", "–", f"error: {e!r}", None, 0.0, kind="health")]
    rows += safeguard_rows(scene.name, results)
    mark_safeguard_hits(rows)
    settle_misses(rows)
    return label, results, rows


def worst_score(rows):
    """The point's worst |error| / target over its targeted rows (inf when one has no value)."""
    worst = 0.0
    for r in rows:
        if r.target is None or r.status == "SKIP":
            continue
        if r.error is None or not math.isfinite(r.error):
            return math.inf
        worst = max(worst, abs(r.error) / r.target if r.target > 0 else (0.0 if r.error == 0 else math.inf))
    return worst


def pareto_front(points):
    """Indices of the (wall, score) points that no other point beats in both."""
    front = []
    for i, (w, s) in enumerate(points):
        if not any((w2 <= w and s2 <= s) and (w2 < w or s2 < s) for j, (w2, s2) in enumerate(points) if j != i):
            front.append(i)
    return sorted(front, key=lambda i: points[i][0])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene", help="scene name or case file of validation/report.py")
    ap.add_argument("--vary", type=parse_vary, action="append", required=True, metavar="KEY=v1,v2,...")
    ap.add_argument("--set", dest="fixed_sets", type=parse_set, action="append", default=[], metavar="KEY=V")
    ap.add_argument("--mode", choices=("reduced", "full"), default="reduced")
    ap.add_argument("--build", required=True, help="CMake build directory (holds app/sphdem)")
    ap.add_argument("--out", required=True)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--threads", type=int, default=0, help="OMP_NUM_THREADS of each run (default cores / jobs)")
    ap.add_argument("--reuse", action="store_true", help="re-read runs already made with the same command")
    ap.add_argument("--nice", type=int, default=0)
    args = ap.parse_args()
    args.fixed = dict(args.fixed_sets)
    args.out = os.path.abspath(args.out)
    if args.jobs < 1:
        sys.exit(f"sweep.py: --jobs {args.jobs}: must be at least 1")

    scene = find_scene(args.scene)
    sphdem = os.path.abspath(os.path.join(args.build, "app", "sphdem"))
    if not os.access(sphdem, os.X_OK):
        sys.exit(f"sweep.py: no sphdem at {sphdem}")
    keys = [k for k, _ in args.vary]
    if len(set(keys)) != len(keys):
        sys.exit("sweep.py: a key is varied twice")
    grid = [dict(zip(keys, combo)) for combo in itertools.product(*[v for _, v in args.vary])]
    threads = args.threads or max(1, (os.cpu_count() or 1) // args.jobs)
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    os.makedirs(args.out, exist_ok=True)
    print(f"[sweep] {scene.name}, mode {args.mode}: {len(grid)} points x {len(scene.runs(args.mode))} runs, "
          f"{args.jobs} at once with {threads} threads each", flush=True)

    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(run_point, i, values, scene, args, sphdem, env) for i, values in enumerate(grid)]
        done = [f.result() for f in futures]

    csv_path = os.path.join(args.out, "sweep.csv")
    stab_keys = ["steps", "max_density_error", "voidage_clamped_max", "omega_bounded_max",
                 "voidage_floor_steps", "omega_clamp_steps", "ke_fluid_last_quarter_growth"]
    summary = []
    failed_runs = 0
    with open(csv_path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["point"] + keys + ["scene", "quantity", "reference", "simulated", "error", "target", "status",
                                       "run", "wall_s"] + stab_keys)
        for (label, results, rows), values in zip(done, grid):
            failed_runs += sum(not r.ok for r in results.values())
            for row in rows:
                r = row.result
                st = stability(r) if r is not None else dict.fromkeys(stab_keys)
                w.writerow([label] + [values[k] for k in keys] +
                           [row.scene, row.quantity, row.reference, row.simulated,
                            "" if row.error is None else f"{row.error:.6g}",
                            "" if row.target is None else f"{row.target:g}", row.status,
                            r.run.key if r is not None else "", f"{r.wall:.2f}" if r is not None else ""] +
                           ["" if st[k] is None else f"{st[k]:.6g}" for k in stab_keys])
            wall = sum(r.wall for r in results.values())
            summary.append((label, values, wall, worst_score(rows),
                            sum(r.status == "PASS" for r in rows), sum(r.status in ("FAIL", "MISS") for r in rows)))

    points = [(s[2], s[3]) for s in summary]
    front = pareto_front(points)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    finite = [p for p in points if math.isfinite(p[1])]
    top = 1.5 * max([p[1] for p in finite] + [1.0])
    for (label, values, wall, score, _, _) in summary:
        y = score if math.isfinite(score) else top
        ax.plot(wall, y, "o" if math.isfinite(score) else "x", color="C0")
        ax.annotate(" / ".join(values.values()), (wall, y), fontsize=7, xytext=(3, 3), textcoords="offset points")
    ax.plot([points[i][0] for i in front if math.isfinite(points[i][1])],
            [points[i][1] for i in front if math.isfinite(points[i][1])], "-", color="C1", label="Pareto front")
    ax.axhline(1.0, color="grey", ls=":", label="every target met below this line")
    ax.set_xlabel(f"wall time of the point's runs (s; {args.jobs} at once, {threads} threads each)")
    ax.set_ylabel("worst |error| / target")
    ax.set_yscale("log")
    ax.set_title(f"{scene.name} ({args.mode}): accuracy against wall time\n"
                 f"points: {' / '.join(keys)}", fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "pareto.png"), dpi=110)
    plt.close(fig)

    for i, (label, values, wall, score, n_pass, n_fail) in enumerate(summary):
        mark = "*" if i in front else " "
        print(f"{mark} {label}  {point_label(values):50s} wall {wall:8.1f} s  worst |err|/target {score:8.3g}  "
              f"{n_pass} pass, {n_fail} fail")
    print(f"[sweep] {csv_path}, {os.path.join(args.out, 'pareto.png')} (* = Pareto front); "
          f"{failed_runs} runs failed")
    return 1 if failed_runs else 0


if __name__ == "__main__":
    sys.exit(main())
