"""noiselab from Python: the library's noise and statistics on numpy arrays.

Every number comes from libnoiselab (the C library this repository builds):
nothing here is a second implementation. Modules:

  noiselab.noise    grid(...) and points(...) of every noise of ``noiselab render``
  noiselab.stats    kstest, ks_2samp, kuiper, chisquare, linkage, GaussianMixture
                    with scipy's and scikit-learn's names and result attributes
  noiselab.cheng    Cheng's controllable noise: optimise a table for a pattern array
  noiselab.byexample  Lagae's noise by example: analyse an image, synthesize, morph
  noiselab.results  an experiment folder's tables, manifest and verdicts

Binding: the noise calls go through a CPython extension, noiselab._ext
(_ext.c, built by meson over numpy's C API, the whole library linked in): a
call on Python floats costs about what python3-noise's pnoise3 costs, and
long calls release the GIL and honour Ctrl-C between blocks. Everything else
goes through ctypes, which opens that same extension: its few microseconds
per call do not show beside a KS test, a mixture fit or a synthesis, and the
headers are plain C structs that ctypes describes directly (each mirror
checked against the library's layout at import). numpy arrays go to C by
pointer (no copy when they are float64 and C-contiguous); every long call
releases the GIL, so kernels run beside other threads. Installed with
``pip install .`` (meson-python) or ``meson install``: docs/python.md.

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
