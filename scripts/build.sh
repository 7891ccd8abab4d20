#!/usr/bin/env bash
# Installs what is missing, configures and builds (Release with assertions) into build/.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/bootstrap.sh"
build="${RADIOSITY_BUILD_DIR:-$root/build}"
jobs="${RADIOSITY_JOBS:-$(nproc)}"
mkdir -p "$build"
bash "$root/scripts/fetch-data.sh" "$build/data" ||
  echo "build: could not fetch the bunny (npm); the highly tessellated scene is left out" >&2
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON >/dev/null
fi
cmake --build "$build" -j "$jobs"
