#!/usr/bin/env bash
# In-situ cost and output size on the default scene (cases/block_monodisperse.yaml):
#  1. with the in-situ pipelines at the scene's cadence: the share of wall time spent in
#     the analysis against the time spent in SPH-DEM steps (printed by sphdem);
#  2. the same run with full VTK snapshots at the same cadence instead (--no-insitu):
#     their time, and the bytes written by each kind of output.
# Usage: bash bench/insitu_cost.sh [build dir] [extra --set ...]
set -euo pipefail
BUILD=${1:-build}
shift || true
W=$(mktemp -d -t sphdem-insitu-cost.XXXXXX)
BIN="$BUILD/app/sphdem"
CASE=cases/block_monodisperse.yaml
EVERY=$(awk '/^insitu:/{f=1} f && /every:/{print $2; exit}' "$CASE")
echo "# machine: $(nproc) cores, $(lscpu | awk -F: '/Model name/{gsub(/^ +/,"",$2); print $2}'), $(date -u +%F)"
echo "# scene: $CASE, analysis every $EVERY s; work dir $W"
env -u DISPLAY "$BIN" run "$CASE" --out "$W/insitu" --set output.progress_interval=1000 "$@" 2>&1 |
  grep -E "in-situ analysis|done"
env -u DISPLAY "$BIN" run "$CASE" --out "$W/vtk" --no-insitu --set output.vtk.every="$EVERY" \
  --set output.progress_interval=1000 "$@" 2>&1 | grep -E "VTK snapshots|done"
echo "# bytes: reduced in-situ data (insitu/ without snapshots): $(du -sb --exclude=snapshots "$W/insitu/insitu" | cut -f1)"
echo "# bytes: PNG snapshots: $(du -sb "$W/insitu/insitu/snapshots" | cut -f1)"
echo "# bytes: figures: $(du -sb "$W/insitu/figures" | cut -f1)"
echo "# bytes: full VTK snapshots at the same cadence: $(du -sb "$W/vtk/vtk" | cut -f1)"
