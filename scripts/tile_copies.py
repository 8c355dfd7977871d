#!/usr/bin/python3
"""Writes N copies of a binary little-endian PLY of triangles (float x y z, uchar count and int
indices) side by side in a grid, as one PLY, streaming: one copy in memory at a time. With
split_in_four.py it makes the inputs of more than 100M faces of the scale benchmark from shipped
data (docs/scale.md): the dragon split twice, in eight copies, is 111.5M faces.

usage: scripts/tile_copies.py IN.ply OUT.ply N
"""
import math
import sys

import numpy as np

from split_in_four import ply_header, read_body


def read_ply(path):
    data, end, vertex_count, face_count = read_body(path, "tiled")
    points = np.frombuffer(data, dtype="<f4", count=3 * vertex_count, offset=end)
    faces = np.frombuffer(data, dtype=np.dtype([("n", "u1"), ("v", "<i4", 3)]), count=face_count,
                          offset=end + 12 * vertex_count)
    if np.any(faces["n"] != 3):
        sys.exit(f"{path}: only triangles are tiled")
    return points.reshape(-1, 3), faces


def main():
    if len(sys.argv) != 4 or not sys.argv[3].isdigit() or int(sys.argv[3]) < 1:
        sys.exit("usage: scripts/tile_copies.py IN.ply OUT.ply N")
    points, faces = read_ply(sys.argv[1])
    copies = int(sys.argv[3])
    side = math.ceil(math.sqrt(copies))
    step = 1.1 * (points.max(axis=0) - points.min(axis=0))
    with open(sys.argv[2], "wb") as out:
        out.write(ply_header(copies * len(points), copies * len(faces),
                             f"comment {copies} copies of {sys.argv[1]} (scripts/tile_copies.py)\n"))
        for c in range(copies):
            offset = np.array([step[0] * (c % side), step[1] * (c // side), 0], dtype="<f4")
            out.write((points + offset).astype("<f4").tobytes())
        for c in range(copies):
            moved = faces.copy()
            moved["v"] += c * len(points)
            out.write(moved.tobytes())


if __name__ == "__main__":
    main()
