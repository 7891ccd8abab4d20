"""A small lit room in ParaView's Radiosity Render View: a floor and two
walls from Plane sources, four shapes, a spot and the sun added as the Light
Inspector adds scene lights, solved by the view's vtkRadiosityPass and saved
as a screenshot. Runs in pvpython (an interactive window) or pvbatch.

Usage: pvbatch --force-offscreen-rendering renderview.py <Radiosity.so> <output.png> [method]
       (method: Meshless, the default, Hierarchical, Progressive or Face Cluster)
"""
import sys
import time

from paraview.simple import *  # noqa: F401,F403

LoadPlugin(sys.argv[1], remote=False, ns=globals())
output = sys.argv[2]
method = sys.argv[3] if len(sys.argv) > 3 else "Meshless"

view = CreateView("RadiosityRenderView")
view.ViewSize = [640, 480]
view.OrientationAxesVisibility = 0
view.Method = method
view.UseColorPaletteForBackground = 0
view.Background = [0.1, 0.1, 0.12]

# Surfaces are one-sided: each plane's normal (Point1 - Origin) x (Point2 -
# Origin) faces into the room.
room = [
    (Plane(Origin=[-2, -2, 0], Point1=[2, -2, 0], Point2=[-2, 2, 0]), [0.75, 0.75, 0.75]),  # floor
    (Plane(Origin=[-2, 2, 0], Point1=[2, 2, 0], Point2=[-2, 2, 2.5]), [0.8, 0.78, 0.7]),    # back wall
    (Plane(Origin=[-2, -2, 0], Point1=[-2, 2, 0], Point2=[-2, -2, 2.5]), [0.7, 0.75, 0.8]),  # left wall
]
shapes = [
    (Box(XLength=0.8, YLength=0.8, ZLength=0.8, Center=[-0.9, 0.8, 0.4]), [0.8, 0.3, 0.2]),
    (Sphere(Radius=0.45, Center=[0.6, 0.2, 0.45], ThetaResolution=32, PhiResolution=24), [0.2, 0.4, 0.8]),
    (Cylinder(Radius=0.3, Height=1.2, Resolution=32), [0.3, 0.7, 0.3]),
    (Cone(Radius=0.35, Height=0.8, Center=[-0.6, -0.8, 0.4], Direction=[0, 0, 1], Resolution=32),
     [0.85, 0.75, 0.2]),
]
for source, colour in room + shapes:
    display = Show(source, view)
    display.DiffuseColor = colour
# The Cylinder source's axis is y: stand it up (an actor transform, which
# the pass applies to the solved points).
cylinder = GetDisplayProperties(shapes[2][0], view)
cylinder.Orientation = [90, 0, 0]
cylinder.Position = [1.0, 1.3, 0.6]

# Scene lights (the Light Inspector's Coords "Scene"): a spot over the
# shapes and the sun low from the front right. The headlight and the light
# kit move with the camera and are not solved.
spot = AddLight(view=view)
spot.Coords = "Scene"
spot.Type = "Positional"
spot.Position = [0.5, -0.5, 2.4]
spot.FocalPoint = [0.0, 0.5, 0.0]
spot.ConeAngle = 40.0
spot.Intensity = 2.5
spot.DiffuseColor = [1.0, 0.9, 0.75]
sun = AddLight(view=view)
sun.Coords = "Scene"
sun.Type = "Directional"
sun.Position = [3.0, -2.0, 2.0]
sun.FocalPoint = [0.0, 0.0, 0.0]
sun.Intensity = 0.6
sun.DiffuseColor = [1.0, 0.95, 0.85]

view.CameraPosition = [3.6, -5.0, 2.6]
view.CameraFocalPoint = [-0.2, 0.4, 0.7]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 36.0
start = time.time()
Render(view)  # solves (the progress bar shows it in the GUI)
solved = time.time() - start
view.CameraPosition = [3.4, -5.2, 2.8]  # a camera move only redraws
start = time.time()
Render(view)
redraw = time.time() - start
SaveScreenshot(output, view, ImageResolution=[640, 480])
view.UpdatePropertyInformation()
print("%s: first image %.2f s, a camera move %.3f s, %d solve(s)"
      % (method, solved, redraw, view.GetPropertyValue("NumberOfSolves")))
print("wrote", output)
