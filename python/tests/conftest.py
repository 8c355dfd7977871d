"""Where the tests find the shipped meshes and the built tools (CTest sets both)."""
import os
import pathlib
import subprocess

import numpy as np
import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
DATA = pathlib.Path(os.environ.get("CGAL_POLICIES_DATA", REPO / "data"))
BIN = pathlib.Path(os.environ.get("CGAL_POLICIES_BIN", REPO / "build" / "bin"))


@pytest.fixture
def data():
    return DATA


def run_tool(name, *args):
    """Runs a built tool; its completed process (exit code, stdout, stderr)."""
    return subprocess.run([str(BIN / name), *map(str, args)], capture_output=True, text=True)


def grid(n):
    """A flat n x n grid of unit squares in z = 0, two triangles each: (n + 1)^2 vertices."""
    xs, ys = np.meshgrid(np.arange(n + 1, dtype=float), np.arange(n + 1, dtype=float))
    vertices = np.column_stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)])
    faces = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            faces += [[a, a + 1, a + n + 2], [a, a + n + 2, a + n + 1]]
    return vertices, np.array(faces, dtype=np.int64)
