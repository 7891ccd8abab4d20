"""pvbatch test of the Radiosity Render View (vtkPVRadiosityRenderView): a
plane floor, a box and a sphere lit by a scene light added as the Light
Inspector adds it, solved by the view's vtkRadiosityPass; the solve's
progress reaching the session's progress handler; the screenshot against its
baseline, neither black nor flat; a camera move not re-solving; a light move
re-solving once and changing the image (mean pixel difference 31.4
measured, bound 10); the view's Radiosity Exposure at 2 brightening it
without a solve (mean gain 11.4 measured, bound 5); a state file saved and
loaded back with the plugin loaded giving a Radiosity Render View with the
same Method and Tolerance and the same image (mean difference 0.00
measured, bound 2).

Usage: pvbatch --force-offscreen-rendering TestRadiosityRenderView.py
           <plugin.so> <baseline dir> <output dir>
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview import servermanager  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from radiosity_pvtest import check, compare_with_baseline, finish, read_png  # noqa: E402

LoadPlugin(sys.argv[1], remote=False, ns=globals())
baselines, output = sys.argv[2], sys.argv[3]

view = CreateView("RadiosityRenderView")
check(view.GetXMLName() == "RadiosityRenderView", "CreateView gave %s" % view.GetXMLName())
check(view.GetClientSideObject().GetClassName() == "vtkPVRadiosityRenderView",
      "the view's class is %s" % view.GetClientSideObject().GetClassName())
view.ViewSize = [400, 300]
view.OrientationAxesVisibility = 0
view.Method = "Hierarchical"
view.Tolerance = 0.01

floor = Plane(Origin=[-2.0, -2.0, 0.0], Point1=[2.0, -2.0, 0.0], Point2=[-2.0, 2.0, 0.0],
              XResolution=8, YResolution=8)
box = Box(XLength=0.8, YLength=0.8, ZLength=0.8, Center=[-0.6, 0.4, 0.4])
sphere = Sphere(Radius=0.45, Center=[0.7, -0.3, 0.45], ThetaResolution=24, PhiResolution=16)
displays = [Show(source, view) for source in (floor, box, sphere)]
displays[0].DiffuseColor = [0.8, 0.8, 0.8]
displays[1].DiffuseColor = [0.8, 0.3, 0.2]
displays[2].DiffuseColor = [0.2, 0.4, 0.8]

light = AddLight(view=view)
light.Coords = "Scene"
light.Type = "Positional"
light.ConeAngle = 90.0
light.Position = [1.5, -1.0, 2.5]
light.FocalPoint = [0.0, 0.0, 0.0]
light.Intensity = 2.0


def screenshot(name):
    Render(view)
    path = os.path.join(output, "TestRadiosityRenderView_%s.png" % name)
    SaveScreenshot(path, view, ImageResolution=[400, 300])
    return path


def solves():
    view.UpdatePropertyInformation()
    return view.GetPropertyValue("NumberOfSolves")


# The solve's progress reaches the session's progress handler (the progress
# bar) as a filter's does, under the filter's progress text.
progress = []
handler = servermanager.ActiveConnection.Session.GetProgressHandler()
if hasattr(handler, "SetProgressInterval"):
    handler.SetProgressInterval(0.0)
observer = handler.AddObserver(
    "ProgressEvent", lambda caller, event: progress.append(caller.GetLastProgressText()))
# paraview.simple's first Render resets the camera: the view's camera after it.
Render(view)
handler.RemoveObserver(observer)
print("progress events of the solve: %d" % progress.count("Radiosity solve"))
check("Radiosity solve" in progress, "no progress of the solve: %s" % sorted(set(progress)))
view.CameraPosition = [3.2, -4.2, 3.0]
view.CameraFocalPoint = [0.0, 0.0, 0.4]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30.0
first = screenshot("Light")
pixels = read_png(first)
print("first image: mean %.1f, deviation %.1f, solves %d" % (pixels.mean(), pixels.std(), solves()))
# One solve: ParaView's first render moves the representations' mapper
# MTimes once more, but the mapper nodes compare what they convert (the
# same triangles and materials), so that is not a change to solve.
first_solves = solves()
check(first_solves == 1, "the first render solved %d times" % first_solves)
check(pixels.mean() > 30.0 and pixels.std() > 15.0, "black or flat image")
compare_with_baseline(first, os.path.join(baselines, os.path.basename(first)))

# A camera move only redraws.
view.CameraPosition = [3.0, -4.4, 3.1]
Render(view)
check(solves() == first_solves, "a camera move re-solved (%d solves)" % solves())
view.CameraPosition = [3.2, -4.2, 3.0]

# A light move re-solves and changes the image.
light.Position = [-1.8, 1.2, 2.0]
moved = screenshot("LightMoved")
difference = abs(read_png(moved) - pixels).mean()
print("light moved: mean pixel difference %.2f, solves %d" % (difference, solves()))
check(solves() == first_solves + 1, "the light move solved %d times" % (solves() - first_solves))
check(difference > 10.0, "moving the light changed the image by %.2f only" % difference)

# The display's exposure redraws brighter without a solve.
view.RadiosityExposure = 2.0
brighter = screenshot("Exposure")
view.RadiosityExposure = 1.0
gain = read_png(brighter).mean() - read_png(moved).mean()
print("exposure 2: mean pixel gain %.2f, solves %d" % (gain, solves()))
check(solves() == first_solves + 1, "the exposure re-solved (%d solves)" % solves())
check(gain > 5.0, "exposure 2 brightened the image by %.2f only" % gain)

# A state file saved and loaded back.
state = os.path.join(output, "TestRadiosityRenderView.pvsm")
SaveState(state)
ResetSession()
LoadState(state)
views = GetViews()
check(len(views) == 1, "the state has %d views" % len(views))
if views:
    loaded = views[0]
    check(loaded.GetXMLName() == "RadiosityRenderView",
          "the state's view is a %s" % loaded.GetXMLName())
    check(loaded.Method == "Hierarchical", "the state's Method is %s" % loaded.Method)
    check(abs(loaded.Tolerance - 0.01) < 1e-12, "the state's Tolerance is %g" % loaded.Tolerance)
    SetActiveView(loaded)
    Render(loaded)
    reloaded = os.path.join(output, "TestRadiosityRenderView_Reloaded.png")
    SaveScreenshot(reloaded, loaded, ImageResolution=[400, 300])
    # The state's scene, light and camera: the moved light's image again.
    reloaded_difference = abs(read_png(reloaded) - read_png(moved)).mean()
    print("reloaded view: mean pixel difference %.2f from the moved light's image"
          % reloaded_difference)
    check(reloaded_difference < 2.0,
          "the reloaded view's image differs by %.2f" % reloaded_difference)
    loaded.UpdatePropertyInformation()
    reloaded_solves = loaded.GetPropertyValue("NumberOfSolves")
    print("reloaded view: solves %d" % reloaded_solves)
    check(reloaded_solves >= 1, "the reloaded view did not solve")
finish()
