"""pvbatch test of the Radiosity plugin's other filters, each on the Cornell
box: the face cluster hierarchy's ClusterId levels, the discontinuity mesh's
quadratic interpolants, the meshless field and its Shepard probe, what
Method Auto chose and why, and a
screenshot of the solution (Surface coloured by Radiosity) against its
baseline.

Usage: pvbatch --force-offscreen-rendering TestRadiosityFilters.py <plugin.so> <baseline.png> <output dir>
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager  # noqa: E402
from radiosity_pvtest import check, compare_with_baseline, finish  # noqa: E402


def finite_positive(array):
    values = [array.GetComponent(i, c) for i in range(array.GetNumberOfTuples())
              for c in range(array.GetNumberOfComponents())]
    return bool(values) and all(math.isfinite(v) for v in values) and max(values) > 0.0


LoadPlugin(sys.argv[1], remote=False, ns=globals())
baseline, output = sys.argv[2], sys.argv[3]
CLUSTERED_MEAN_BOUND = 0.025  # measured 0.0093 (0.364655 plain, 0.368048 clustered)
box = CornellBox()

clusters = FaceClusterHierarchy(Input=box)
clusters.NumberOfLevels = 3
data = servermanager.Fetch(clusters)
for level in range(3):
    check(data.GetCellData().GetArray("ClusterId%d" % level) is not None, "no ClusterId%d" % level)
check(data.GetCellData().GetArray("ClusterId3") is None, "NumberOfLevels 3 wrote a fourth level")

hierarchical = Radiosity(Input=box)
hierarchical.Method = "Hierarchical"
# The Product output (port 1): the discontinuity mesh.
data = servermanager.Fetch(hierarchical, idx=1)
interpolants = data.GetCellData().GetArray("QuadraticInterpolant")
check(interpolants is not None and interpolants.GetNumberOfComponents() == 18,
      "no 18-component QuadraticInterpolant")
check(finite_positive(data.GetCellData().GetArray("Irradiance")), "discontinuity mesh irradiance")
print("discontinuity mesh: %d triangles" % data.GetNumberOfCells())

# Clustering forced on (the Hierarchical group's Clustering choice): links
# from the face cluster roots; the Cornell box's light on the walls is the
# plain solve's within a few per cent.
def area_mean_irradiance(data):
    import vtk
    sizes = vtk.vtkCellSizeFilter()
    sizes.SetInputData(data)
    sizes.ComputeAreaOn()
    sizes.Update()
    area = sizes.GetOutput().GetCellData().GetArray("Area")
    irradiance = data.GetCellData().GetArray("Irradiance")
    total = sum(area.GetValue(i) for i in range(data.GetNumberOfCells()))
    return sum(area.GetValue(i) * sum(irradiance.GetTuple3(i)) / 3.0
               for i in range(data.GetNumberOfCells())) / total


plain_mean = area_mean_irradiance(servermanager.Fetch(hierarchical, idx=0))
clustered = Radiosity(Input=box)
clustered.Method = "Hierarchical"
clustered.Clustering = "On"
clustered_data = servermanager.Fetch(clustered, idx=0)
check(finite_positive(clustered_data.GetCellData().GetArray("Irradiance")), "clustered irradiance")
clustered_mean = area_mean_irradiance(clustered_data)
print("area-mean irradiance: plain %.6g, clustered %.6g" % (plain_mean, clustered_mean))
check(abs(clustered_mean / plain_mean - 1.0) < CLUSTERED_MEAN_BOUND,
      "clustered mean irradiance %g against the plain solve's %g" % (clustered_mean, plain_mean))

meshless = Radiosity(Input=box)
meshless.Method = "Meshless"
# The Product output (port 1): the Shepard field's points.
field = OutputPort(meshless, 1)
data = servermanager.Fetch(meshless, idx=1)
for name in ("Level", "Radius", "Coefficient", "Irradiance"):
    check(data.GetPointData().GetArray(name) is not None, "meshless field: no %s" % name)
print("meshless field: %d basis functions" % data.GetNumberOfPoints())
probe = ShepardFieldProbe(Input=box, Field=field)
data = servermanager.Fetch(probe)
check(finite_positive(data.GetPointData().GetArray("Irradiance")), "Shepard probe irradiance")

# Method Auto, the default: the matte 32-triangle box is solved by clustered
# hierarchical radiosity, and the output's field data says so and why.
chosen = Radiosity(Input=box)
check(chosen.Method == "Auto", "the default Method is %s" % chosen.Method)
data = servermanager.Fetch(chosen, idx=0)
choice = data.GetFieldData().GetAbstractArray("MethodChoice")
check(choice is not None and choice.GetValue(0).startswith("hierarchical: 32 triangles, at most 2048"),
      "MethodChoice: %s" % (choice.GetValue(0) if choice else None))
product = servermanager.Fetch(chosen, idx=1)
check(product.GetCellData().GetArray("QuadraticInterpolant") is not None,
      "auto's hierarchical product has no QuadraticInterpolant")
print("auto: %s" % choice.GetValue(0))

# The progressive solution as ParaView shows it, against the baseline.
solve = Radiosity(Input=box)
solve.Method = "Progressive"
view = CreateRenderView()
view.ViewSize = [400, 400]
view.OrientationAxesVisibility = 0
display = Show(solve, view)
ColorBy(display, ("POINTS", "Radiosity", "Magnitude"))
lut = GetColorTransferFunction("Radiosity")
lut.ApplyPreset("Grayscale", True)
lut.RescaleTransferFunction(0.0, 1.2)  # the walls; the light saturates
# The radiosity alone, without ParaView's headlight shading.
display.Ambient = 1.0
display.Diffuse = 0.0
view.CameraPosition = [0.278, 0.273, -0.8]
view.CameraFocalPoint = [0.278, 0.273, 0.28]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraViewAngle = 39.0
Render(view)
image = os.path.join(output, "TestRadiosityFilters.png")
SaveScreenshot(image, view, ImageResolution=[400, 400])
compare_with_baseline(image, baseline)

finish()
