#!/usr/bin/env python3
"""Writes the small glTF 2.0 test scenes of the importer path (Python's
standard library only; the files are committed, this script is how they
were made):

- gltf_point_floor.gltf: a 4 m x 4 m black floor at y = 0 facing +y (glTF is
  y-up; baseColorFactor 0, metallicFactor 0, not doubleSided) under a
  KHR_lights_punctual point light of intensity 2 (colour (1, 0.5, 0.25)) at
  (0, 1, 0), placed by a parent node translated by (0, 0.5, 0) and its child
  by (0, 0.5, 0); a camera looking at the floor. Direct light only: the
  irradiance at (x, 0, z) is I h / d^3 = I / (x^2 + z^2 + 1)^1.5 per channel.
  Also as gltf_point_floor.glb (binary: the buffers in the BIN chunk) and
  gltf_truncated.glb (that file cut after 300 bytes, inside its JSON chunk).
- gltf_emissive.gltf: the same black floor under a 1 m x 1 m panel at
  y = 1 facing down (-y), emissiveFactor (1, 1, 1) (1 W/m^2 radiant exitance
  through the filter's LightScale 1 for glTF), no light: the irradiance below
  it is the exitance times the point-to-parallel-rectangle form factor.

Usage: make_gltf_scenes.py OUTPUT_DIR
"""
import base64
import json
import os
import struct
import sys


def buffer_of(positions, indices):
    """Positions (float32 triples) then uint16 indices, as a data: URI."""
    data = b"".join(struct.pack("<3f", *p) for p in positions)
    data += b"".join(struct.pack("<H", i) for i in indices)
    if len(data) % 4:
        data += b"\0" * (4 - len(data) % 4)
    return data


class Gltf:
    def __init__(self):
        self.g = {"asset": {"version": "2.0", "generator": "make_gltf_scenes.py"},
                  "buffers": [], "bufferViews": [], "accessors": [], "meshes": [],
                  "materials": [], "nodes": [], "scenes": [{"nodes": []}], "scene": 0}

    def material(self, name, base, emissive=(0, 0, 0)):
        self.g["materials"].append({"name": name, "pbrMetallicRoughness": {
            "baseColorFactor": list(base) + [1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0},
            "emissiveFactor": list(emissive)})
        return len(self.g["materials"]) - 1

    def mesh(self, name, positions, indices, material):
        data = buffer_of(positions, indices)
        b = len(self.g["buffers"])
        self.g["buffers"].append({"byteLength": len(data),
                                  "uri": "data:application/octet-stream;base64," +
                                  base64.b64encode(data).decode()})
        v = len(self.g["bufferViews"])
        self.g["bufferViews"] += [
            {"buffer": b, "byteOffset": 0, "byteLength": 12 * len(positions)},
            {"buffer": b, "byteOffset": 12 * len(positions), "byteLength": 2 * len(indices)}]
        a = len(self.g["accessors"])
        self.g["accessors"] += [
            {"bufferView": v, "componentType": 5126, "count": len(positions), "type": "VEC3",
             "min": [min(p[k] for p in positions) for k in range(3)],
             "max": [max(p[k] for p in positions) for k in range(3)]},
            {"bufferView": v + 1, "componentType": 5123, "count": len(indices), "type": "SCALAR"}]
        self.g["meshes"].append({"name": name, "primitives": [
            {"attributes": {"POSITION": a}, "indices": a + 1, "material": material}]})
        self.node({"name": name, "mesh": len(self.g["meshes"]) - 1})

    def node(self, node, root=True):
        self.g["nodes"].append(node)
        if root:
            self.g["scenes"][0]["nodes"].append(len(self.g["nodes"]) - 1)
        return len(self.g["nodes"]) - 1

    def lights(self, lights):
        self.g["extensionsUsed"] = ["KHR_lights_punctual"]
        self.g["extensions"] = {"KHR_lights_punctual": {"lights": lights}}

    def camera(self, position, rotation, yfov):
        self.g["cameras"] = [{"type": "perspective",
                              "perspective": {"yfov": yfov, "znear": 0.01, "aspectRatio": 1.0}}]
        self.node({"name": "camera", "camera": 0, "translation": position, "rotation": rotation})

    def write(self, path):
        with open(path, "w") as f:
            json.dump(self.g, f)
            f.write("\n")

    def write_glb(self, path, cut=None):
        """The same scene as a binary glTF: its buffers joined into the BIN
        chunk; `cut`: keep only that many bytes (a truncated file)."""
        g = json.loads(json.dumps(self.g))
        binary = b""
        offsets = []
        for b in g["buffers"]:
            offsets.append(len(binary))
            binary += base64.b64decode(b["uri"].split(",", 1)[1])
        for v in g["bufferViews"]:
            v["byteOffset"] = v.get("byteOffset", 0) + offsets[v["buffer"]]
            v["buffer"] = 0
        g["buffers"] = [{"byteLength": len(binary)}]
        text = json.dumps(g).encode()
        text += b" " * (-len(text) % 4)
        binary += b"\0" * (-len(binary) % 4)
        data = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(binary))
        data += struct.pack("<II", len(text), 0x4E4F534A) + text
        data += struct.pack("<II", len(binary), 0x004E4942) + binary
        with open(path, "wb") as f:
            f.write(data if cut is None else data[:cut])


def floor(g):
    black = g.material("black floor", (0, 0, 0))
    # Counter-clockwise seen from +y: the front face looks up.
    g.mesh("floor", [(-2, 0, -2), (-2, 0, 2), (2, 0, 2), (2, 0, -2)], [0, 1, 2, 0, 2, 3], black)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    # Looking down at the floor from (0, 3, 3), 45 degrees below the horizon.
    down = [-0.38268343236508984, 0, 0, 0.9238795325112867]

    g = Gltf()
    floor(g)
    g.lights([{"type": "point", "name": "bulb", "color": [1, 0.5, 0.25], "intensity": 2}])
    parent = g.node({"name": "lamp holder", "translation": [0, 0.5, 0], "children": []})
    child = g.node({"name": "lamp", "translation": [0, 0.5, 0],
                    "extensions": {"KHR_lights_punctual": {"light": 0}}}, root=False)
    g.g["nodes"][parent]["children"].append(child)
    g.camera([0, 3, 3], down, 0.8)
    g.write(os.path.join(out, "gltf_point_floor.gltf"))
    g.write_glb(os.path.join(out, "gltf_point_floor.glb"))
    g.write_glb(os.path.join(out, "gltf_truncated.glb"), cut=300)

    g = Gltf()
    floor(g)
    glow = g.material("panel", (0, 0, 0), emissive=(1, 1, 1))
    # Clockwise seen from +y: the front face looks down at the floor.
    g.mesh("panel", [(-0.5, 1, -0.5), (0.5, 1, -0.5), (0.5, 1, 0.5), (-0.5, 1, 0.5)],
           [0, 1, 2, 0, 2, 3], glow)
    g.camera([0, 3, 3], down, 0.8)
    g.write(os.path.join(out, "gltf_emissive.gltf"))


if __name__ == "__main__":
    main()
