#!/usr/bin/env bash
# The main job: the built-in Cornell box solved, rendered and reported into out/.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/build.sh"
build="${RADIOSITY_BUILD_DIR:-$root/build}"
cd "$root"
# OpenGL needs an X server even offscreen.
if [ -n "${DISPLAY:-}" ]; then
  "$build/bin/vtkradiosity" demo --output-dir out "$@"
else
  xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" "$build/bin/vtkradiosity" demo --output-dir out "$@"
fi
