# Type stubs of discrete_lie_flow (the functions are documented in __init__.py).
import os
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__all__: List[str]
__version__: str

class FlowError(RuntimeError):
    report: Optional[Dict[str, Any]]

Callback = Callable[[Dict[str, Any]], Optional[bool]]
# {"faces": face indices, or "ball": (x, y, z, radius); "factor": float; "name": str (optional)}
Region = Dict[str, Any]

def disk(
    V: npt.ArrayLike,
    F: npt.ArrayLike,
    *,
    mode: str = ...,
    border: Optional[str] = ...,
    init: str = ...,
    density: Optional[npt.ArrayLike] = ...,
    regions: Optional[Sequence[Region]] = ...,
    band: Optional[float] = ...,
    seam: Optional[npt.ArrayLike] = ...,
    tolerance: Optional[float] = ...,
    init_uv: Optional[npt.ArrayLike] = ...,
    max_iterations: Optional[int] = ...,
    mu: Optional[float] = ...,
    share_tolerance: Optional[float] = ...,
    fixed_step: Optional[float] = ...,
    threshold: Optional[float] = ...,
    outer_loop: int = ...,
    literal_targets: bool = ...,
    delaunay_flips: bool = ...,
    history: bool = ...,
    callback: Optional[Callback] = ...,
    name: str = ...,
    strict: bool = ...,
) -> Tuple[npt.NDArray[np.float64], Dict[str, Any]]: ...
def sphere(
    V: npt.ArrayLike,
    F: npt.ArrayLike,
    *,
    mode: str = ...,
    density: Optional[npt.ArrayLike] = ...,
    regions: Optional[Sequence[Region]] = ...,
    band: Optional[float] = ...,
    tolerance: Optional[float] = ...,
    log_area_tolerance: Optional[float] = ...,
    max_iterations: Optional[int] = ...,
    mu: Optional[float] = ...,
    share_tolerance: Optional[float] = ...,
    fixed_step: Optional[float] = ...,
    threshold: Optional[float] = ...,
    literal_targets: bool = ...,
    delaunay_flips: bool = ...,
    history: bool = ...,
    start: str = ...,
    init_map: Optional[npt.ArrayLike] = ...,
    callback: Optional[Callback] = ...,
    name: str = ...,
    strict: bool = ...,
) -> Tuple[npt.NDArray[np.float64], Dict[str, Any]]: ...
def score(V: npt.ArrayLike, F: npt.ArrayLike, uv: npt.ArrayLike, *, density: Optional[npt.ArrayLike] = ...) -> Dict[str, Any]: ...
def info(V: npt.ArrayLike, F: npt.ArrayLike, *, name: str = ...) -> Dict[str, Any]: ...
def atlas(
    V: npt.ArrayLike,
    F: npt.ArrayLike,
    *,
    border: str = ...,
    tips: Optional[int] = ...,
    gutter: Optional[float] = ...,
    stretch: bool = ...,
    density: Optional[npt.ArrayLike] = ...,
    name: str = ...,
    strict: bool = ...,
) -> Tuple[npt.NDArray[np.float64], Dict[str, Any]]: ...
def read_mesh(path: Union[str, os.PathLike[str]]) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
