#!/usr/bin/env bash
# Sets up, builds and runs the main job. Today: the demo run of the spec's two solid blocks merged
# into one loaded body (examples/decks/merged_blocks.k) with the blockcontact CLI; results in out/.
# (The 19-problem verification suite and its report replace this when the contact issues land.)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
if [ -x build/apps/blockcontact/blockcontact ]; then
  build/apps/blockcontact/blockcontact run examples/decks/merged_blocks.k -o out --csv
else
  echo "blockcontact is not built; running the library example instead"
  build/examples/loaded_block
fi
