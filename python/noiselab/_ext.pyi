# The types of the extension noiselab._ext (_ext.c), for type checkers.
from typing import Any, Callable, Optional, Tuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

class NoiseFunction:
    _noise: Any
    _kind: int
    def __init__(self, owner: Any, fallback: Callable[..., Any], kind: int, planar: int,
                 basis: Optional[int], noise_basis: Optional[int], octaves: Optional[int],
                 grad2: Optional[int], has_sum: int) -> None: ...
    def __call__(self, x: ArrayLike, y: ArrayLike, z: Optional[ArrayLike] = ..., *,
                 out: Optional[NDArray[np.float64]] = ...) -> Any: ...

def points(f: NoiseFunction, x: NDArray[np.float64], y: NDArray[np.float64],
           z: Optional[NDArray[np.float64]], out: NDArray[np.float64], threads: int = ...) -> int: ...
def points_f32(f: NoiseFunction, x: NDArray[np.float32], y: NDArray[np.float32],
               z: Optional[NDArray[np.float32]], out: NDArray[np.float32]) -> int: ...
def has_f32(f: NoiseFunction) -> bool: ...
def bases() -> Tuple[Tuple[str, str, bool], ...]: ...
def grid(noise_basis: int, octaves: int, x0: float, y0: float, z: float, size: float, w: int,
         h: int, marble: bool, omega: float, a: float, block: int,
         out: NDArray[np.float64], threads: int = ...) -> None: ...
