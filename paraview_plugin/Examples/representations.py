"""The Cornell box solved by three methods and drawn by the plugin's three
representations side by side, saved as a screenshot of the layout.

Usage: pvbatch --force-offscreen-rendering representations.py <Radiosity.so> <output.png>
"""
import sys

from paraview.simple import *  # noqa: F401,F403

LoadPlugin(sys.argv[1], remote=False, ns=globals())
box = CornellBox()

hierarchical = Radiosity(Input=box, Method="Hierarchical")
faceCluster = Radiosity(Input=box, Method="Face Cluster")
# Glossy surfaces for the vector irradiance's Phong lobe.
specular = Calculator(Input=faceCluster, AttributeType="Cell Data", ResultArrayName="Specular",
                      Function="0.5*iHat+0.5*jHat+0.5*kHat")
glossy = Calculator(Input=specular, AttributeType="Cell Data", ResultArrayName="Shininess",
                    Function="30")
meshless = Radiosity(Input=box, Method="Meshless")
panels = [
    (OutputPort(hierarchical, 1), "Radiosity Quadratic Interpolants"),
    (glossy, "Vector Irradiance (glossy)"),
    (meshless, "Meshless Field Splats"),
]

layout = CreateLayout("Radiosity")
# Three equal cells: 1 | (5 | 6).
layout.SplitHorizontal(0, 1.0 / 3.0)
layout.SplitHorizontal(2, 0.5)
for cell, (source, representation) in zip((1, 5, 6), panels):
    view = CreateRenderView()
    layout.AssignView(cell, view)
    view.OrientationAxesVisibility = 0
    display = Show(source, view)
    display.SetRepresentationType(representation)
    display.RadianceExposure = 1.5
    display.RadianceToneMapping = "Reinhard"
    label = Show(Text(Text=representation), view)
    label.WindowLocation = "Upper Center"
    label.FontSize = 14
    view.CameraPosition = [0.278, 0.273, -0.8]
    view.CameraFocalPoint = [0.278, 0.273, 0.28]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 39.0
layout.SetSize(1200, 400)
SaveScreenshot(sys.argv[2], layout, ImageResolution=[1200, 400])
print("wrote", sys.argv[2])
