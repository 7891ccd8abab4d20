#!/usr/bin/env python3
"""Writes the two small 3D Studio files of the importer path's tests (Python's
standard library only; the files are committed, this script is how they were
made): a chunk tree main (0x4D4D) > editor (0x3D3D) > object 'tri' (0x4000) >
triangle mesh (0x4100) with a vertex list (0x4110: (0, 0, 0), (1, 0, 0),
(0, 1, 0)) and a face list (0x4120: one face).

- 3ds_triangle.3ds: the face (0, 1, 2), a right triangle in z = 0 facing +z.
- 3ds_face_out_of_range.3ds: the face (0, 1, 60000), an index past the three
  vertices: vtk3DSImporter (VTK 9.2) crashes on it (in vtkStripper's links),
  which the command line must refuse, not crash on.

Usage: make_3ds_files.py [OUTPUT_DIR]
"""
import os
import struct
import sys


def chunk(identifier, payload):
    return struct.pack("<HI", identifier, 6 + len(payload)) + payload


def triangle_file(third_index):
    vertices = struct.pack("<H", 3) + b"".join(
        struct.pack("<3f", *v) for v in [(0, 0, 0), (1, 0, 0), (0, 1, 0)])
    faces = struct.pack("<H", 1) + struct.pack("<4H", 0, 1, third_index, 0)
    mesh = chunk(0x4100, chunk(0x4110, vertices) + chunk(0x4120, faces))
    return chunk(0x4D4D, chunk(0x3D3D, chunk(0x4000, b"tri\0" + mesh)))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(out, "3ds_triangle.3ds"), "wb") as f:
        f.write(triangle_file(2))
    with open(os.path.join(out, "3ds_face_out_of_range.3ds"), "wb") as f:
        f.write(triangle_file(60000))


if __name__ == "__main__":
    main()
