#!/usr/bin/env bash
# Test insitu_two_ranks: the Catalyst adaptor and the reduction pipelines give the same
# answers on one and on two MPI ranks, and the known ones (compare_ranks.py).
#
#   two_ranks.sh DRIVER PIPELINES_DIR WORK_DIR
#
# Runs DRIVER (two_rank_driver) with mpirun -np 1 and -np 2 into WORK_DIR/np1 and
# WORK_DIR/np2, without a display (the pipelines used do not render).
set -euo pipefail

if [ $# -ne 3 ]; then
  echo "usage: $0 DRIVER PIPELINES_DIR WORK_DIR" >&2
  exit 2
fi
driver=$1
pipelines=$2
work=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

# mpirun as root (CI containers) and more ranks than cores (notes/paraview-catalyst.md §7)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
export OMP_NUM_THREADS=1

rm -rf "$work"
mkdir -p "$work"
for np in 1 2; do
  out="$work/np$np"
  mkdir -p "$out"
  echo "== mpirun -np $np $driver $out $pipelines"
  if ! env -u DISPLAY mpirun -np "$np" "$driver" "$out" "$pipelines" >"$out/run.log" 2>&1; then
    cat "$out/run.log" >&2
    echo "FAIL: the driver failed on $np rank(s) (log above: $out/run.log)" >&2
    exit 1
  fi
  cat "$out/run.log"
done

exec /usr/bin/python3 "$here/compare_ranks.py" "$work/np1" "$work/np2"
