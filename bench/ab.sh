#!/usr/bin/env bash
# Wall time of the coupled scenes with two builds, interleaved (A B A B ...), so that the
# machine's drift falls on both alike; prints every run, the medians and the ratio A/B of
# each pair with its median (> 1: B is faster).
#
#   bash bench/ab.sh OLD_BUILD NEW_BUILD [ROUNDS]      (default 3 rounds)
#   SCENES="sand_column_reduced" THREADS=1 END=0.05 bash bench/ab.sh build-old build
#
# A build is a CMake build directory holding app/sphdem (ParaView or not: the runs use
# --no-insitu). Scenes: cases/<name>.yaml as shipped *with each build's source* (a case's
# coupling keys and the defaults that replaced them travel with the code; CASES=DIR runs
# both on DIR/<name>.yaml instead), from t = 0 (after the relaxation) to END (default
# 0.1 s), OMP_NUM_THREADS=THREADS (default 2). Runs go to a temporary folder.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 2 ]; then sed -n '2,12p' "$0"; exit 2; fi
A="$1/app/sphdem"
B="$2/app/sphdem"
ROUNDS="${3:-3}"
SCENES="${SCENES:-sand_column_reduced suspension_monodisperse}"
THREADS="${THREADS:-2}"
END="${END:-0.1}"
for bin in "$A" "$B"; do [ -x "$bin" ] || { echo "ab.sh: no program $bin" >&2; exit 2; }; done
OUT="$(mktemp -d -t sphdem-ab.XXXXXX)"
echo "# ab.sh $(date -u '+%Y-%m-%dT%H:%M:%SZ') host=$(hostname) nproc=$(nproc) load1=$(cut -d' ' -f1 /proc/loadavg)"
source_of() {  # build directory -> its source tree (from CMakeCache.txt)
  local src
  src="$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$1/CMakeCache.txt" 2>/dev/null)"
  echo "${src:-.}"
}
commit() { git -C "$(source_of "$1")" rev-parse --short HEAD 2>/dev/null || echo '?'; }
CASES_A="${CASES:-$(source_of "$1")/cases}"
CASES_B="${CASES:-$(source_of "$2")/cases}"
echo "# A = $A (source at $(commit "$1"), cases from $CASES_A)"
echo "# B = $B (source at $(commit "$2"), cases from $CASES_B)"
echo "# OMP_NUM_THREADS=$THREADS, time.end=$END s, $ROUNDS rounds, runs in $OUT"

run() {  # build-binary cases-folder scene tag -> wall seconds
  local bin=$1 cases=$2 scene=$3 tag=$4
  OMP_NUM_THREADS="$THREADS" /usr/bin/time -f '%e' -o "$OUT/$tag.time" \
    "$bin" run "$cases/$scene.yaml" --out "$OUT/$tag" --no-insitu --set "time.end=$END" >"$OUT/$tag.log" 2>&1 \
    || { echo "ab.sh: $bin on $scene failed, see $OUT/$tag.log" >&2; exit 1; }
  tail -1 "$OUT/$tag.time"
}
median() { sort -g | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : 0.5*(v[NR/2]+v[NR/2+1])}'; }

printf '%-26s %5s %10s %10s %8s\n' scene round A_wall_s B_wall_s A/B
for scene in $SCENES; do
  : >"$OUT/$scene.a"; : >"$OUT/$scene.b"; : >"$OUT/$scene.r"
  for r in $(seq 1 "$ROUNDS"); do
    ta=$(run "$A" "$CASES_A" "$scene" "${scene}_a$r")
    tb=$(run "$B" "$CASES_B" "$scene" "${scene}_b$r")
    echo "$ta" >>"$OUT/$scene.a"; echo "$tb" >>"$OUT/$scene.b"
    awk -v a="$ta" -v b="$tb" 'BEGIN{print a/b}' >>"$OUT/$scene.r"
    printf '%-26s %5s %10s %10s %8.3f\n' "$scene" "$r" "$ta" "$tb" "$(tail -1 "$OUT/$scene.r")"
  done
  printf '%-26s %5s %10s %10s %8.3f\n' "$scene" median "$(median <"$OUT/$scene.a")" "$(median <"$OUT/$scene.b")" \
    "$(median <"$OUT/$scene.r")"
done
