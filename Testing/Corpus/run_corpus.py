#!/usr/bin/env python3
"""Real-world corpus test: every .obj, .ply, .stl, .gltf, .glb, .3ds and .wrl
of Debian's assimp-testmodels (/usr/share/assimp/models, invalid/ included)
through `vtkradiosity solve` (the last four through VTK's importers and
vtkRadiosityPass). Each file must either

- solve: exit 0, and the output's Irradiance (points and cells) finite and
  non-negative (checked by CorpusOutputCheck, which reads the .vtp with VTK);
  a scene without emitters must give the documented zero solution (report
  `solution.stop` "no emitters", all irradiance 0) and say "no emitter" on
  stderr; or
- be refused: exit 2 with exactly one non-empty `error:` line and nothing
  written.

Never a signal, a hang (the per-file timeout), exit 1, exit 2 without its
line, or a zero answer without its warning. glTF is not read by the scene
loader yet: it is refused (unknown type), which counts as refused.

Every file that solved is then lit (SPEC.md "Lights and sky"): solved again
with `--lights`, a LIGHTS.json of a point light above its bounding box (from
the first solve's output: half a diagonal d above its top in y and in z, so
that it is above for y-up and z-up files alike, and a quarter of d beyond it
in x, so that no axis-aligned plane of the box holds it) and its mirror below
the box (surfaces are one-sided: a lone triangle facing down, as
OBJ/multiple_spaces.obj's does, is rightly dark under a light above), each
of intensity d^2 W/sr (about 1 W/m^2 on the box). That solve must exit 0
without the "no emitter" warning (nor a "no emitters" stop) and with a
non-zero peak irradiance (CorpusOutputCheck --nonzero): a zero answer under
a light fails.

Usage: run_corpus.py VTKRADIOSITY CORPUSOUTPUTCHECK WORKDIR [MODELS]
Exit 0 when every file passes, 1 otherwise, 77 (ctest: skipped) without the
package. Measured on the 2-core development machine (other builds running):
107 files in 86 to 103 s (63 zero solutions with their warning, each then
lit to a non-zero answer, 1 solved; 43 refused: among them glTF 1.0 files,
required extensions VTK does not read (Draco, techniqueWebGL), out-of-range
indices, a missing buffer file, a node that is its own ancestor, infinite
coordinates, primitives of points and lines only).
"""
import concurrent.futures
import json
import math
import os
import subprocess
import sys
import time

SKIP = 77
# Per file, a hang detector. Most files read, clean and solve in under 10 s,
# but 2CylinderEngine.glb (110k triangles) takes 26 s alone even with
# --max-time 5: meshless radiosity always completes its coarsest level
# (11.4 s of gathers there; MeshlessRadiosity::Refine), and the output
# evaluation and product add 7.5 s. Under CI's load (two files at once
# beside ctest -j2 on 2 cores) its lit run passed 60 s twice in 2026-12.
TIMEOUT_S = 180
EXTENSIONS = (".obj", ".ply", ".stl", ".gltf", ".glb", ".3ds", ".wrl")


def light_above(verdict):
    """The LIGHTS.json text of the point lights above and below the bounding
    box that CorpusOutputCheck printed ("bounds: xmin xmax ymin ymax zmin zmax")."""
    for line in verdict.splitlines():
        if line.startswith("bounds:"):
            b = [float(v) for v in line.split()[1:7]]
            break
    else:
        return None
    d = math.sqrt((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2)
    if not (d > 0.0 and math.isfinite(d)):
        return None
    above = [b[1] + d / 4.0, b[3] + d / 2.0, b[5] + d / 2.0]
    below = [b[0] - d / 4.0, b[2] - d / 2.0, b[4] - d / 2.0]
    return json.dumps({"lights": [
        {"type": "point", "position": above, "intensity": d * d, "name": "above"},
        {"type": "point", "position": below, "intensity": d * d, "name": "below"}]})


def run_lit(program, check, work, index, path, verdict, seconds):
    """The second solve, under the point lights above and below the box."""
    lights_text = light_above(verdict)
    if lights_text is None:
        return "other", "no bounding box to place the light from: " + verdict, seconds
    lights = os.path.join(work, "lights%d.json" % index)
    out = os.path.join(work, "lit%d.vtp" % index)
    with open(lights, "w") as f:
        f.write(lights_text + "\n")
    if os.path.exists(out):
        os.remove(out)
    command = [program, "solve", path, "--max-time", "5", "--output", out, "--lights", lights]
    start = time.monotonic()
    try:
        p = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return "hung", "lit: no answer after %d s" % TIMEOUT_S, seconds + TIMEOUT_S
    seconds += time.monotonic() - start
    stderr = p.stderr.decode("utf-8", "replace")
    if p.returncode != 0:
        return ("crashed" if p.returncode < 0 or p.returncode >= 128 else "other",
                "lit: exit %d: %s" % (p.returncode, stderr.strip()[-300:]), seconds)
    if "no emitter" in stderr:
        return "other", "lit: warned of no emitter under a light", seconds
    c = subprocess.run([check, out, "--nonzero"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       timeout=TIMEOUT_S)
    lit_verdict = c.stdout.decode("utf-8", "replace").strip()
    if c.returncode != 0:
        return "other", "lit: " + lit_verdict.replace("\n", "; "), seconds
    return "lit", lit_verdict.splitlines()[0], seconds


def run_one(program, check, work, index, path):
    outcome, detail, seconds = run_unlit(program, check, work, index, path)
    if outcome not in ("solved", "solved-zero-with-warning"):
        return outcome, detail, seconds
    lit = run_lit(program, check, work, index, path, detail, seconds)
    if lit[0] != "lit":
        return lit
    return outcome, detail.splitlines()[0] + "; lit: " + lit[1], lit[2]


def run_unlit(program, check, work, index, path):
    out = os.path.join(work, "out%d.vtp" % index)
    report = os.path.join(work, "report%d.json" % index)
    for f in (out, report):
        if os.path.exists(f):
            os.remove(f)
    command = [program, "solve", path, "--max-time", "5", "--output", out, "--report", report]
    start = time.monotonic()
    try:
        p = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return "hung", "no answer after %d s" % TIMEOUT_S, TIMEOUT_S
    seconds = time.monotonic() - start
    stderr = p.stderr.decode("utf-8", "replace")
    errors = [l for l in stderr.splitlines() if l.startswith("error:")]
    if p.returncode < 0 or p.returncode >= 128:
        return "crashed", "signal %d" % (-p.returncode if p.returncode < 0 else p.returncode - 128), seconds
    if p.returncode == 2:
        if len(errors) != 1 or not errors[0][len("error:"):].strip():
            return "other", "exit 2 with %d error lines: %s" % (len(errors), stderr.strip()[-300:]), seconds
        if os.path.exists(out) or os.path.exists(report):
            return "other", "refused but wrote an output: " + errors[0], seconds
        return "refused", errors[0], seconds
    if p.returncode != 0:
        return "other", "exit %d: %s" % (p.returncode, stderr.strip()[-300:]), seconds
    try:
        with open(report) as f:
            stop = json.load(f)["solution"]["stop"]
    except (OSError, ValueError, KeyError) as e:
        return "other", "exit 0 but no readable report: %s" % e, seconds
    c = subprocess.run([check, out], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       timeout=TIMEOUT_S)
    verdict = c.stdout.decode("utf-8", "replace").strip()
    if c.returncode != 0:
        return "other", "bad output: " + verdict, seconds
    zero = verdict.startswith("zero")
    if stop == "no emitters":
        if "no emitter" not in stderr:
            return "other", "zero solution without its 'no emitter' warning", seconds
        if not zero:
            return "other", "no emitters but a non-zero irradiance: " + verdict, seconds
        return "solved-zero-with-warning", verdict, seconds
    if zero and "no emitter" not in stderr:
        # Emitters that light nothing (facing away, all occluded) are legal, but say so.
        return "solved", "zero irradiance with emitters (%s): %s" % (stop, verdict), seconds
    return "solved", "%s: %s" % (stop, verdict), seconds


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 1
    program, check, work = sys.argv[1:4]
    models = sys.argv[4] if len(sys.argv) > 4 else "/usr/share/assimp/models"
    if not os.path.isdir(models):
        print("SKIPPED: %s not found (Debian package assimp-testmodels)" % models)
        return SKIP
    files = sorted(os.path.join(d, f) for d, _, names in os.walk(models) for f in names
                   if f.lower().endswith(EXTENSIONS))
    os.makedirs(work, exist_ok=True)
    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(lambda a: run_one(program, check, work, *a), enumerate(files)))
    counts = {k: 0 for k in ("solved", "solved-zero-with-warning", "refused", "crashed", "hung", "other")}
    failing = []
    for path, (outcome, detail, seconds) in zip(files, results):
        counts[outcome] += 1
        line = "%-24s %5.1f s  %s: %s" % (outcome, seconds, os.path.relpath(path, models), detail)
        print(line)
        if outcome in ("crashed", "hung", "other"):
            failing.append(line)
    print("\n%d files in %.0f s: %s" % (len(files), time.monotonic() - start,
                                        ", ".join("%s %d" % kv for kv in counts.items())))
    if failing:
        print("FAILING:\n" + "\n".join(failing))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
