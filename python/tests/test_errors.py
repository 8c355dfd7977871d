"""Options refused with the command line's messages, interruption, and no leak over many calls."""
import _thread
import json
import threading
import time

import numpy as np
import pytest

import cgal_policies as cp
from conftest import DATA, grid, run_tool

VERTICES, FACES = grid(4)


def tool_message(*options):
    """What the simplify tool says of these options, without its "simplify: " prefix."""
    done = run_tool("simplify", DATA / "cow.obj", "/tmp/never_written.obj", *options)
    assert done.returncode == 2
    return done.stderr.strip().removeprefix("simplify: ")


@pytest.mark.parametrize("keywords, options", [
    ({"policy": "nope"}, ["0.1", "--policy", "nope"]),
    ({"policy": "hausdorff", "tolerance": -1}, ["0.1", "--policy", "hausdorff", "--tolerance", "-1"]),
    ({"policy": "fast", "max_error": 0.01}, ["0.1", "--policy", "fast", "--max-error", "0.01"]),
    ({"ratio": 1.5}, ["1.5"]),
    ({"target_count": 0}, ["--faces", "0"]),
    ({"smooth_method": "cubic"}, ["0.1", "--smooth-method", "cubic"]),
    ({"threads": 2.5}, ["0.1", "--threads", "2.5"]),
    ({"policy": "fast", "prepass": 4}, ["0.1", "--policy", "fast", "--prepass", "4"]),
])
def test_options_are_refused_with_the_command_lines_message(keywords, options):
    with pytest.raises(ValueError) as raised:
        cp.simplify(VERTICES, FACES, **keywords)
    assert str(raised.value) == tool_message(*options)


def test_unknown_keywords_and_bad_values_are_refused():
    with pytest.raises(ValueError, match=r"^unknown option --colour=1.0 \(see --help\)$"):
        cp.simplify(VERTICES, FACES, colour=1)
    with pytest.raises(ValueError, match="give a ratio or --faces, not both"):
        cp.simplify(VERTICES, FACES, target_count=5, target_reduction=0.5)
    with pytest.raises(ValueError, match=r"target_reduction must be a number in \[0, 1\)"):
        cp.simplify(VERTICES, FACES, target_reduction=1)
    with pytest.raises(TypeError):
        cp.simplify(VERTICES, FACES, tolerance=[1])


def test_ctrl_c_stops_a_run_and_the_next_one_runs():
    bunny = cp.read(DATA / "bunny.obj")
    seen = []

    def ctrl_c_once_the_run_goes_on():  # it runs without the GIL between the calls of progress
        while len(seen) < 2:
            time.sleep(0.001)
        _thread.interrupt_main()

    threading.Thread(target=ctrl_c_once_the_run_goes_on).start()
    with pytest.raises(KeyboardInterrupt):
        cp.simplify(bunny, ratio=0.01, policy="lt", progress=seen.append)
    assert seen[-1] < 0.5  # far from done: it stopped where it was
    _, report = cp.simplify(cp.Mesh(VERTICES, FACES), target_count=8, policy="classic")
    assert report["stop_reason"] == "target_reached"


def test_an_exception_in_progress_stops_the_run():
    def progress(fraction):
        raise RuntimeError(f"stopped at {fraction}")

    with pytest.raises(RuntimeError, match="stopped at"):
        cp.simplify(cp.read(DATA / "cow.obj"), ratio=0.01, policy="lt", progress=progress)


def resident_kib():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * 4


def test_no_leak_over_a_thousand_calls():
    vertices, faces = grid(12)  # 288 faces
    uv = vertices[faces][:, :, :2] / 12
    mesh = cp.Mesh(vertices, faces, uv=uv)

    def calls(n):
        for i in range(n):
            cp.simplify(vertices, faces, target_count=40, policy="lt", progress=lambda f: None)
            simplified, _ = cp.simplify(mesh, target_count=40, policy="classic")
            assert simplified.uv is not None
            with pytest.raises(ValueError):
                cp.simplify(vertices, faces, policy="nope")

    calls(100)  # the allocator's pools and Python's caches settle first
    before = resident_kib()
    calls(1000)
    # A leak of a single input's mesh (about 60 KiB) per call would add some 60 MiB.
    assert resident_kib() - before < 4096


def _gltf_naming(path, uri):
    """A glTF file at `path`: one triangle, its points in the buffer file `uri` names."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps({
        "asset": {"version": "2.0"},
        "buffers": [{"uri": uri, "byteLength": 36}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0}))
    return path


def test_a_file_reads_nothing_outside_its_folder_unless_a_root_widens_it(tmp_path):
    np.array([0, 0, 0, 1, 0, 0, 0, 1, 0], dtype="<f4").tofile(tmp_path / "common.bin")
    gltf = _gltf_naming(tmp_path / "asset" / "model.gltf", "../common.bin")
    with pytest.raises(ValueError, match=r"a buffer's uri '\.\./common\.bin' leads outside the "
                                         r"asset's folder"):
        cp.read(gltf)
    assert cp.read(gltf, asset_root=tmp_path).faces.shape == (1, 3)
    outside = _gltf_naming(tmp_path / "asset" / "deeper" / "model.gltf", "../../../common.bin")
    with pytest.raises(ValueError, match="leads outside the asset's folder"):
        cp.read(outside, asset_root=tmp_path)
