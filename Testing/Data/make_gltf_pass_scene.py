#!/usr/bin/env pvpython
"""Writes Testing/Data/gltf_pass_scene.gltf: the scene of vtkRadiosityPass's
tests (Rendering/SceneGraph/Testing/Cxx/PassTestScene.h) exported by
vtkGLTFExporter (ParaView's VTK 9.2, run with pvpython; no display needed),
then lit in its JSON with the pass's two lights as vtkRadiosityPass maps
them at its default LightScale pi (the exporter writes no lights):

- an open room (z up, metres): a 4 m x 4 m floor (resolution 4, colour
  0.8), a back wall at y = 2 (0.75, 0.35, 0.3) and a left wall at x = -2
  (0.3, 0.65, 0.35), 2.5 m high, resolution 3;
- a 0.8 m box (0.85, 0.75, 0.3) placed by its actor's transform (position
  (0.8, 0.5, 0.4), turned 30 degrees about z): the exporter writes it as
  the node's matrix;
- a sphere (radius 0.5 at (-0.8, -0.4, 0.5), 12 x 8, (0.35, 0.45, 0.85));
- the spot: vtkLight at (0.2, 0.2, 2.4) towards (0.2, 0.2, 0), ConeAngle 40,
  Intensity 4 -> KHR spot, intensity 4 pi W/sr, innerConeAngle 0,
  outerConeAngle 40 degrees; the sun: a directional vtkLight from
  (2, -3, 4) towards the origin, colour (1, 0.95, 0.85), Intensity 0.6 ->
  KHR directional, intensity 0.6 pi W/m^2, travelling along (-2, 3, -4);
- the pass tests' camera.

Usage: pvpython make_gltf_pass_scene.py [OUTPUT_DIR]
"""
import json
import math
import os
import sys

from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource, vtkSphereSource

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_gltf_image_scene import actor, add_light_nodes, export, rotation_from_minus_z, setup  # noqa: E402


def plane(origin, p1, p2, resolution, colour, renderer):
    p = vtkPlaneSource()
    p.SetOrigin(*origin)
    p.SetPoint1(*p1)
    p.SetPoint2(*p2)
    p.SetResolution(resolution, resolution)
    return actor(p, colour, renderer)


def main():
    out, window, renderer = setup()

    plane((-2, -2, 0), (2, -2, 0), (-2, 2, 0), 4, (0.8, 0.8, 0.8), renderer)
    plane((-2, 2, 0), (2, 2, 0), (-2, 2, 2.5), 3, (0.75, 0.35, 0.3), renderer)
    plane((-2, -2, 0), (-2, 2, 0), (-2, -2, 2.5), 3, (0.3, 0.65, 0.35), renderer)
    cube = vtkCubeSource()
    cube.SetXLength(0.8)
    cube.SetYLength(0.8)
    cube.SetZLength(0.8)
    box = actor(cube, (0.85, 0.75, 0.3), renderer)
    box.SetPosition(0.8, 0.5, 0.4)
    box.RotateZ(30.0)
    ball = vtkSphereSource()
    ball.SetCenter(-0.8, -0.4, 0.5)
    ball.SetRadius(0.5)
    ball.SetThetaResolution(12)
    ball.SetPhiResolution(8)
    actor(ball, (0.35, 0.45, 0.85), renderer)

    camera = renderer.GetActiveCamera()
    camera.SetPosition(3.6, -4.6, 3.0)
    camera.SetFocalPoint(-0.1, 0.3, 0.6)
    camera.SetViewUp(0.0, 0.0, 1.0)
    camera.SetViewAngle(40.0)

    path = os.path.join(out, "gltf_pass_scene.gltf")
    g = export(window, path)
    g["asset"]["generator"] = "VTK vtkGLTFExporter, lights added by make_gltf_pass_scene.py"
    add_light_nodes(g, [
        {"type": "spot", "name": "spot", "intensity": 4 * math.pi,
         "spot": {"innerConeAngle": 0.0, "outerConeAngle": math.radians(40.0)}},
        {"type": "directional", "name": "sun", "intensity": 0.6 * math.pi,
         "color": [1.0, 0.95, 0.85]}],
        [{"name": "spot", "translation": [0.2, 0.2, 2.4]},
         {"name": "sun", "rotation": rotation_from_minus_z([-2.0, 3.0, -4.0])}])
    with open(path, "w") as f:
        json.dump(g, f)
        f.write("\n")


if __name__ == "__main__":
    main()
