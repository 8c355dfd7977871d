#!/usr/bin/env python3
"""Splits every triangle of a binary little-endian PLY (float x y z, uchar/int index lists) in
four at its edge midpoints, shared between neighbours, so the result stays as clean as the input.
Makes the large inputs of the reader benchmark: data/dragon.ply becomes 3.5M faces.

usage: scripts/split_in_four.py IN.ply OUT.ply
"""
import struct
import sys


def read_body(path, verb):
    """The bytes of a binary little-endian PLY, where its body starts, and its vertex and face
    counts; `verb` says what this script does with it, for the error."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").split("\n")
    if "format binary_little_endian 1.0" not in header:
        sys.exit(f"{path}: only binary little-endian PLY is {verb}")
    counts = {line.split()[1]: int(line.split()[2]) for line in header if line.startswith("element")}
    return data, end, counts["vertex"], counts["face"]


def ply_header(vertex_count, face_count, comment=""):
    """The header of a binary PLY of float x y z and uchar/int index lists."""
    return (f"ply\nformat binary_little_endian 1.0\n{comment}element vertex {vertex_count}\n"
            "property float x\nproperty float y\nproperty float z\n"
            f"element face {face_count}\nproperty list uchar int vertex_indices\n"
            "end_header\n").encode("ascii")


def read_ply(path):
    data, end, vertex_count, face_count = read_body(path, "split")
    points = list(struct.iter_unpack("<3f", data[end:end + 12 * vertex_count]))
    faces, at = [], end + 12 * vertex_count
    for _ in range(face_count):
        if data[at] != 3:
            sys.exit(f"{path}: only triangles are split")
        faces.append(struct.unpack_from("<3i", data, at + 1))
        at += 13
    return points, faces


def split(points, faces):
    midpoint_of = {}

    def midpoint(a, b):
        key = (a, b) if a < b else (b, a)
        if key not in midpoint_of:
            pa, pb = points[a], points[b]
            midpoint_of[key] = len(points)
            points.append(tuple((x + y) / 2 for x, y in zip(pa, pb)))
        return midpoint_of[key]

    out = []
    for a, b, c in faces:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return points, out


def write_ply(path, points, faces):
    with open(path, "wb") as f:
        f.write(ply_header(len(points), len(faces)))
        f.write(b"".join(struct.pack("<3f", *p) for p in points))
        f.write(b"".join(struct.pack("<B3i", 3, *t) for t in faces))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    write_ply(sys.argv[2], *split(*read_ply(sys.argv[1])))
