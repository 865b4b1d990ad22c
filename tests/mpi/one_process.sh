#!/usr/bin/env bash
# Test mpi_one_process: `mpirun -np 2 sphdem ...` is refused with one clear message (from
# rank 0) and a non-zero status on every rank, before any file is written; without mpirun
# the same command runs. (sphdem runs a scene on one process; launcher_ranks.hpp.)
#
#   one_process.sh SPHDEM CASE WORK_DIR
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: $0 SPHDEM CASE WORK_DIR" >&2; exit 2; }
bin=$1 case=$2 work=$3
# mpirun as root (CI containers) and more ranks than cores (notes/paraview-catalyst.md §7)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMP_NUM_THREADS=1
rm -rf "$work"; mkdir -p "$work"; cd "$work"
status=0
env -u DISPLAY mpirun -np 2 "$bin" run "$case" --out out --no-insitu --set time.end=1e-4 \
  >log 2>&1 || status=$?
cat log
fail() { echo "FAIL: $*" >&2; exit 1; }
[ "$status" -ne 0 ] || fail "mpirun -np 2 sphdem run exited 0"
[ "$(grep -c 'started as 2 MPI ranks' log)" -eq 1 ] || fail "expected the refusal once, naming 2 ranks"
[ ! -e out ] || fail "the refused run wrote its output directory"
"$bin" check "$case" >/dev/null || fail "sphdem check without mpirun failed"
echo "ok: refused on 2 ranks with one message, nothing written; runs without mpirun"
