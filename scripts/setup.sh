#!/usr/bin/env bash
# Installs what sphdem needs on Debian 12 (as root, or with sudo) and builds it in
# Release into build/. Safe to run again: apt skips what is installed, CMake rebuilds
# only what changed. Used by scripts/run-default.sh, scripts/test.sh and .ci/run.
set -euo pipefail
cd "$(dirname "$0")/.."

# ParaView 5.11 brings its own VTK 9.2 (libvtk9-dev conflicts with it); Catalyst needs
# parallel HDF5 and Open MPI; Xvfb gives headless runs a display; Debian's python3
# runs the pipelines' helpers and the figures (h5py, matplotlib, mpi4py, yaml); clang and
# its runtimes (libFuzzer, sanitizers) build the scene loader's fuzz target (scripts/test.sh);
# clang-format checks every C++ file against .clang-format (ctest label format).
PACKAGES=(g++ cmake make pkg-config clang-format libyaml-cpp-dev libfmt-dev libcli11-dev libgtest-dev libbenchmark-dev
          clang libclang-rt-14-dev
          paraview-dev python3-paraview libhdf5-openmpi-dev libopenmpi-dev openmpi-bin xvfb xauth
          python3-h5py python3-matplotlib python3-mpi4py python3-yaml python3-numpy)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build build -j"$(nproc)"
