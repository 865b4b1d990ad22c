#!/usr/bin/env bash
# Set-up plus the main job: the default scene (`sphdem run` with no case file) into
# out/default. Extra arguments go to `sphdem run` (e.g. --set time.end=0.01).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
./build/app/sphdem run --out out/default "$@"
