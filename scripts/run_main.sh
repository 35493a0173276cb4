#!/usr/bin/env bash
# Sets up, builds and runs the main job: the 19 verification problems of the spec
# (DYNA3D verification report, McMichael 2006; docs/verification.md) through `blockcontact verify --all`, which prints the
# table of criteria (ours beside DYNA3D's) and writes out/verify/report.md with its plots.
# Exit code: verify's (0 only when every criterion of every problem holds).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out/verify
status=0
build/apps/blockcontact/blockcontact verify --all -o out/verify || status=$?
echo "verification report: $(pwd)/out/verify/report.md (exit code ${status})"
exit "${status}"
