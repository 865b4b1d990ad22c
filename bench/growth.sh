#!/usr/bin/env bash
# Growth of the coupled step's cost with the particle count: the monodisperse suspension
# (cases/suspension_monodisperse.yaml) widened in x and y at the same resolution, so dt,
# the sub-steps and the neighbours per particle stay the same while N goes from ~1e4 to
# ~1e6. Each size runs STEPS_TIME of simulated time (~20 SPH steps) without relaxation;
# the sizes are interleaved over ROUNDS rounds and the medians printed: wall time per
# particle-step (fluid + wall + spheres, the loop only), its ratio to the smallest size,
# and the peak resident set of the process (/usr/bin/time).
# Usage: bash bench/growth.sh [BUILD_DIR=build] [ROUNDS=3]   (OMP_NUM_THREADS as set, default 2)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
ROUNDS=${2:-3}
SIZES=${SIZES:-"0.0024 0.0076 0.024"}   # box width (m): ~1.0e4, ~1.0e5, ~1.0e6 particles
STEPS_TIME=${STEPS_TIME:-4e-4}
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2}
BIN=$BUILD/app/sphdem
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
echo "commit $(git -C "$(dirname "$(realpath "$BIN")")" rev-parse --short HEAD 2>/dev/null || echo '?') build $BUILD, $OMP_NUM_THREADS threads, $(nproc) cores, $(date -u +%FT%TZ)"
for r in $(seq 1 "$ROUNDS"); do
  for L in $SIZES; do
    log=$OUT/run_${L}_$r.txt
    /usr/bin/time -f "peak_kib %M" "$BIN" run cases/suspension_monodisperse.yaml --no-insitu -o "$OUT/out_$L" \
      --set "domain.size=[$L,$L,0.006]" --set "particles.0.max=[$L,$L,0.0048]" \
      --set time.end="$STEPS_TIME" --set startup.relax_steps=0 >"$log" 2>&1
    rm -rf "$OUT/out_$L"
  done
done
python3 - "$OUT" "$ROUNDS" $SIZES <<'PY'
import re, statistics, sys
out, rounds, sizes = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
rows = []
for L in sizes:
    cost, peak = [], []
    for r in range(1, rounds + 1):
        text = open(f"{out}/run_{L}_{r}.txt").read()
        nf, nw, ns = map(int, re.search(r"(\d+) fluid \+ (\d+) wall SPH particles, (\d+) spheres", text).groups())
        steps, rate = re.search(r"done, (\d+) steps to .*\(([\d.e+-]+) SPH particle-steps/s\)", text).groups()
        # the rate counts the owned SPH particles (fluid + wall) per second of the loop
        loop = (nf + nw) * int(steps) / float(rate)
        cost.append(loop / (int(steps) * (nf + nw + ns)) * 1e9)
        peak.append(int(re.search(r"peak_kib (\d+)", text).group(1)) / 1024)
    rows.append((L, nf + nw + ns, int(steps), statistics.median(cost), statistics.median(peak), cost))
base = rows[0][3]
print(f"{'width (m)':>9} {'particles':>10} {'steps':>5} {'ns/particle-step':>17} {'vs smallest':>11} {'peak RSS MiB':>12}  rounds (ns)")
for L, n, steps, c, p, all_c in rows:
    print(f"{L:>9} {n:>10} {steps:>5} {c:>17.1f} {c / base:>11.2f} {p:>12.0f}  {' '.join(f'{x:.1f}' for x in all_c)}")
PY
