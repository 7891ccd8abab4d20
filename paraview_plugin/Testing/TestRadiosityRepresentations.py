"""pvbatch test of the Radiosity plugin's representations: the Cornell box
solved by each method and shown with the representation drawing it
("Radiosity Quadratic Interpolants", "Vector Irradiance (glossy)",
"Meshless Field Splats", "Radiosity Element Samples"), each screenshot against its baseline; the
representation properties (exposure, tone mapping) and the glossy arrays
changing the image; input a representation cannot draw giving an error that
names what is missing.

Usage: pvbatch --force-offscreen-rendering TestRadiosityRepresentations.py
           <plugin.so> <baseline dir> <output dir>
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview.simple import *  # noqa: E402,F401,F403
from radiosity_pvtest import (  # noqa: E402
    CapturedMessages, check, compare_with_baseline, finish, read_png)

LoadPlugin(sys.argv[1], remote=False, ns=globals())
baselines, output = sys.argv[2], sys.argv[3]

view = CreateRenderView()
view.ViewSize = [400, 400]
view.OrientationAxesVisibility = 0
view.CameraPosition = [0.278, 0.273, -0.8]
view.CameraFocalPoint = [0.278, 0.273, 0.28]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraViewAngle = 39.0


def screenshot(name):
    Render(view)
    path = os.path.join(output, "TestRadiosityRepresentations_%s.png" % name)
    SaveScreenshot(path, view, ImageResolution=[400, 400])
    return path


def shown(source, representation):
    display = Show(source, view)
    display.SetRepresentationType(representation)
    return display


def mean(path):
    return read_png(path).mean()


def mean_difference(a, b):
    return abs(read_png(a) - read_png(b)).mean()


def check_image(name, path):
    """Against the baseline, and neither black nor flat."""
    pixels = read_png(path)
    print("%s: mean %.1f, deviation %.1f" % (name, pixels.mean(), pixels.std()))
    check(pixels.mean() > 40.0 and pixels.std() > 20.0, "%s: black or flat image" % name)
    compare_with_baseline(path, os.path.join(baselines, os.path.basename(path)))


def check_exposure(display, what, shot, name, exposure):
    """Radiance Exposure `exposure` (2 or 0.5) moves the mean of `shot` by
    more than 5 in its direction; returns the new screenshot."""
    display.RadianceExposure = exposure
    changed = screenshot(name)
    print("%s exposure 1 -> %g: mean %.1f -> %.1f" % (what, exposure, mean(shot), mean(changed)))
    moved = mean(changed) - mean(shot)
    check(moved > 5.0 if exposure > 1.0 else moved < -5.0,
          "Radiance Exposure %g did not %s the %s" % (exposure, "brighten" if exposure > 1.0 else "darken", what))
    return changed


box = CornellBox()

# Hardt and Teller: the discontinuity mesh's quadratic interpolants.
hierarchical = Radiosity(Input=box)
hierarchical.Method = "Hierarchical"
mesh = OutputPort(hierarchical, 1)  # the Product output: the discontinuity mesh
display = shown(mesh, "Radiosity Quadratic Interpolants")
check(display.RadianceExposure == 1.0 and display.RadianceToneMapping == "Clamp",
      "unexpected defaults %s %s" % (display.RadianceExposure, display.RadianceToneMapping))
interpolants = screenshot("QuadraticInterpolants")
check_image("quadratic interpolants", interpolants)
brighter = check_exposure(display, "interpolants", interpolants, "QuadraticInterpolantsExposure2", 2.0)
display.RadianceToneMapping = "Reinhard"
reinhard = screenshot("QuadraticInterpolantsReinhard")
print("clamp -> Reinhard at exposure 2: mean difference %.1f" % mean_difference(brighter, reinhard))
check(mean_difference(brighter, reinhard) > 1.0, "Radiance Tone Mapping Reinhard changed nothing")
display.RadianceToneMapping = "Clamp"
display.RadianceExposure = 1.0
Hide(mesh, view)

# Gobbetti et al.: the face cluster solution's vector irradiance, glossy.
faceCluster = Radiosity(Input=box)
faceCluster.Method = "Face Cluster"
display = shown(faceCluster, "Vector Irradiance (glossy)")
diffuse = screenshot("VectorIrradianceDiffuse")
Hide(faceCluster, view)
specular = Calculator(Input=faceCluster, AttributeType="Cell Data", ResultArrayName="Specular",
                      Function="0.5*iHat+0.5*jHat+0.5*kHat")
glossy = Calculator(Input=specular, AttributeType="Cell Data", ResultArrayName="Shininess",
                    Function="30")
display = shown(glossy, "Vector Irradiance (glossy)")
vector = screenshot("VectorIrradiance")
check_image("vector irradiance", vector)
print("diffuse -> glossy: mean difference %.1f" % mean_difference(diffuse, vector))
check(mean_difference(diffuse, vector) > 2.0, "Specular and Shininess changed nothing")
Hide(glossy, view)

# Lehtinen et al.: the meshless field's splats; the exposure reaches this
# representation too (the properties are shared).
meshless = Radiosity(Input=box)
meshless.Method = "Meshless"
display = shown(meshless, "Meshless Field Splats")
splats = screenshot("ShepardSplats")
check_image("meshless field splats", splats)
check_exposure(display, "splats", splats, "ShepardSplatsExposure05", 0.5)
display.RadianceExposure = 1.0
Hide(meshless, view)

# Coombe et al.'s texel display: the progressive solution's elements, each
# from its own corner and centroid samples.
progressive = Radiosity(Input=box)
progressive.Method = "Progressive"
display = shown(progressive, "Radiosity Element Samples")
samples = screenshot("ElementSamples")
check_image("element samples", samples)
check_exposure(display, "samples", samples, "ElementSamplesExposure2", 2.0)
display.RadianceExposure = 1.0
Hide(progressive, view)

# What a representation cannot draw: an error naming what is missing.
with CapturedMessages() as messages:
    display = shown(progressive, "Radiosity Quadratic Interpolants")
    screenshot("Refused")
check("QuadraticInterpolant" in messages.text,
      "no error naming QuadraticInterpolant: %r" % messages.text[:300])
Hide(progressive, view)
with CapturedMessages() as messages:
    display = shown(faceCluster, "Meshless Field Splats")
    screenshot("Refused")
check("Method Meshless" in messages.text, "no error naming Method Meshless: %r" % messages.text[:300])
Hide(faceCluster, view)

finish()
