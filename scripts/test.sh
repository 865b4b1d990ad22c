#!/usr/bin/env bash
# Set-up plus the whole test suite: ctest labels unit, validation, extremes, restart, mpi,
# format (every C++ file as .clang-format says) and insitu (once the Catalyst adaptor is
# built). Extra arguments go to ctest (e.g. -L unit) and run that alone. With none (as
# .ci/run calls it) two more checks follow, each built apart with only what it needs and
# timed:
#  - the unit tests under AddressSanitizer and UBSan (SPHDEM_SANITIZE, g++, build-asan);
#  - the scene loader's fuzz target for 60 s from its corpus (SPHDEM_FUZZ, clang, build-fuzz).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# Two tests at a time, each on one OpenMP thread (tests that need two threads or ranks
# take both slots: ctest PROCESSORS 2): on 2 cores this finishes the suite in ~60 % of
# the time of one test at a time on two threads, whose barriers spin while a thread waits.
OMP_NUM_THREADS=${OMP_NUM_THREADS:-1} ctest --test-dir build -j2 --output-on-failure "$@"
(($# == 0)) || exit 0

timed() {  # timed WHAT COMMAND...: runs it, then prints how long it took
  local what=$1 t0=$SECONDS
  shift
  "$@"
  echo "test.sh: ${what}: $((SECONDS - t0)) s"
}
asan_build() {
  cmake -S . -B build-asan -DSPHDEM_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug \
    -DSPHDEM_WITH_PARAVIEW=OFF -DSPHDEM_BUILD_BENCH=OFF -DPython3_EXECUTABLE=/usr/bin/python3
  cmake --build build-asan -j2 --target unit_tests
}
fuzz_build() {
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -DSPHDEM_FUZZ=ON
  cmake --build build-fuzz -j2 --target scene_fuzz
}
timed "sanitizer build (configure + unit tests)" asan_build
# One OpenMP thread a test, two tests at once: under ASan, OpenMP's spinning barriers on
# shared cores made hydrostatic_test 263 s with 2 threads against 50 s with one.
OMP_NUM_THREADS=1 timed "sanitizer run (ctest -L unit, 1 thread, -j2)" \
  ctest --test-dir build-asan -L unit -j2 --output-on-failure
timed "fuzz build (configure + scene_fuzz)" fuzz_build
timed "fuzz run (ctest -L fuzz)" ctest --test-dir build-fuzz -L fuzz --output-on-failure
grep -h "^Done .* runs" build-fuzz/Testing/Temporary/LastTest.log || true
