#!/usr/bin/env bash
# Sets up (Debian packages) and builds the Release tree in build/. Used by run_main.sh and test.sh;
# its arguments go to scripts/setup.sh (test.sh passes --paraview).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh "$@"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"${JOBS:-2}"
