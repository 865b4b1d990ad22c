#!/usr/bin/env bash
# The decomposition's halo at R ranks (weak scaling) against the cube model:
#   bash bench/halo_exchange.sh BUILD ["1 2 4 8 16"] ["10000 100000"]
# Ghost counts are exact at any R; the times only where R <= the cores (oversubscribed
# ranks wait on each other). One line per run (bench/halo_exchange.cpp).
set -euo pipefail
cd "$(dirname "$0")/.."
BIN="$1/bench/halo_exchange"
RANKS="${2:-1 2 3 4 8 16}"
SIZES="${3:-10000 100000}"
echo "# halo_exchange.sh $(date -u '+%Y-%m-%dT%H:%M:%SZ') host=$(hostname) nproc=$(nproc) commit=$(git rev-parse --short HEAD)"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMP_NUM_THREADS=1
for n in $SIZES; do
  for r in $RANKS; do mpirun -np "$r" "$BIN" "$n"; done
done
