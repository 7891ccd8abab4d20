#!/usr/bin/env bash
# Builds and runs every test (unit, image regression, command line) under Xvfb;
# fails when npm is there but the test data cannot be fetched (scripts/build.sh).
set -euo pipefail
export RADIOSITY_REQUIRE_DATA="${RADIOSITY_REQUIRE_DATA:-1}"
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/build.sh"
build="${RADIOSITY_BUILD_DIR:-$root/build}"
cd "$build"
# -noreset: by default Xvfb resets when its last client disconnects, and a
# test connecting during that reset fails with "bad X server connection".
xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" ctest --output-on-failure -j "${RADIOSITY_JOBS:-$(nproc)}" "$@"
