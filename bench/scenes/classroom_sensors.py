#!/usr/bin/env python3
"""Sensors on the surfaces of the classroom (../shared/scenes/classroom), for
the real-interior bench (issue 53): N points drawn by area over the triangles
inside the room (the ground plane outside and anything beyond the room's
walls left out), each offset 0.1 mm along its triangle's normal (on the surface by the
methods' rule: within 1e-6 of the scene's 320 m diagonal) so that the
path tracer and every method see the same side. Deterministic (a fixed
seed). Writes the SPEC probe CSV x,y,z,nx,ny,nz to stdout.

usage: classroom_sensors.py CLASSROOM.gltf [N]"""
import json
import math
import os
import random
import struct
import sys

path = sys.argv[1]
count = int(sys.argv[2]) if len(sys.argv) > 2 else 48
g = json.load(open(path))
blobs = [open(os.path.join(os.path.dirname(path), b["uri"]), "rb").read() for b in g["buffers"]]


def accessor(i):
    a = g["accessors"][i]
    view = g["bufferViews"][a["bufferView"]]
    data = blobs[view["buffer"]]
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    width = {"SCALAR": 1, "VEC3": 3}[a["type"]]
    fmt = {5126: "f", 5125: "I", 5123: "H"}[a["componentType"]]
    size = struct.calcsize(fmt)
    stride = view.get("byteStride", size * width)
    return [struct.unpack_from("<" + fmt * width, data, start + k * stride) for k in range(a["count"])]


triangles = []  # (a, b, c, area, normal)
for node in g["nodes"]:
    if "mesh" not in node:
        continue
    for prim in g["meshes"][node["mesh"]]["primitives"]:
        p = accessor(prim["attributes"]["POSITION"])
        idx = [i[0] for i in accessor(prim["indices"])]
        for k in range(0, len(idx), 3):
            a, b, c = p[idx[k]], p[idx[k + 1]], p[idx[k + 2]]
            u = [b[j] - a[j] for j in range(3)]
            v = [c[j] - a[j] for j in range(3)]
            n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
            length = math.sqrt(sum(x * x for x in n))
            if length <= 0:
                continue
            triangles.append((a, b, c, 0.5 * length, [x / length for x in n]))

# The room: the box of its walls (x in [-4.6, 4.6], y in [0, 3.1], z in
# [-6.0, 6.0] m); the ground plane and what stands outside are beyond it.
lo, hi = (-4.6, -0.01, -6.0), (4.6, 3.1, 6.0)


def inside(t):
    return all(lo[j] <= t[k][j] <= hi[j] for k in range(3) for j in range(3))


room = [t for t in triangles if inside(t)]
total = sum(t[3] for t in room)
rng = random.Random(53)
print("x,y,z,nx,ny,nz")
for _ in range(count):
    pick = rng.uniform(0, total)
    for t in room:
        pick -= t[3]
        if pick <= 0:
            break
    r1, r2 = rng.random(), rng.random()
    s = math.sqrt(r1)
    w = [1 - s, s * (1 - r2), s * r2]
    x = [sum(w[k] * t[k][j] for k in range(3)) + 1e-4 * t[4][j] for j in range(3)]
    print(",".join("%.6f" % v for v in x + t[4]))
