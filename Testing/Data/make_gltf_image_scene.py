#!/usr/bin/env pvpython
"""Writes Testing/Data/gltf_room.gltf, the scene of the importer path's image
test: a small VTK scene exported by vtkGLTFExporter (ParaView's VTK 9.2, run
with pvpython; no display needed), then lit in its JSON (the exporter writes
no lights).

The VTK scene (y up, metres): a 4 m x 4 m floor at y = 0 (reflectance 0.5),
a back wall at z = -2 (0.6), a red box (0.8 m, (0.7, 0.2, 0.2)) and a sphere
(radius 0.4 m, (0.2, 0.3, 0.7)); the camera at (0, 2, 5) looking at
(0, 0.6, -0.5), 40 degrees. Added to the JSON: KHR_lights_punctual with a
point light of 8 W/sr at (0, 2.5, 1) and a spot of 20 W/sr at (1.5, 2.5,
1.5) pointing at the box (inner cone 0.3 rad, outer 0.5: solved from the
file's values, a vtkLight has one cone), each on a node of its own.

Usage: pvpython make_gltf_image_scene.py [OUTPUT_DIR]
"""
import json
import math
import os
import sys

from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkIOExport import vtkGLTFExporter
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the render window and actors' classes)


def actor(source, colour, renderer):
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(source.GetOutputPort())
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(triangles.GetOutputPort())
    a = vtkActor()
    a.SetMapper(mapper)
    a.GetProperty().SetColor(*colour)
    renderer.AddActor(a)
    return a


def setup():
    """The output folder (the first argument, else this script's) and an
    offscreen window with its renderer."""
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    renderer = vtkRenderer()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    return out, window, renderer


def rotation_from_minus_z(d):
    """The quaternion (x, y, z, w) of the shortest rotation taking (0, 0, -1) onto d."""
    n = math.sqrt(sum(c * c for c in d))
    d = [c / n for c in d]
    axis = [0 * d[2] - (-1) * d[1], (-1) * d[0] - 0 * d[2], 0 * d[1] - 0 * d[0]]
    cos = -d[2]
    w = math.sqrt((1 + cos) / 2)
    s = 1 / (2 * w)
    return [axis[0] * s, axis[1] * s, axis[2] * s, w]


def export(window, path):
    """Writes the window's scene to `path` with vtkGLTFExporter (data inline)
    and returns the file's JSON, for the lights to be added."""
    exporter = vtkGLTFExporter()
    exporter.SetRenderWindow(window)
    exporter.SetFileName(path)
    exporter.InlineDataOn()
    exporter.Write()
    with open(path) as f:
        return json.load(f)


def add_light_nodes(g, lights, nodes):
    """Adds KHR_lights_punctual `lights` to the glTF JSON `g`, and a root node
    per light (`nodes`: name, translation and rotation as glTF has them)."""
    g["extensionsUsed"] = ["KHR_lights_punctual"]
    g["extensions"] = {"KHR_lights_punctual": {"lights": lights}}
    scene = g["scenes"][g.get("scene", 0)]["nodes"]
    for index, node in enumerate(nodes):
        node = dict(node)
        node["extensions"] = {"KHR_lights_punctual": {"light": index}}
        g["nodes"].append(node)
        scene.append(len(g["nodes"]) - 1)


def main():
    out, window, renderer = setup()

    floor = vtkPlaneSource()  # right-hand normal (P1 - O) x (P2 - O) = +y
    floor.SetOrigin(-2, 0, 2)
    floor.SetPoint1(2, 0, 2)
    floor.SetPoint2(-2, 0, -2)
    actor(floor, (0.5, 0.5, 0.5), renderer)
    wall = vtkPlaneSource()  # +z
    wall.SetOrigin(-2, 0, -2)
    wall.SetPoint1(2, 0, -2)
    wall.SetPoint2(-2, 2.5, -2)
    actor(wall, (0.6, 0.6, 0.6), renderer)
    box = vtkCubeSource()
    box.SetCenter(-0.6, 0.4, -0.4)
    box.SetXLength(0.8)
    box.SetYLength(0.8)
    box.SetZLength(0.8)
    actor(box, (0.7, 0.2, 0.2), renderer)
    sphere = vtkSphereSource()
    sphere.SetCenter(0.7, 0.4, 0.3)
    sphere.SetRadius(0.4)
    sphere.SetThetaResolution(16)
    sphere.SetPhiResolution(12)
    actor(sphere, (0.2, 0.3, 0.7), renderer)

    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, 2, 5)
    camera.SetFocalPoint(0, 0.6, -0.5)
    camera.SetViewUp(0, 1, 0)
    camera.SetViewAngle(40)

    path = os.path.join(out, "gltf_room.gltf")
    g = export(window, path)
    g["asset"]["generator"] = "VTK vtkGLTFExporter, lights added by make_gltf_image_scene.py"
    # A spot points along its node's -z: a rotation taking -z onto the box.
    at, to = (1.5, 2.5, 1.5), (-0.6, 0.4, -0.4)
    add_light_nodes(g, [
        {"type": "point", "name": "ceiling lamp", "intensity": 8},
        {"type": "spot", "name": "spot on the box", "intensity": 20,
         "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.5}}],
        [{"name": "lamp", "translation": [0, 2.5, 1]},
         {"name": "spot", "translation": list(at),
          "rotation": rotation_from_minus_z([t - a for t, a in zip(to, at)])}])
    with open(path, "w") as f:
        json.dump(g, f)
        f.write("\n")


if __name__ == "__main__":
    main()
