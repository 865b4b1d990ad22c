#!/usr/bin/env bash
# A run under contention: the same scene alone and beside a busy loop on one core, with
# OpenMP's default wait policy and with OMP_WAIT_POLICY=passive (threads sleep at a
# barrier instead of spinning). Interleaved over ROUNDS rounds; prints the median wall
# times and the slowdown beside the busy loop. Three runnable threads on 2 cores leave
# our 2 threads 4/3 of a core: a slowdown of 1.5x is "in proportion".
# Usage: bash bench/contention.sh [BUILD_DIR=build] [ROUNDS=3]
#        SCENE=cases/... END=0.05 (simulated seconds)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
ROUNDS=${2:-3}
SCENE=${SCENE:-cases/sand_column_reduced.yaml}
END=${END:-0.05}
BIN=$BUILD/app/sphdem
OUT=$(mktemp -d)
hog=""
stop_hog() { if [ -n "$hog" ]; then kill "$hog" 2>/dev/null || true; wait "$hog" 2>/dev/null || true; hog=""; fi; }
trap 'stop_hog; rm -rf "$OUT"' EXIT
echo "commit $(git rev-parse --short HEAD) build $BUILD, $SCENE to t = $END s, 2 threads, $(nproc) cores, $(date -u +%FT%TZ)"
run() {  # name policy busy
  local name=$1 policy=$2 busy=$3
  if [ "$busy" = 1 ]; then
    bash -c 'while :; do :; done' &
    hog=$!
  fi
  local t
  t=$( { env OMP_NUM_THREADS=2 ${policy:+OMP_WAIT_POLICY=$policy} /usr/bin/time -f "%e" \
        "$BIN" run "$SCENE" --no-insitu -o "$OUT/out" --set time.end="$END" >/dev/null 2>"$OUT/err"; } 2>&1; tail -1 "$OUT/err")
  stop_hog
  echo "$name $t" >>"$OUT/times"
}
for r in $(seq 1 "$ROUNDS"); do
  run default_alone "" 0
  run default_busy "" 1
  run passive_alone passive 0
  run passive_busy passive 1
done
python3 - "$OUT/times" <<'PY'
import statistics, sys
t = {}
for line in open(sys.argv[1]):
    name, s = line.split()
    t.setdefault(name, []).append(float(s))
m = {k: statistics.median(v) for k, v in t.items()}
for policy in ("default", "passive"):
    a, b = m[f"{policy}_alone"], m[f"{policy}_busy"]
    print(f"{policy:>8} wait policy: alone {a:7.1f} s  beside a busy loop {b:7.1f} s  slowdown {b / a:4.2f}x"
          f"   rounds alone {t[f'{policy}_alone']} busy {t[f'{policy}_busy']}")
print(f"passive/default alone {m['passive_alone'] / m['default_alone']:.2f}x")
PY
