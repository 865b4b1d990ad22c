#!/usr/bin/env bash
# OpenMP thread scaling of the coupled step, pass by pass (bench/step_profile at each thread
# count, ROUNDS rounds interleaved): the hybrid baseline that MPI ranks will add to.
# Usage: bash bench/thread_scaling.sh BUILD "1 2 4 8 16" [ROUNDS] [RUN_DIR]
#   BUILD    a Release build with bench/step_profile
#   RUN_DIR  a 1 m sand column run whose newest checkpoint has a bed (resume=): optional
# Prints, per scene and thread count, the wall time per step and the three largest passes.
set -euo pipefail
build=$1
threads=${2:-"1 2 4 8 16"}
rounds=${3:-2}
run_dir=${4:-}
profile() {  # label threads args...
  local label=$1 t=$2
  shift 2
  echo "=== $label threads $t"
  OMP_NUM_THREADS=$t OMP_PROC_BIND=close OMP_PLACES=cores "$build/bench/step_profile" "$@" 2>&1 |
    grep -E "s per step|^(dem_substeps|voidage|interpolation) "
}
nproc
for round in $(seq "$rounds"); do
  for t in $threads; do
    [[ -z $run_dir ]] || profile bed_1m "$t" cases/sand_column.yaml 12 3 "resume=$run_dir"
    profile start_1m "$t" cases/sand_column.yaml 10 3 startup.relax_steps=10
    profile default "$t" cases/sedimentation.yaml 60 10
  done
done
