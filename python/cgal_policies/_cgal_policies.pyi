# Type hints of the compiled module; the docstrings (help(cgal_policies.simplify)) are the reference.
import os
from typing import Any, Callable, Optional, Union, overload

import numpy as np
import numpy.typing as npt

_Path = Union[str, os.PathLike[str]]
_Report = dict[str, Any]

class Mesh:
    def __init__(
        self,
        vertices: npt.ArrayLike,
        faces: npt.ArrayLike,
        *,
        uv: Optional[npt.ArrayLike] = None,
        normals: Optional[npt.ArrayLike] = None,
        colors: Optional[npt.ArrayLike] = None,
        materials: Optional[npt.ArrayLike] = None,
        material_names: list[str] = [],
        material_libraries: list[str] = [],
    ) -> None: ...
    @property
    def vertices(self) -> npt.NDArray[np.float64]: ...
    @property
    def faces(self) -> npt.NDArray[np.int64]: ...
    @property
    def uv(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def normals(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def colors(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def materials(self) -> Optional[npt.NDArray[np.int64]]: ...
    @property
    def material_names(self) -> list[str]: ...
    @property
    def material_libraries(self) -> list[str]: ...
    @property
    def repairs(self) -> list[str]: ...

@overload
def simplify(
    vertices: npt.ArrayLike,
    faces: npt.ArrayLike,
    *,
    target_count: Optional[int] = None,
    target_reduction: Optional[float] = None,
    policy: Optional[str] = None,
    fit: Optional[bool] = None,
    max_error: Optional[float] = None,
    threads: Optional[int] = None,
    progress: Optional[Callable[[float], object]] = None,
    **policy_options: Union[bool, float, str],
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], _Report]: ...
@overload
def simplify(
    mesh: Mesh,
    *,
    target_count: Optional[int] = None,
    target_reduction: Optional[float] = None,
    policy: Optional[str] = None,
    fit: Optional[bool] = None,
    max_error: Optional[float] = None,
    threads: Optional[int] = None,
    progress: Optional[Callable[[float], object]] = None,
    **policy_options: Union[bool, float, str],
) -> tuple[Mesh, _Report]: ...
def read(path: _Path, *, asset_root: Optional[_Path] = None) -> Mesh: ...
def write(mesh: Mesh, path: _Path, *, gltf_encoding: str = "float") -> None: ...
def measure(a: Mesh, b: Mesh, *, samples: int = 200000) -> _Report: ...
def policies() -> dict[str, dict[str, Any]]: ...

class PartitionedJob:
    def __init__(
        self,
        folder: _Path,
        *,
        target_count: Optional[int] = None,
        target_reduction: Optional[float] = None,
        policy: Optional[str] = None,
        fit: Optional[bool] = None,
        max_error: Optional[float] = None,
        threads: Optional[int] = None,
        **policy_options: Union[bool, float, str],
    ) -> None: ...
    def cut(self, mesh: Mesh) -> int: ...
    def cut_file(self, path: _Path) -> int: ...
    def run_part(self, stage: int, c: int) -> None: ...
    def stitch(self, stage: int) -> bool: ...
    def result(self, mesh: Optional[Mesh] = None) -> tuple[Mesh, _Report]: ...
