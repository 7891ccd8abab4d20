"""pvbatch test of the Radiosity plugin: the Cornell box through the
Radiosity filter (every method), a property change that must show in the
output arrays, bad input that must name what is wrong, and the "Lights"
group: a floor with no emitter lit by a LIGHTS.json point light (I h / d^3)
and by a uniform sky (pi L), and a bad lights file named by light and field.

Usage: pvbatch --force-offscreen-rendering TestRadiosityPipeline.py <plugin.so>
"""
import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager  # noqa: E402
from radiosity_pvtest import CapturedMessages, check, finish  # noqa: E402


LoadPlugin(sys.argv[1], remote=False, ns=globals())

box = CornellBox()
box.UpdatePipeline()
scene = servermanager.Fetch(box)
check(scene.GetNumberOfCells() > 0, "the Cornell box has no cells")
check(scene.GetCellData().GetArray("Reflectance") is not None, "the Cornell box has no Reflectance")


def mean_irradiance(data):
    array = data.GetPointData().GetArray("Irradiance")
    if array is None:
        return None
    total = 0.0
    for i in range(array.GetNumberOfTuples()):
        value = array.GetTuple3(i)
        if not all(math.isfinite(v) for v in value):
            return float("nan")
        total += sum(value) / 3.0
    return total / max(array.GetNumberOfTuples(), 1)


# Every method: Irradiance and Radiosity as point and cell data, finite.
solve = Radiosity(Input=box)
for method, extra in (("Progressive", None), ("Hierarchical", None), ("Meshless", None),
                      ("Face Cluster", "IrradianceVector")):
    solve.Method = method
    solve.UpdatePipeline()
    out = servermanager.Fetch(solve)
    for where, attributes in (("point", out.GetPointData()), ("cell", out.GetCellData())):
        for name in ("Irradiance", "Radiosity"):
            check(attributes.GetArray(name) is not None, "%s: no %s %s array" % (method, where, name))
    if extra:
        check(out.GetPointData().GetArray(extra) is not None, "%s: no %s" % (method, extra))
    h = mean_irradiance(out)
    check(h is not None and math.isfinite(h) and h > 0.0, "%s: mean irradiance %s" % (method, h))
    print("%s: %d cells, mean irradiance %.4g W/m^2" % (method, out.GetNumberOfCells(), h or 0.0))

# A property change shows in the output: twice the light, twice the light.
solve.Method = "Progressive"
box.LightScale = 1.0
solve.UpdatePipeline()
once = mean_irradiance(servermanager.Fetch(solve))
box.LightScale = 2.0
solve.UpdatePipeline()
twice = mean_irradiance(servermanager.Fetch(solve))
check(abs(twice / once - 2.0) < 1e-6, "LightScale 2 gave %s times the irradiance" % (twice / once))
print("light x2: irradiance x%.6f" % (twice / once))

# Progress reaches ParaView (the progress bar listens to the algorithm's
# ProgressEvent), rising; aborting from it stops the solve with a warning.
progress = []
solver = solve.GetClientSideObject()
tag = solver.AddObserver("ProgressEvent", lambda o, e: progress.append(o.GetProgress()))
box.LightScale = 1.5
solve.UpdatePipeline()
solver.RemoveObserver(tag)
check(len(progress) >= 3, "only %d progress events" % len(progress))
check(all(b >= a for a, b in zip(progress, progress[1:])), "progress went backwards: %s" % progress)
print("progress: %d events, last %.2f" % (len(progress), progress[-1] if progress else -1))


def abort(o, e):
    if o.GetProgress() > 0.05:
        o.SetAbortExecute(1)


tag = solver.AddObserver("ProgressEvent", abort)
box.LightScale = 1.25
with CapturedMessages() as messages:
    solve.UpdatePipeline()
solver.RemoveObserver(tag)
check("aborted" in messages.text, "no abort warning: %r" % messages.text[:300])
solver.SetAbortExecute(0)

# Bad input: a Reflectance of one component; the error names the array.
grey = Calculator(Input=box, AttributeType="Cell Data", ResultArrayName="Reflectance", Function="0.5")
bad = Radiosity(Input=grey)
with CapturedMessages() as messages:
    bad.UpdatePipeline()
check("Reflectance" in messages.text, "no error naming Reflectance: %r" % messages.text[:300])
check(servermanager.Fetch(bad).GetNumberOfCells() == 0, "bad input gave an output")

# Lights: a 1 m floor with no emitting triangle, lit by a point light of
# 2 W/sr 1 m above its centre (LightsFileName): nonzero, and I h / d^3 at
# the output's points (progressive: exact at its element corners).
work = tempfile.mkdtemp(prefix="radiosity_pvlights_")
lights = os.path.join(work, "lights.json")
with open(lights, "w") as f:
    f.write('{ "lights": [ { "type": "point", "position": [0, 0, 1], "intensity": 2 } ] }\n')
floor = Plane(XResolution=8, YResolution=8)
lit = Radiosity(Input=floor)
lit.Method = "Progressive"
with CapturedMessages() as messages:
    lit.LightsFileName = lights
    lit.UpdatePipeline()
check("no emitter" not in messages.text, "a floor lit by a light warned of no emitter: %r" % messages.text[:300])
out = servermanager.Fetch(lit)
array = out.GetPointData().GetArray("Irradiance")
check(array is not None and out.GetNumberOfPoints() > 0, "the lit floor has no Irradiance")
worst, peak = 0.0, 0.0
for i in range(out.GetNumberOfPoints() if array is not None else 0):
    x, y, _ = out.GetPoint(i)
    exact = 2.0 / (x * x + y * y + 1.0) ** 1.5
    worst = max(worst, abs(array.GetTuple3(i)[1] - exact) / exact)
    peak = max(peak, array.GetTuple3(i)[1])
print("point-lit floor: peak irradiance %.6g (I/h^2 = 2), worst relative error %.3g" % (peak, worst))
check(peak > 0.0, "the point-lit floor solved to zero")
# Measured 6.3e-8 (the progressive method's point values are the exact direct light).
check(worst < 1e-6, "point-lit floor off I h / d^3 by %.3g" % worst)

# The sky group: a uniform sky of radiance 1 gives pi on the open floor,
# added to the point light.
lit.SkyModel = "Uniform"
lit.SkyRadiance = [1.0, 1.0, 1.0]
lit.SkyUp = [0.0, 0.0, 1.0]
lit.UpdatePipeline()
out = servermanager.Fetch(lit)
array = out.GetPointData().GetArray("Irradiance")
worst = 0.0
for i in range(out.GetNumberOfPoints() if array is not None else 0):
    x, y, _ = out.GetPoint(i)
    exact = math.pi + 2.0 / (x * x + y * y + 1.0) ** 1.5
    worst = max(worst, abs(array.GetTuple3(i)[1] - exact) / exact)
print("sky and point light: worst relative error %.3g" % worst)
# Measured 1.6e-8 (the unobstructed sky's quadrature is exact: every weight pi / N).
check(array is not None and worst < 1e-6, "uniform sky + point light off by %.3g" % worst)
lit.SkyModel = "None"

# A bad light: the request fails naming the light's index and field.
bad_lights = os.path.join(work, "bad.json")
with open(bad_lights, "w") as f:
    f.write('{ "lights": [ { "type": "point", "position": [0, 0, 1] }, '
            '{ "type": "directional", "direction": [0, 0, 0] } ] }\n')
with CapturedMessages() as messages:
    lit.LightsFileName = bad_lights
    lit.UpdatePipeline()
check("light 1" in messages.text and "'direction'" in messages.text,
      "no error naming light 1's direction: %r" % messages.text[:300])
check(servermanager.Fetch(lit).GetNumberOfCells() == 0, "a bad light gave an output")
for name in (lights, bad_lights):
    os.remove(name)
os.rmdir(work)

finish()
