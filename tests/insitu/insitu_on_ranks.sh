#!/usr/bin/env bash
# Test insitu_on_ranks: `mpirun -np 2 sphdem run` with its in-situ analysis gives the reduced
# data of one rank (voidage_height.h5, interfaces.csv, com.csv within 1e-9: the runs differ
# in summation order only), the same snapshots and the figures; a run stopped at half time
# and resumed on 2 ranks carries its in-situ rows on to the same end. With the double
# smoothing: on ranks its phi is read from the run's sphere copies, which a step leaves a half
# step behind their owners and the runner brings up to date before the hooks (without that
# the map moved by 1e-6). The spheres move as one rigid block: the double smoothing is refused
# over mobile spheres that settle into a bed (scene/scene_limits.hpp).
#
#   insitu_on_ranks.sh SPHDEM CASE WORK_DIR
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: $0 SPHDEM CASE WORK_DIR" >&2; exit 2; }
bin=$1 case=$2 work=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMP_NUM_THREADS=1
rm -rf "$work"; mkdir -p "$work"; cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
short=(--set time.end=0.002 --set startup.relax_steps=2 --set insitu.every=0.0001
  --set coupling.voidage_smoothing=double --set particles.0.rigid=true)

env -u DISPLAY "$bin" run "$case" --out one "${short[@]}" >one.log 2>&1 || { cat one.log; fail "1 rank"; }
env -u DISPLAY mpirun -np 2 "$bin" run "$case" --out two "${short[@]}" >two.log 2>&1 ||
  { cat two.log; fail "2 ranks"; }
grep -q "on 2 ranks" two.log || fail "the run did not say it ran on 2 ranks"
env -u DISPLAY mpirun -np 2 "$bin" run "$case" --out halves "${short[@]}" --set time.end=0.001 \
  >halves.log 2>&1 || { cat halves.log; fail "2 ranks, first half"; }
env -u DISPLAY mpirun -np 2 "$bin" resume halves --set time.end=0.002 >>halves.log 2>&1 ||
  { cat halves.log; fail "2 ranks, resumed"; }
for f in figures/voidage_height_time.png figures/interfaces.png figures/com_tracks.png; do
  [ -s "two/$f" ] || fail "2 ranks: no $f"
done
[ "$(ls one/insitu/snapshots | wc -l)" -eq "$(ls two/insitu/snapshots | wc -l)" ] ||
  fail "the snapshot PNGs differ in number between 1 and 2 ranks"
[ "$(ls two/insitu/snapshots | wc -l)" -gt 0 ] || fail "no snapshot PNGs (is Xvfb installed?)"
/usr/bin/python3 "$here/compare_insitu_runs.py" one/insitu two/insitu 1e-9
/usr/bin/python3 "$here/compare_insitu_runs.py" two/insitu halves/insitu 1e-9
echo "ok: in-situ on 2 ranks as on 1 rank, and resumed on 2 ranks"
