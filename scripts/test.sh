#!/usr/bin/env bash
# Set-up plus the whole test suite: ctest labels unit, validation (and insitu once
# the Catalyst adaptor is built). Extra arguments go to ctest (e.g. -L unit).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
ctest --test-dir build --output-on-failure "$@"
