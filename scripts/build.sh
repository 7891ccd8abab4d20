#!/usr/bin/env bash
# Installs what is missing, configures and builds (Release with assertions) into build/.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/bootstrap.sh"
build="${RADIOSITY_BUILD_DIR:-$root/build}"
jobs="${RADIOSITY_JOBS:-$(nproc)}"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON >/dev/null
fi
cmake --build "$build" -j "$jobs"
