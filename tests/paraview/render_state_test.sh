#!/usr/bin/env bash
# Runs a spec deck with state output, renders its last state coloured by von Mises with
# scripts/render_state.py in pvbatch and checks the picture (not blank, stress read as a 6-component
# tensor). Exit 77 (ctest: skipped) when pvbatch is not installed.
# Usage: render_state_test.sh BLOCKCONTACT SOURCE_DIR OUT_DIR
set -euo pipefail
blockcontact=$1 source_dir=$2 out=$3
if ! command -v pvbatch > /dev/null; then
  echo "pvbatch not found (apt-get install paraview xvfb xauth): skipped"
  exit 77
fi
rm -rf "$out" && mkdir -p "$out"
"$blockcontact" run "$source_dir/examples/sslide/sslide3p.k" -o "$out" --threads 1 > "$out/run.log"
# Debian's ParaView renders through X: use a virtual display when there is none.
pv=(pvbatch)
if [[ -z "${DISPLAY:-}" ]]; then
  if command -v xvfb-run > /dev/null; then pv=(xvfb-run -a pvbatch); else pv=(pvbatch --force-offscreen-rendering); fi
fi
"${pv[@]}" "$source_dir/scripts/render_state.py" "$out/sslide3p.xdmf" "$out/sslide3p.png" --check
test -s "$out/sslide3p.png"
