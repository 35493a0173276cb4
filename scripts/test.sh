#!/usr/bin/env bash
# Sets up (Debian packages), builds (Release) and runs every test; then builds the unit tests with
# AddressSanitizer + UndefinedBehaviorSanitizer and runs them. Exit status non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-2}
bash scripts/build.sh
ctest --test-dir build -j"$jobs" --output-on-failure --timeout 900
if [ "${SLIDELINE_SKIP_SANITIZERS:-0}" != "1" ]; then
  cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSLIDELINE_SANITIZE=ON \
        -DSLIDELINE_BUILD_BENCHMARKS=OFF -DSLIDELINE_BUILD_APPS=OFF
  cmake --build build-sanitize -j"$jobs" --target unit_tests
  # libgomp is not instrumented; its thread pool's allocations are not leaks of ours.
  ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir build-sanitize -L unit -LE package -j"$jobs" --output-on-failure --timeout 900
fi
