"""The partitioned run on a Dask cluster (docs/python.md): a task per part and a stitch, by stages.

The mesh is cut where this function runs. Each part is simplified by a task on whichever worker
Dask picks, and a stitch task puts the parts together and runs the policy over the whole; then,
when the run fits its output, two more stages of a task per part and a stitch run the two halves
of the fit by cells. The output comes back here. The tasks hand their work on as files in a
folder under `shared`, a path that the workers and this process all see (a network file system
across machines; the local temporary folder for a LocalCluster), removed afterwards. The result
is simplify()'s with the same options and parts, byte for byte once written. A mesh file given by
its path (binary PLY or OBJ) is cut while it is read in passes, never whole, and the result is
then `simplify --out-of-core`'s.

    from distributed import Client, LocalCluster
    import cgal_policies, cgal_policies.dask

    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as client:
        mesh = cgal_policies.read("scan.ply")
        out, report = cgal_policies.dask.simplify(client, mesh, parts=16, target_reduction=0.99)
"""

import itertools
import os
import shutil
import tempfile

from ._cgal_policies import PartitionedJob


def _run_part(folder, options, stage, c):
    PartitionedJob(folder, **options).run_part(stage, c)


def _stitch(folder, options, stage, parts_done):
    return PartitionedJob(folder, **options).stitch(stage)


def simplify(client, mesh, *, shared=None, **options):
    """Simplifies `mesh` as cgal_policies.simplify(mesh, **options) does, its parts as tasks of
    the Dask `client` (a distributed.Client). `mesh` is a Mesh, or the path of a mesh file too
    large to read whole (its points and triangles only; the options that need the whole input,
    such as max_error, are refused). `options` are simplify()'s but progress; `parts` sets the cut
    (0, the default: one part per 500,000 faces, and one part, run whole, for a smaller mesh).
    Returns (mesh, report) as simplify() does. ValueError for a bad option or an unreadable file
    before any task starts; a task's error is raised here, and the job's files are removed all
    the same.
    """
    folder = tempfile.mkdtemp(prefix="cgal_policies_job_", dir=shared)
    futures = []
    try:
        job = PartitionedJob(folder, **options)
        from_file = isinstance(mesh, (str, os.PathLike))
        parts = job.cut_file(mesh) if from_file else job.cut(mesh)
        # pure=False: two jobs never share a task, whatever their arguments.
        for stage in itertools.count():
            done = [client.submit(_run_part, folder, options, stage, c, pure=False)
                    for c in range(parts)]
            stitched = client.submit(_stitch, folder, options, stage, done, pure=False)
            futures = done + [stitched]
            if not stitched.result():
                break
        return job.result(None if from_file else mesh)
    finally:
        client.cancel(futures)
        shutil.rmtree(folder, ignore_errors=True)
