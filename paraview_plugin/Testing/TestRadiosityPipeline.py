"""pvbatch test of the Radiosity plugin: the Cornell box through the
Radiosity filter (every method), a property change that must show in the
output arrays, and bad input that must name what is wrong.

Usage: pvbatch --force-offscreen-rendering TestRadiosityPipeline.py <plugin.so>
"""
import math
import os
import sys

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

finish()
