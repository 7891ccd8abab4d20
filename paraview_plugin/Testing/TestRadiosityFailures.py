"""pvbatch test: a solver failure inside ParaView leaves the session running.

Bad input and a solve over its memory budget each fail with their message in
ParaView's output (vtkErrorMacro), an empty output and no exception leaving
the filter; the next valid solve on the same filter then works.

Usage: pvbatch --force-offscreen-rendering TestRadiosityFailures.py <plugin.so>
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager  # noqa: E402
from radiosity_pvtest import CapturedMessages, check, finish  # noqa: E402

LoadPlugin(sys.argv[1], remote=False, ns=globals())


def peak_irradiance(data):
    array = data.GetCellData().GetArray("Irradiance")
    if array is None or array.GetNumberOfTuples() == 0:
        return None
    return max(max(array.GetTuple3(i)) for i in range(array.GetNumberOfTuples()))


box = CornellBox()
solve = Radiosity(Input=box, Method="Hierarchical")

# 1. A solve over its memory budget: the estimate refuses it before it
# allocates (the Cornell box needs tens of kB for its initial links; 1 kB is given).
solve.MaxMemory = 1e-6
with CapturedMessages() as messages:
    solve.UpdatePipeline()
print("over budget:", next((l for l in messages.text.splitlines() if "memory budget" in l), "(no message)"))
check("memory budget" in messages.text and "--max-memory" in messages.text,
      "no memory budget error: %r" % messages.text[:400])
check(servermanager.Fetch(solve).GetNumberOfCells() == 0, "a refused solve gave an output")

# 2. The same filter with the budget lifted solves the box.
solve.MaxMemory = 0.0
with CapturedMessages() as messages:
    solve.UpdatePipeline()
good = peak_irradiance(servermanager.Fetch(solve))
check(good is not None and math.isfinite(good) and good > 1.0,
      "the solve after a failure gave peak irradiance %s" % good)
check("ERROR" not in messages.text, "errors after the budget was lifted: %r" % messages.text[:400])
print("after the failure: peak irradiance %.4g W/m^2" % (good or 0.0))

# 3. Bad input (a negative Emission) on every method: the message names the
# array and the value, the output is empty, and the session goes on.
negative = Calculator(Input=box, AttributeType="Cell Data", ResultArrayName="Emission",
                      Function="-1*iHat-1*jHat-1*kHat")
bad = Radiosity(Input=negative)
for method in ("Progressive", "Hierarchical", "Meshless", "Face Cluster"):
    bad.Method = method
    with CapturedMessages() as messages:
        bad.UpdatePipeline()
    check("Emission" in messages.text and "bad input" in messages.text,
          "%s: no bad-input error naming Emission: %r" % (method, messages.text[:400]))
    check(servermanager.Fetch(bad).GetNumberOfCells() == 0, "%s: bad input gave an output" % method)

# 4. And a valid solve again, on another method.
solve.Method = "Meshless"
solve.UpdatePipeline()
again = peak_irradiance(servermanager.Fetch(solve))
check(again is not None and math.isfinite(again) and again > 1.0,
      "meshless after the failures: peak irradiance %s" % again)
print("meshless after the failures: peak irradiance %.4g W/m^2" % (again or 0.0))

finish()
