"""examples/textured_to_gltf.py does what it says on spot."""
import subprocess
import sys

import cgal_policies as cp
from conftest import DATA, REPO


def test_the_example_writes_a_textured_gltf(tmp_path):
    out = tmp_path / "spot.glb"
    done = subprocess.run([sys.executable, str(REPO / "examples" / "textured_to_gltf.py"),
                           str(DATA / "spot.obj"), str(out)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("5856 -> 586 faces, attributes carried; mean error ")
    assert cp.read(out).uv is not None
