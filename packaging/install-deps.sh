#!/usr/bin/env bash
# Installs every Debian 12 package clm3d needs to build, test and run.
# Idempotent: packages already present are skipped; apt-get update runs at most once.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git lld
  clang libclang-rt-14-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libeigen3-dev nlohmann-json3-dev libcli11-dev
  libassimp-dev libosmesa6-dev libegl-dev
  libarchive-dev
  libopencv-dev opencv-data
  libdlib-dev libdlib-data libblas-dev liblapack-dev
  qtbase5-dev libqt5charts5-dev libqt5svg5-dev
  libvtk9-dev libvtk9-qt-dev
  xvfb xauth
  slurm-wlm munge
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  sudo_cmd=(sudo)
fi

echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
