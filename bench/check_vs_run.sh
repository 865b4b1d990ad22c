#!/usr/bin/env bash
# `sphdem check`'s wall-time estimate against the run it estimates, scene by scene: for
# each case, check and then the run (--no-insitu) to END (default 0.05 s), on THREADS
# threads (default 2); prints the estimate, the measured wall time (/usr/bin/time) and
# their ratio. Run on idle cores (bench/RESULTS.md).
#
#   bash bench/check_vs_run.sh BUILD [CASE ...]       (default: every cases/*.yaml)
#   END=1.0 bash bench/check_vs_run.sh build cases/sedimentation.yaml
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 1 ]; then sed -n '2,8p' "$0"; exit 2; fi
BIN="$1/app/sphdem"; shift
CASES=("$@"); [ ${#CASES[@]} -gt 0 ] || CASES=(cases/*.yaml)
END="${END:-0.05}"; THREADS="${THREADS:-2}"
OUT="$(mktemp -d -t sphdem-check.XXXXXX)"
echo "# check_vs_run.sh $(date -u '+%Y-%m-%dT%H:%M:%SZ') host=$(hostname) nproc=$(nproc) load1=$(cut -d' ' -f1 /proc/loadavg) commit=$(git rev-parse --short HEAD) END=$END THREADS=$THREADS"
printf '%-30s %12s %12s %8s\n' case estimate_s measured_s ratio
seconds() {  # "about 2.2 h on ..." -> seconds
  awk '{for (i = 1; i < NF; ++i) if ($i == "about") {v = $(i+1); u = $(i+2);
        print (u == "h") ? v * 3600 : (u == "min") ? v * 60 : v; exit}}'
}
for c in "${CASES[@]}"; do
  n="$(basename "$c" .yaml)"
  est=$(OMP_NUM_THREADS="$THREADS" "$BIN" check "$c" --set "time.end=$END" | grep '^wall time' | seconds)
  OMP_NUM_THREADS="$THREADS" /usr/bin/time -f '%e' -o "$OUT/$n.time" \
    "$BIN" run "$c" --out "$OUT/$n" --no-insitu --set "time.end=$END" >"$OUT/$n.log" 2>&1
  run=$(tail -1 "$OUT/$n.time")
  printf '%-30s %12.1f %12.1f %8.2f\n' "$n" "$est" "$run" "$(awk -v a="$est" -v b="$run" 'BEGIN{print a/b}')"
done
