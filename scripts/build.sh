#!/usr/bin/env bash
# Installs what is missing, configures and builds (Release with assertions) into build/.
# RADIOSITY_REQUIRE_DATA=1 (set by scripts/test.sh): fail when npm is there
# but the bunny cannot be fetched (otherwise a warning, and its tests report
# as skipped).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/bootstrap.sh"
build="${RADIOSITY_BUILD_DIR:-$root/build}"
jobs="${RADIOSITY_JOBS:-$(nproc)}"
mkdir -p "$build"
had_data=0
[ -f "$build/data/bunny/index.js" ] && had_data=1
fetch=0
bash "$root/scripts/fetch-data.sh" "$build/data" || fetch=$?
if [ "$fetch" -eq 3 ]; then
  echo "build: npm is not available, the bunny is left out: its tests report as skipped" >&2
elif [ "$fetch" -ne 0 ]; then
  if [ "${RADIOSITY_REQUIRE_DATA:-0}" = 1 ]; then
    echo "build: npm is there but the bunny could not be fetched (see above): the tests need it" >&2
    exit 1
  fi
  echo "build: could not fetch the bunny (npm); its tests report as skipped" >&2
fi
# Configure when new, and again when the data has just arrived (the bunny
# tests are set up at configure time). The configure's warnings are shown.
if [ ! -f "$build/CMakeCache.txt" ] || { [ "$had_data" = 0 ] && [ -f "$build/data/bunny/index.js" ]; }; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON
fi
cmake --build "$build" -j "$jobs"
