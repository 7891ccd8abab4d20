#!/usr/bin/env bash
# The real-interiors bench (issue 53): every method on the built-in office
# (daylight only, 20 sensors on the working plane) and on the classroom of
# ../shared/scenes/classroom (sun and overcast sky, 48 sensors on its
# surfaces), each against a path-traced reference computed once and kept
# (--reference-output). Prints one markdown row per scene and method: time
# all in (the report's time.total_s), solve time, RMS and worst sensor error
# relative to the peak (the report's probe_output_* figures), the stop.
#
# usage: bench/real_interiors.sh [OUT_DIR] [METHODS...]
#   OUT_DIR  default bench/results/real-interiors; the references go there too
#   METHODS  default: auto progressive hierarchical meshless facecluster
# Environment: RADIOSITY_BUILD_DIR (default build), CLASSROOM (the .gltf),
#   REFERENCE_SAMPLES (paths per sensor, default 1048576: the classroom's
#   kept sensors to 0.5% standard error), MAX_TIME (per solve, default 900 s).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${RADIOSITY_BUILD_DIR:-$root/build}"
bin="$build/bin/vtkradiosity"
out="${1:-$root/bench/results/real-interiors}"
shift || true
methods=("$@")
[ ${#methods[@]} -gt 0 ] || methods=(auto progressive hierarchical meshless facecluster)
classroom="${CLASSROOM:-$root/../shared/scenes/classroom/classroom.gltf}"
samples="${REFERENCE_SAMPLES:-1048576}"
maxtime="${MAX_TIME:-900}"
mkdir -p "$out"

# The office: daylight only (the lamp left out), the working plane 0.75 m up.
cat > "$out/office-sky.json" <<'JSON'
{ "lights": [ { "type": "sky", "model": "cie-overcast", "up": [0, 0, 1], "intensity": 1000 } ] }
JSON
python3 - "$out/office-desk.csv" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("x,y,z,nx,ny,nz\n")
    for i in range(5):
        for j in range(4):
            f.write("%g,%g,0.75,0,0,1\n" % (0.5 + i, 0.5 + j))
PY
[ -f "$out/classroom-sensors.csv" ] ||
  python3 "$root/bench/scenes/classroom_sensors.py" "$classroom" 64 > "$out/classroom-sensors.csv"

row() { # scene method report
  python3 - "$@" <<'PY'
import json, sys
scene, method, path = sys.argv[1:4]
r = json.load(open(path))
e = r.get("error") or {}
def pct(v):
    return "n/a" if v is None else "%.2f%%" % (100 * v)
print("| %s | %s%s | %.1f | %.1f | %s | %s | %s |" % (scene, method,
    " (%s)" % r["method"] if method == "auto" else "", r["time"]["total_s"], r["time"].get("solve_s", 0.0),
    pct(e.get("probe_output_rms_relative_error")), pct(e.get("probe_output_max_relative_error")),
    r["solution"]["stop"]))
PY
}

echo "| scene | method | all in (s) | solve (s) | RMS of peak | worst of peak | stop |"
echo "|---|---|---|---|---|---|---|"
for scene in office classroom; do
  if [ "$scene" = office ]; then
    args=(office --lights "$out/office-sky.json" --probes "$out/office-desk.csv")
  else
    args=("$classroom" --lights "$(dirname "$classroom")/lights.json" --probes "$out/classroom-sensors.csv")
  fi
  ref="$out/$scene-reference.csv"
  if [ ! -f "$ref" ]; then
    "$bin" solve "${args[@]}" --method progressive --max-time 1 --reference pathtraced \
      --reference-samples "$samples" --reference-output "$ref" --report "$out/$scene-reference.json" \
      > /dev/null 2> "$out/$scene-reference.log"
    if [ "$scene" = classroom ]; then
      # A sensor drawn on a face that lies inside another part (the
      # classroom's parts interpenetrate) sees nothing: those whose
      # reference is below 1% of the median are dropped, from both files.
      python3 - "$out/classroom-sensors.csv" "$ref" <<'PY'
import sys
sensors, ref = (open(p).read().split("\n") for p in sys.argv[1:3])
rows = [(s, r) for s, r in zip(sensors[1:], ref[1:]) if s and r]
e = sorted(float(r.split(",")[4]) for s, r in rows)
median = e[len(e) // 2]
kept = [(s, r) for s, r in rows if float(r.split(",")[4]) >= 0.01 * median]
se = [float(r.split(",")[6]) for s, r in kept if len(r.split(",")) > 6]
sys.stderr.write("classroom sensors: %d kept of %d; largest relative standard error of the kept: %s\n"
                 % (len(kept), len(rows), "%.2e" % max(se) if se else "unknown"))
open(sys.argv[1], "w").write("\n".join([sensors[0]] + [s for s, r in kept]) + "\n")
open(sys.argv[2], "w").write("\n".join([ref[0]] + [r for s, r in kept]) + "\n")
PY
    fi
  fi
  for m in "${methods[@]}"; do
    if "$bin" solve "${args[@]}" --method "$m" --max-time "$maxtime" --reference "$ref" \
      --probe-output "$out/$scene-$m-probes.csv" --report "$out/$scene-$m.json" > /dev/null 2> "$out/$scene-$m.log"; then
      row "$scene" "$m" "$out/$scene-$m.json"
    else
      echo "| $scene | $m | failed: $(tail -1 "$out/$scene-$m.log") | | | | |"
    fi
  done
done
