#!/usr/bin/env bash
# Installs the Debian 12 packages slideline needs. Idempotent: a no-op when all are present.
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  libeigen3-dev libfcl-dev libccd-dev libhdf5-dev
  libgtest-dev libgmock-dev libcli11-dev libfmt-dev libbenchmark-dev
  python3-matplotlib python3-h5py
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi
echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
