#!/usr/bin/env bash
# Installs the Debian 12 packages slideline needs. Idempotent: a no-op when all are present.
# --paraview adds ParaView and a virtual X server (paraview python3-paraview xvfb xauth, installed
# with their recommendations, the set checked to render here: about 1 GB, 3-5 minutes on a fresh
# machine): scripts/test.sh asks for them so that the test paraview.render_state opens our XDMF
# output in ParaView; building and the main job do not need them.
set -euo pipefail
viewer=()
packages=(
  build-essential cmake pkg-config
  libeigen3-dev libfcl-dev libccd-dev libhdf5-dev
  libgtest-dev libgmock-dev libcli11-dev libfmt-dev libbenchmark-dev
  python3-matplotlib python3-h5py
)
for arg in "$@"; do
  case "$arg" in
    --paraview) viewer=(paraview python3-paraview xvfb xauth) ;;
    *) echo "setup.sh: unknown argument '$arg' (expected --paraview)" >&2; exit 2 ;;
  esac
done
missing=() missing_viewer=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
for p in "${viewer[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing_viewer+=("$p")
done
if [ ${#missing[@]} -eq 0 ] && [ ${#missing_viewer[@]} -eq 0 ]; then
  echo "setup: all $(( ${#packages[@]} + ${#viewer[@]} )) packages present"
  exit 0
fi
echo "setup: installing ${missing[*]} ${missing_viewer[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
if [ ${#missing[@]} -gt 0 ]; then
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
if [ ${#missing_viewer[@]} -gt 0 ]; then
  $SUDO apt-get install -y -q "${missing_viewer[@]}"
fi
