"""The partitioned run as Dask tasks on two worker processes, against the run in one process."""
import pytest

import cgal_policies as cp
import cgal_policies.dask
from test_simplify import NOT_OF_THE_RUN, same_report, tool_run

distributed = pytest.importorskip("distributed")
# Debian's tornado 6.2 under distributed 2022.12 warns of its own event loop handling.
pytestmark = pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            yield client


def same_run(dask_report, report):
    for key, value in report.items():
        if key not in NOT_OF_THE_RUN:
            assert dask_report[key] == value, key


@pytest.mark.parametrize("source, name, options", [
    # The default pipeline: lt on every part, stitched, and the fit by cells.
    ("bunny.obj", "out.ply", {"parts": 4, "ratio": 0.05}),
    # Spot's texture, seams and material through the parts.
    ("spot.obj", "out.obj", {"parts": 4, "ratio": 0.1, "policy": "attributes"}),
    # A mesh the run would not cut: one part, run whole.
    ("cow.obj", "out.ply", {"ratio": 0.1, "policy": "fast"}),
])
def test_the_dask_run_gives_the_bytes_of_the_run_in_one_process(client, tmp_path, data, source,
                                                                 name, options):
    mesh = cp.read(data / source)
    expected, report = cp.simplify(mesh, **options)
    cp.write(expected, tmp_path / ("one_process_" + name))
    shared = tmp_path / "shared"
    shared.mkdir()
    out, dask_report = cp.dask.simplify(client, mesh, shared=shared, **options)
    cp.write(out, tmp_path / ("dask_" + name))
    assert (tmp_path / ("dask_" + name)).read_bytes() == \
        (tmp_path / ("one_process_" + name)).read_bytes()
    same_run(dask_report, report)
    assert dask_report["parts"] == options.get("parts", 1)
    assert list(shared.iterdir()) == []  # the job's files are gone


def test_a_bad_option_is_refused_before_any_task(client, tmp_path, data):
    with pytest.raises(ValueError, match=r"^unknown option --no-such-option=1.0 \(see --help\)$"):
        cp.dask.simplify(client, cp.read(data / "cow.obj"), shared=tmp_path, no_such_option=1)
    assert list(tmp_path.iterdir()) == []


def test_a_failing_task_is_raised_and_leaves_no_file(client, tmp_path, data, monkeypatch):
    def failing_part(folder, options, stage, c):
        raise OSError("the shared folder is gone")

    monkeypatch.setattr(cp.dask, "_run_part", failing_part)
    with pytest.raises(OSError, match="the shared folder is gone"):
        cp.dask.simplify(client, cp.read(data / "bunny.obj"), shared=tmp_path, parts=2, ratio=0.1)
    assert list(tmp_path.iterdir()) == []


def test_a_file_cut_in_passes_gives_the_bytes_of_simplify_out_of_core(client, tmp_path, data):
    """The bunny by its path: the cut reads it in passes, the tasks fit by cells."""
    expected, tool_report = tool_run(tmp_path, data / "bunny.obj", "tool.ply", "0.05",
                                     "--parts", "4", "--out-of-core")
    shared = tmp_path / "shared"
    shared.mkdir()
    out, report = cp.dask.simplify(client, data / "bunny.obj", shared=shared, parts=4, ratio=0.05)
    cp.write(out, tmp_path / "dask.ply")
    assert (tmp_path / "dask.ply").read_bytes() == expected
    same_report(report, tool_report, [])
    assert report["parts"] == 4 and report["fit"]
    assert list(shared.iterdir()) == []


def test_a_file_is_not_cut_for_an_option_that_needs_it_whole(client, tmp_path, data):
    with pytest.raises(ValueError, match=r"^a mesh file is cut in passes, never held whole, "):
        cp.dask.simplify(client, data / "bunny.obj", shared=tmp_path, ratio=0.05, max_error=0.01)
    assert list(tmp_path.iterdir()) == []
