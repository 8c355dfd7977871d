"""simplify() against the simplify tool, exact facts on a grid, the report and the options."""
import json

import numpy as np
import pytest

import cgal_policies as cp
from conftest import grid, run_tool

# Fields of simplify --json that depend on the clock, the files or the process, not on the run.
NOT_OF_THE_RUN = {"input", "output", "seconds", "total_seconds", "faces_removed_per_second",
                  "smooth_seconds", "fit_seconds", "read_seconds", "write_seconds",
                  "peak_memory_mib"}


def tool_run(tmp_path, source, name, *options):
    """The simplify tool's output file bytes and its JSON report."""
    out = tmp_path / name
    done = run_tool("simplify", source, out, *options, "--json", "--quiet")
    assert done.returncode == 0, done.stderr
    return out.read_bytes(), json.loads(done.stdout)


def same_report(python_report, tool_report, repairs):
    """The same fields, but the repairs: the tool's are of reading its input, `repairs`."""
    assert tool_report.pop("repairs") == repairs
    for key, value in python_report.items():
        if key not in NOT_OF_THE_RUN | {"repairs"}:
            assert tool_report[key] == value, key
    assert set(tool_report) - set(python_report) <= NOT_OF_THE_RUN


@pytest.mark.parametrize("source, options, keywords", [
    ("cow.obj", ["0.1"], {"ratio": 0.1}),
    ("cow.obj", ["--faces", "300", "--policy", "classic", "--fit"],
     {"target_count": 300, "policy": "classic", "fit": True}),
    ("fandisk.obj", ["0.05", "--policy", "fast"], {"ratio": 0.05, "policy": "fast"}),
    ("cow.obj", ["0.2", "--policy", "curvature", "--min-component", "3", "--smooth", "2"],
     {"ratio": 0.2, "policy": "curvature", "min_component": 3, "smooth": 2}),
    # Cells on two threads, which call back into Python from threads of their own.
    ("bunny.obj", ["0.1", "--parts", "4", "--threads", "2"], {"ratio": 0.1, "parts": 4, "threads": 2}),
    # Fast's prepass in each cell.
    ("bunny.obj", ["0.01", "--policy", "flat-lt", "--prepass", "10", "--parts", "4"],
     {"ratio": 0.01, "policy": "flat-lt", "prepass": 10, "parts": 4}),
])
def test_arrays_give_the_tools_bytes(tmp_path, data, source, options, keywords):
    expected, tool_report = tool_run(tmp_path, data / source, "tool.obj", *options)
    mesh = cp.read(data / source)
    vertices, faces, report = cp.simplify(mesh.vertices, mesh.faces, **keywords)
    cp.write(cp.Mesh(vertices, faces), tmp_path / "python.obj")
    assert (tmp_path / "python.obj").read_bytes() == expected
    same_report(report, tool_report, mesh.repairs)
    assert report["repairs"] == []  # read() repaired the file's soup already


@pytest.mark.parametrize("name", ["tool.obj", "tool.glb", "tool.ply"])
def test_a_textured_mesh_gives_the_tools_bytes(tmp_path, data, name):
    expected, tool_report = tool_run(tmp_path, data / "spot.obj", name, "0.1")
    simplified, report = cp.simplify(cp.read(data / "spot.obj"), ratio=0.1)
    cp.write(simplified, tmp_path / name.replace("tool", "python"))
    assert (tmp_path / name.replace("tool", "python")).read_bytes() == expected
    same_report(report, tool_report, [])
    assert report["attributes"] == "carried"


def test_a_grid_reaches_its_target_exactly():
    vertices, faces = grid(4)  # 25 vertices, 32 faces
    out_vertices, out_faces, report = cp.simplify(vertices, faces, target_reduction=0.75,
                                                  policy="classic")
    assert (report["input_faces"], report["input_vertices"], report["target_faces"]) == (32, 25, 8)
    assert report["policy"] == "classic" and report["fit"] is False
    assert out_faces.shape == (report["output_faces"], 3) and out_faces.dtype == np.int64
    assert out_vertices.shape == (report["output_vertices"], 3)
    assert report["stop_reason"] == "target_reached" and report["output_faces"] <= 8
    # Every output vertex is a grid point on the plane: collapses in a plane stay in it.
    assert np.all(out_vertices[:, 2] == 0)
    assert report["attributes"] == "none" and report["repairs"] == []


def test_the_default_is_the_librarys_pipeline_at_ten_percent(data):
    mesh = cp.read(data / "cow.obj")
    _, report = cp.simplify(mesh)
    assert report["policy"] == "lt" and report["fit"] is True
    assert report["target_faces"] == round(0.1 * report["input_faces"])


def test_fit_false_turns_the_default_pipelines_fit_off():
    vertices, faces = grid(4)
    _, _, report = cp.simplify(vertices, faces, target_count=10, fit=False)
    assert report["policy"] == "lt" and report["fit"] is False and "fit_rounds" not in report


def test_policy_options_reach_the_report():
    vertices, faces = grid(6)
    _, _, report = cp.simplify(vertices, faces, target_count=20, policy="classic",
                               border_weight=10, max_normal_angle=45)
    assert report["option_border-weight"] == 10  # named as simplify --json names it


def test_progress_rises_to_the_target(data):
    seen = []
    cp.simplify(cp.read(data / "bunny.obj"), ratio=0.1, policy="lt", progress=seen.append)
    assert seen and all(0 <= f <= 1 for f in seen) and seen == sorted(seen)


def test_policies_lists_every_policy_with_its_ranges():
    listed = cp.policies()
    help_line = next(line for line in run_tool("simplify", "--help").stdout.splitlines()
                     if "--policy NAME" in line)
    assert "|".join(listed) == help_line.split()[2]  # the tool's names, in its order
    tolerance = listed["hausdorff"]["options"]["tolerance"]
    assert tolerance["min"] == 0 and tolerance["flag"] is False
    for entry in listed.values():
        for option in entry["options"].values():
            assert option["min"] <= option["default"] <= option["max"]


def test_measure_gives_mesh_errors_fields(tmp_path, data):
    a = cp.read(data / "cow.obj")
    b, _ = cp.simplify(a, ratio=0.1)
    cp.write(b, tmp_path / "b.obj")
    done = run_tool("mesh_error", data / "cow.obj", tmp_path / "b.obj", "--samples", "5000",
                    "--json", "--attributes")
    assert cp.measure(a, b, samples=5000) == json.loads(done.stdout)


def test_measure_a_tetrahedron_against_itself():
    from test_mesh import TETRAHEDRON
    tetrahedron = cp.Mesh(*TETRAHEDRON)
    itself = cp.measure(tetrahedron, tetrahedron, samples=100)
    assert itself["bbox_diagonal"] == float(f"{3 ** 0.5:.10g}")  # ten digits, as the tools print
    assert (itself["mean_a_to_b"], itself["mean_b_to_a"], itself["rms"]) == (0, 0, 0)
    assert itself["samples"] == 100 and itself["valid"] is True and itself["closed"] is True
    assert (itself["euler_characteristic"], itself["min_angle_deg"]) == (2, 45)
