#!/usr/bin/env python3
"""Times cgal_policies.dask.simplify on a LocalCluster of one worker process and of two, in one
run, each worker with one thread and the library with one thread per task, and checks that both
give the same mesh. Prints a line per run and the ratio (docs/python.md, "On a Dask cluster").
With --from-file the tasks get the file's path, cut while it is read in passes, never whole.

usage: PYTHONPATH=build/python /usr/bin/python3 scripts/dask_scaling.py [--from-file] MESH
           [KEY=VALUE ...]
  e.g. scripts/dask_scaling.py /tmp/dragon16.ply parts=16 ratio=0.01 policy=flat-lt fit=True
"""
import ast
import sys
import time

import numpy as np
from distributed import Client, LocalCluster

import cgal_policies as cp
import cgal_policies.dask


def option(text):
    key, value = text.split("=", 1)
    try:
        return key, ast.literal_eval(value)
    except (ValueError, SyntaxError):
        return key, value


def main():
    args = sys.argv[1:]
    from_file = bool(args) and args[0] == "--from-file"
    if from_file:
        args.pop(0)
    if not args:
        sys.exit(__doc__)
    options = dict(option(a) for a in args[1:])
    options["threads"] = 1
    mesh = args[0]
    if not from_file:
        start = time.perf_counter()
        mesh = cp.read(args[0])
        print(f"read {len(mesh.faces)} faces in {time.perf_counter() - start:.1f} s", flush=True)
    seconds, outputs = {}, {}
    for workers in (1, 2):
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                          dashboard_address=None) as cluster, Client(cluster) as client:
            start = time.perf_counter()
            out, report = cp.dask.simplify(client, mesh, **options)
            seconds[workers] = time.perf_counter() - start
        outputs[workers] = out
        print(f"{workers} worker(s): {seconds[workers]:.1f} s, {report['output_faces']} faces, "
              f"{report['parts']} parts", flush=True)
    same = all(np.array_equal(getattr(outputs[1], a), getattr(outputs[2], a))
               for a in ("vertices", "faces"))
    print(f"one worker / two: {seconds[1] / seconds[2]:.2f}x; the same mesh: {same}")


if __name__ == "__main__":
    main()
