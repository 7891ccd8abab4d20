#!/usr/bin/env bash
# Installs the Debian packages the project needs (see shared DESIGN.md), only those missing:
# assimp-testmodels is the real-world corpus test's input, clang and its runtime the fuzz build's.
# Idempotent and quick when everything is already there.
set -euo pipefail

PACKAGES=(
  cmake g++ ninja-build ccache pkg-config
  paraview-dev paraview python3-paraview
  libembree-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev libglm-dev
  libopenexr-dev libtbb-dev libeigen3-dev libnanoflann-dev libsleef-dev libgtest-dev libbenchmark-dev
  nlohmann-json3-dev libcli11-dev
  xvfb xauth libgl1-mesa-dri
  mpi-default-dev mpi-default-bin libglew-dev libgl-dev libx11-dev libexpat1-dev
  libdouble-conversion-dev liblz4-dev liblzma-dev libjpeg-dev libtiff-dev
  libpng-dev zlib1g-dev libutfcpp-dev libpython3-dev
  assimp-testmodels clang libclang-rt-14-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "bootstrap: installing ${#missing[@]} missing Debian packages: ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
