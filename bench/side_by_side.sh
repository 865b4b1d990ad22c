#!/usr/bin/env bash
# sphdem against LAMMPS and LIGGGHTS on the peers' own scenes, in one run: our benchmarks
# (bench_scenes: BM_FluidColumnStep = `sph`, BM_DemSettle = `dem_settle`, BM_DemBed =
# `dem_bed`, the same particles, physics and step windows) and the team's
# shared/peers/run-peers.sh, alternately, on 1 and 2 threads/ranks, ROUNDS rounds; prints
# every measurement, then the medians in million particle-steps per second and the ratios
# sphdem / peer of the medians.
#
#   bash bench/side_by_side.sh [BUILD] [ROUNDS]     (defaults: build, 3; ~10 min a round)
#   SCENES="sph" bash bench/side_by_side.sh build 3  (a subset of sph, dem_settle, dem_bed)
#
# The peers' script installs lammps, liggghts and openmpi-bin if they are missing (root).
# Everything goes to a temporary folder, printed in the header.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="$(cd "${1:-$ROOT/build}" && pwd)"
ROUNDS="${2:-3}"
SCENES="${SCENES:-sph dem_settle dem_bed}"
FILTER=""
for sc in $SCENES; do
  case "$sc" in
    sph) b=FluidColumnStep ;; dem_settle) b=DemSettle ;; dem_bed) b=DemBed ;;
    *) echo "side_by_side.sh: unknown scene $sc (sph, dem_settle, dem_bed)" >&2; exit 2 ;;
  esac
  FILTER="${FILTER:+$FILTER|}$b"
done
PEERS="${PEERS_DIR:-$ROOT/../shared/peers}"
BENCH="$BUILD/bench/bench_scenes"
[ -x "$BENCH" ] || { echo "side_by_side.sh: no $BENCH (build with -DSPHDEM_BUILD_BENCH=ON)" >&2; exit 2; }
[ -x "$PEERS/run-peers.sh" ] || { echo "side_by_side.sh: no $PEERS/run-peers.sh (set PEERS_DIR)" >&2; exit 2; }
OUT="$(mktemp -d -t sphdem-side-by-side.XXXXXX)"
echo "# side_by_side.sh $(date -u '+%Y-%m-%dT%H:%M:%SZ') host=$(hostname) nproc=$(nproc) load1=$(cut -d' ' -f1 /proc/loadavg)"
echo "# sphdem $(git -C "$ROOT" rev-parse --short HEAD) ($BENCH), peers $PEERS, $ROUNDS rounds, output $OUT"

for r in $(seq 1 "$ROUNDS"); do
  for t in 1 2; do
    echo "# round $r, $t thread(s)/rank(s): sphdem $(date -u +%H:%M:%S)"
    OMP_NUM_THREADS=$t "$BENCH" --benchmark_filter="BM_($FILTER)/" \
      --benchmark_out="$OUT/sphdem_r${r}_t$t.json" --benchmark_out_format=json >"$OUT/sphdem_r${r}_t$t.txt" 2>&1
    echo "# round $r, $t thread(s)/rank(s): peers $(date -u +%H:%M:%S)"
    OUTDIR="$OUT/peers_r${r}_t$t" "$PEERS/run-peers.sh" --ranks "$t" --scenes "$SCENES" \
      >"$OUT/peers_r${r}_t$t.txt" 2>&1
  done
done

/usr/bin/python3 - "$OUT" <<'EOF'
import csv, glob, json, os, statistics, sys
out = sys.argv[1]
ours = {"BM_FluidColumnStep": ("sph", "sph_particle_steps_per_s"),
        "BM_DemSettle": ("dem_settle", "dem_particle_steps_per_s"),
        "BM_DemBed": ("dem_bed", "dem_particle_steps_per_s")}
runs = {}  # (code, scene, threads) -> [M p-s/s per round]
for path in sorted(glob.glob(os.path.join(out, "sphdem_r*_t*.json"))):
    t = int(path.rsplit("_t", 1)[1].split(".")[0])
    for b in json.load(open(path))["benchmarks"]:
        name = b["name"].split("/")[0]
        if name in ours:
            scene, counter = ours[name]
            runs.setdefault(("sphdem", scene, t), []).append(b[counter] / 1e6)
for path in sorted(glob.glob(os.path.join(out, "peers_r*_t*", "results.tsv"))):
    for row in csv.DictReader(open(path), delimiter="\t"):
        runs.setdefault((row["peer"], row["scene"], int(row["ranks"])), []).append(float(row["particle_steps_per_s"]) / 1e6)
print("\n# every measurement (M particle-steps/s)")
for key in sorted(runs):
    print("  %-8s %-10s %d: %s" % (key[0], key[1], key[2], " ".join("%.3f" % v for v in runs[key])))
med = {k: statistics.median(v) for k, v in runs.items()}
print("\n| scene | threads / ranks | sphdem | LAMMPS | LIGGGHTS | sphdem / LAMMPS | sphdem / LIGGGHTS |")
print("|---|---|---|---|---|---|---|")
for scene in ("sph", "dem_settle", "dem_bed"):
    for t in (1, 2):
        s = med.get(("sphdem", scene, t))
        cells = []
        for peer in ("lammps", "liggghts"):
            p = med.get((peer, scene, t))
            cells.append(p)
        fmt = lambda v: "%.3f" % v if v is not None else "–"
        ratio = lambda p: "%.2f×" % (s / p) if (s is not None and p) else "–"
        print("| %s | %d | %s | %s | %s | %s | %s |" % (scene, t, fmt(s), fmt(cells[0]), fmt(cells[1]),
                                                    ratio(cells[0]), ratio(cells[1])))
EOF
