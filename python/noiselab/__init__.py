"""noiselab from Python: the library's noise and statistics on numpy arrays.

Every number comes from libnoiselab (the C library this repository builds):
nothing here is a second implementation. Modules:

  noiselab.noise    grid(...) and points(...) of every noise of ``noiselab render``
  noiselab.stats    kstest, ks_2samp, kuiper, chisquare, linkage, GaussianMixture
                    with scipy's and scikit-learn's names and result attributes
  noiselab.cheng    Cheng's controllable noise: optimise a table for a pattern array
  noiselab.byexample  Lagae's noise by example: analyse an image, synthesize, morph
  noiselab.results  an experiment folder's tables, manifest and verdicts

Binding: ctypes over the shared library, not a CPython extension. ctypes is
in the standard library, so nothing is compiled beyond libnoiselab itself and
the package runs from the build tree or an installed prefix as it is; every
ctypes call releases the GIL, so long kernels run beside other threads; numpy
arrays go to C by pointer (no copy when they are float64 and C-contiguous).
Its cost is a few microseconds per call, which the row and batch kernels
amortise over a whole raster or array; cffi (a Debian package too) would buy
nothing here that outweighs a second dependency, as the headers are plain C
structs that ctypes describes directly.

Errors: a failing library call raises ValueError (bad input, malformed file),
OSError (a file cannot be read or written), MemoryError, or
noiselab.NoiselabError (numerical failure), with the library's one-line
message.

Example (from a checkout built by ``scripts/noiselab setup``):

  $ PYTHONPATH=python /usr/bin/python3
  >>> import noiselab.noise as nn
  >>> v = nn.grid("fbm", 512, octaves=6, seed=7)   # as `noiselab render fbm --seed 7`
"""

import importlib

from ._lib import NoiselabError, path as library_path

_SUBMODULES = ("noise", "stats", "cheng", "byexample", "results")
__all__ = ["NoiselabError", "library_path", *_SUBMODULES]
__version__ = "0.1.0"


def __getattr__(name):
    """``noiselab.stats`` without importing it first: submodules load on first
    use (PEP 562), as scipy's do, so ``import noiselab`` stays cheap."""
    if name in _SUBMODULES:
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(_SUBMODULES))
