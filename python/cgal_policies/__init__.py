"""Mesh simplification with CGAL's edge collapse and this suite's policies and passes.

simplify() runs the library's pipeline on numpy arrays or on a Mesh that carries texture
coordinates, normals, colours and materials; read() and write() take every format the
command-line tools take; measure() gives the evaluator's two-sided error; policies() lists each
policy's options. help(cgal_policies.simplify) is the reference; docs/python.md the guide.
PartitionedJob runs a partitioned simplification a step at a time, and cgal_policies.dask runs
those steps as the tasks of a Dask cluster.
"""

from ._cgal_policies import Mesh, PartitionedJob, measure, policies, read, simplify, write

__all__ = ["Mesh", "PartitionedJob", "measure", "policies", "read", "simplify", "write"]
