"""Noise on numpy arrays: every noise of ``scripts/noiselab render``.

Three entry points, float64 out (``points`` and ``function`` give float32 for float32
coordinates):

``grid(noise, size, ...)``
    a size x size raster through the library's row kernels (the same call
    ``noiselab render`` makes, so the same seed gives the same bits);
``points(x, y, z=None, noise=..., ...)``
    the noise at arrays of coordinates of any shape, broadcast as numpy
    broadcasts, one C call per array: the SIMD batch kernels where the
    library has them (improved and noise2 on their own, fractal and fBm sums
    over improved), the library's point loops otherwise;
``function(noise, ...)``
    the built noise as a function f(x, y[, z]): a call on Python floats
    costs about what python3-noise's pnoise3 costs (the extension's fast
    path, noiselab/_ext.c), arrays as ``points``.

Noises (``noise``): ``improved`` (Perlin 2002), ``noise2`` (Cheng 2009's 2D
gradient table; ``table`` under a sum), ``gctbf`` (Qin & Yang's cellular
sum of F1..F4), ``wavelet`` (Cook & DeRose 2005), and the sums ``fractal``,
``turbulence``, ``fbm`` and ``marble`` over ``basis`` (default improved).
"""

import ctypes
import os
import functools
from typing import TYPE_CHECKING, Optional, Tuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._lib import Error, c_double_p, check, ext, fn, integer, mirror
from ._lib import real as _real

if ext is None:
    raise ImportError("noiselab.noise needs the extension noiselab._ext, which this build "
                      "does not have (meson builds it where numpy's headers are found: "
                      "`scripts/noiselab setup`)")

__all__ = ["grid", "points", "function", "NoiseFunction", "bound", "cellular", "cellular_grid"]

if TYPE_CHECKING:
    from ._ext import NoiseFunction
else:
    NoiseFunction = ext.NoiseFunction
# noise2's gradient table: m angles (radians) and a permutation of 0..m-1
Table = Tuple[ArrayLike, ArrayLike]

_MAX_OCTAVES = 32


@mirror("nl_noise_basis")
class _NoiseBasis(ctypes.Structure):
    _fields_ = [("row", ctypes.c_void_p), ("ctx", ctypes.c_void_p), ("bound", ctypes.c_double)]


@mirror("nl_noise_octaves")
class _Octaves(ctypes.Structure):
    _fields_ = [("n", ctypes.c_int), ("turbulence", ctypes.c_int),
                ("freq", ctypes.c_double * _MAX_OCTAVES), ("amp", ctypes.c_double * _MAX_OCTAVES)]


@mirror("nl_noise_window")
class _Window(ctypes.Structure):
    _fields_ = [("x0", ctypes.c_double), ("y0", ctypes.c_double), ("z", ctypes.c_double),
                ("size", ctypes.c_double), ("w", ctypes.c_int), ("h", ctypes.c_int)]


@mirror("nl_cellular_gctbf")
class _Gctbf(ctypes.Structure):
    _fields_ = [("n", ctypes.c_int), ("c", ctypes.c_double * 4),
                ("cc", (ctypes.c_double * 4) * 4)]


@mirror("nl_basis", gctbf_cell="gctbf.cell", gctbf="gctbf.g")
class _Basis(ctypes.Structure):
    """nl_basis (basis/nl_basis.h): the noise and the tables it points into."""
    _fields_ = [("noise", _NoiseBasis), ("kind", ctypes.c_void_p), ("grad2", ctypes.c_void_p),
                ("perm3", ctypes.c_ubyte * 512), ("cell", ctypes.c_void_p),
                ("gctbf_cell", ctypes.c_void_p), ("gctbf", _Gctbf), ("tile", ctypes.c_void_p)]


@mirror("nl_basis_options", lambda_="lambda")
class _BasisOptions(ctypes.Structure):
    _fields_ = [("table_size", ctypes.c_long), ("reference", ctypes.c_int),
                ("lambda_", ctypes.c_double), ("points", ctypes.c_long), ("count", ctypes.c_int),
                ("terms", ctypes.c_char_p), ("tile", ctypes.c_long)]


@mirror("nl_basis_sum_options")
class _SumOptions(ctypes.Structure):
    _fields_ = [("octaves", ctypes.c_long), ("gain", ctypes.c_double),
                ("lacunarity", ctypes.c_double), ("amplitude", ctypes.c_double),
                ("stripes", ctypes.c_double)]


@mirror("nl_noise_grad2")
class _Grad2(ctypes.Structure):
    _fields_ = [("m", ctypes.c_size_t), ("angle", c_double_p), ("gx", c_double_p),
                ("gy", c_double_p), ("perm", ctypes.POINTER(ctypes.c_uint))]


_basis_defaults = fn("nl_basis_defaults", _BasisOptions)
_basis_make = fn("nl_basis_make", ctypes.c_int, ctypes.c_char_p, ctypes.POINTER(_BasisOptions),
                 ctypes.c_ulong, ctypes.POINTER(ctypes.POINTER(_Basis)), ctypes.POINTER(Error))
_basis_free = fn("nl_basis_free", None, ctypes.POINTER(_Basis))
_sum_check = fn("nl_basis_sum_check", ctypes.c_int, ctypes.POINTER(_SumOptions),
                ctypes.POINTER(Error))
_options_check = fn("nl_basis_options_check", ctypes.c_int, ctypes.POINTER(_BasisOptions),
                    ctypes.POINTER(Error))
_window_check = fn("nl_basis_window_check", ctypes.c_int, ctypes.POINTER(_Window),
                   ctypes.POINTER(Error))
_octaves_fbm = fn("nl_noise_octaves_fbm", _Octaves, ctypes.c_int, ctypes.c_double,
                  ctypes.c_double)
_fractal_grid = fn("nl_noise_fractal_grid", None, ctypes.POINTER(_NoiseBasis),
                   ctypes.POINTER(_Octaves), ctypes.POINTER(_Window), c_double_p)
_fractal_row = fn("nl_noise_fractal_row", None, ctypes.POINTER(_NoiseBasis),
                  ctypes.POINTER(_Octaves), ctypes.c_double, ctypes.c_double, ctypes.c_double,
                  ctypes.c_double, ctypes.c_size_t, c_double_p, c_double_p)
_marble_grid = fn("nl_texture_marble_grid", None, ctypes.POINTER(_NoiseBasis),
                  ctypes.POINTER(_Octaves), ctypes.POINTER(_Window), ctypes.c_double,
                  ctypes.c_double, c_double_p)
_cellular_eval = fn("nl_cellular_eval", None, ctypes.c_void_p, c_double_p, ctypes.c_int,
                    c_double_p)
_cellular_row = fn("nl_cellular_row", None, ctypes.c_void_p, ctypes.c_double, ctypes.c_double,
                   ctypes.c_double, ctypes.c_double, ctypes.c_size_t, ctypes.c_int, c_double_p)
_octaves_bound = fn("nl_noise_octaves_bound", ctypes.c_double, ctypes.POINTER(_Octaves),
                    ctypes.c_double)
_perm3_eval = fn("nl_noise_perm3_eval", ctypes.c_double, ctypes.c_void_p, ctypes.c_double,
                 ctypes.c_double, ctypes.c_double)
_grad2_eval = fn("nl_noise_grad2_eval", ctypes.c_double, ctypes.c_void_p, ctypes.c_double,
                 ctypes.c_double)
_perm3_points = fn("nl_noise_perm3_points", None, ctypes.c_void_p, c_double_p, c_double_p,
                   c_double_p, ctypes.c_size_t, c_double_p)
_perm3_points_sum = fn("nl_noise_perm3_points_sum", ctypes.c_double, ctypes.c_void_p,
                       ctypes.c_double, c_double_p, c_double_p, c_double_p, ctypes.c_size_t,
                       ctypes.c_double, c_double_p)
_grad2_points = fn("nl_noise_grad2_points", None, ctypes.c_void_p, c_double_p, c_double_p,
                   ctypes.c_size_t, c_double_p)
_points_refused = fn("nl_noise_points_refused", ctypes.c_size_t, c_double_p, c_double_p,
                     c_double_p, ctypes.c_size_t, ctypes.c_double)
_perm3_checked = fn("nl_noise_perm3_points_checked", ctypes.c_size_t, ctypes.c_void_p,
                    ctypes.POINTER(_Octaves), c_double_p, c_double_p, c_double_p, ctypes.c_size_t,
                    c_double_p)
_grad2_checked = fn("nl_noise_grad2_points_checked", ctypes.c_size_t, ctypes.c_void_p, c_double_p,
                    c_double_p, ctypes.c_size_t, c_double_p)
_fractal_points = fn("nl_noise_fractal_points", None, ctypes.POINTER(_NoiseBasis),
                     ctypes.POINTER(_Octaves), c_double_p, c_double_p, c_double_p, ctypes.c_size_t,
                     c_double_p)
_octaves_fmax = fn("nl_noise_octaves_fmax", ctypes.c_double, ctypes.POINTER(_Octaves))
_wavelet_points = fn("nl_wavelet_points", None, ctypes.c_void_p, c_double_p, c_double_p,
                     c_double_p, ctypes.c_size_t, c_double_p)
_cellular_points = fn("nl_cellular_points", None, ctypes.c_void_p, c_double_p, c_double_p,
                      c_double_p, ctypes.c_size_t, ctypes.c_int, c_double_p)
_gctbf_points = fn("nl_cellular_gctbf_points", None, ctypes.c_void_p, ctypes.POINTER(_Gctbf),
                   c_double_p, c_double_p, c_double_p, ctypes.c_size_t, c_double_p)
_grad2_alloc = fn("nl_noise_grad2_alloc", ctypes.POINTER(_Grad2), ctypes.c_size_t)
_grad2_free = fn("nl_noise_grad2_free", None, ctypes.POINTER(_Grad2))
_grad2_set_angle = fn("nl_noise_grad2_set_angle", None, ctypes.POINTER(_Grad2), ctypes.c_size_t,
                      ctypes.c_double)
_basis_grad2 = fn("nl_noise_basis_grad2", _NoiseBasis, ctypes.POINTER(_Grad2))

# The library's bases (nl_basis_kinds): each by its name and its name under
# a sum (noise2 is "table" there), in its order; the planar ones take no z.
_BASES = {n: name for name, under, _ in ext.bases() for n in (name, under)}
_PLANAR = tuple(name for name, _, planar in ext.bases() if planar)
_SUMS = ("fractal", "turbulence", "fbm", "marble")
# nl_basis_make names its inputs as render's options (or nl_cellular_alloc's
# fields); a Python user typed these parameters.
_BASIS_NAMES = {"--table-size": "table_size", "--terms": "terms", "--tile": "tile",
                "--lambda": "lambda_", "--points": "points", "--count": "count",
                "cellular: lambda": "lambda_", "cellular: M": "points"}
# The sum's and the window's ranges are render's, checked by the library
# (nl_basis_sum_check, nl_basis_window_check) in render's words.
_RANGE_NAMES = {f"--{k}": k for k in ("octaves", "gain", "lacunarity", "amplitude", "stripes",
                                      "size", "extent", "x0", "y0", "z")}
# render --seed's range: the library takes any unsigned long, the tool not.
_SEED_MAX = 2**32 - 1
# render --count's words (nl_cellular_count_rule's values)
_COUNTS = {"closest": 0, "inverse": 1, "closest-last": 2}
# How the extension evaluates a noise (_ext.c's enum): the SIMD batch
# kernels of improved noise (alone, fractal and fbm sums) and of noise2, the
# library's point loops of wavelet and gctbf, any other sum by its rows.
_K_PERM3, _K_GRAD2, _K_WAVELET, _K_GCTBF, _K_SUM = range(5)


def _ptr(a):
    return a.ctypes.data_as(c_double_p)


def _int(name, v, lo, hi):
    return integer(name, v, lo, hi, "{lo}..{hi}")


def _sum_options(octaves, gain, lacunarity, amplitude=0.5, stripes=1.0):
    """The sum's options, checked by the library as render checks them."""
    so = _SumOptions(_int("octaves", octaves, -2**63, 2**63 - 1), _real("gain", gain),
                     _real("lacunarity", lacunarity), _real("amplitude", amplitude),
                     _real("stripes", stripes))
    err = Error()
    check(_sum_check(ctypes.byref(so), ctypes.byref(err)), err, _RANGE_NAMES)
    return so


def _window(size, extent, x0, y0, z):
    """grid's raster as render's window, checked by the library as render checks it."""
    size = _int("size", size, -2**31, 2**31 - 1)
    win = _Window(_real("x0", x0), _real("y0", y0), _real("z", z), _real("extent", extent),
                  size, size)
    err = Error()
    check(_window_check(ctypes.byref(win), ctypes.byref(err)), err, _RANGE_NAMES)
    return win


def _name(name, v):
    if not isinstance(v, str):
        raise TypeError(f"{name}: expected a str, got {type(v).__name__}")
    return v


class _Noise:
    """A built noise (its C tables) and the octaves of its sum."""

    def __init__(self, noise, seed, basis, octaves, gain, lacunarity, table, table_size,
                 reference, terms, lambda_, points, count, tile):
        self._b = None
        self._g = None
        for name, v in (("noise", noise), ("basis", basis), ("terms", terms), ("count", count)):
            _name(name, v)
        if noise in _SUMS:
            self.sum, under = noise, basis
            if under not in _BASES:
                raise ValueError(f"basis: unknown noise basis {under!r} "
                                 f"(one of {', '.join(sorted(_BASES))})")
        elif noise in _BASES:
            self.sum, under = None, noise
        else:
            raise ValueError(f"noise: unknown noise {noise!r} "
                             f"(one of {', '.join(list(_BASES) + list(_SUMS))})")
        self.kind = _BASES[under]
        self.planar = self.kind in _PLANAR
        if count not in _COUNTS:
            raise ValueError(f"count: {count!r} is not inverse, closest or closest-last")
        seed = integer("seed", seed, 0, _SEED_MAX)
        so = _sum_options(octaves, gain, lacunarity)
        # every option in render's range, read or not (nl_basis_options_check)
        o = _basis_defaults()
        o.table_size = _int("table_size", table_size, -2**62, 2**62)
        o.reference = 1 if reference else 0
        o.lambda_ = _real("lambda_", lambda_)
        o.points = _int("points", points, -2**62, 2**62)
        o.count = _COUNTS[count]
        self._terms = terms.encode()
        o.terms = self._terms
        o.tile = _int("tile", tile, -2**62, 2**62)
        err = Error()
        check(_options_check(ctypes.byref(o), ctypes.byref(err)), err, _BASIS_NAMES)
        if table is not None:
            if self.kind != "noise2":
                raise ValueError(f"table: only noise2 (table under a sum) reads a table, "
                                 f"not {under}")
            self._own_table(table)
        else:
            b = ctypes.POINTER(_Basis)()
            err = Error()
            check(_basis_make(self.kind.encode(), ctypes.byref(o), seed, ctypes.byref(b),
                              ctypes.byref(err)), err, _BASIS_NAMES)
            self._b = b
            self.basis = b.contents.noise
        n = 1 if self.sum is None else so.octaves
        if self.sum == "fbm":
            self.octaves = _octaves_fbm(n, so.gain, so.lacunarity)
        elif self.sum is None:
            self.octaves = _octaves_fbm(1, 1.0, 1.0)
        else:
            self.octaves = _octaves_fbm(n, 0.5, 2.0)   # Shaffer's fractal sum
            self.octaves.turbulence = 1 if self.sum == "turbulence" else 0

    def _own_table(self, table):
        try:
            angle, perm = table
        except (TypeError, ValueError):
            raise ValueError("table: expected (angles, permutation), two arrays of m entries") \
                from None
        angle = np.asarray(angle, dtype=np.float64)
        perm = np.asarray(perm)
        m = angle.size
        if angle.ndim != 1 or perm.shape != (m,) or m < 1:
            raise ValueError(f"table: angles and permutation must be 1-D of the same size m >= 1 "
                             f"(got shapes {angle.shape} and {perm.shape})")
        if not np.all(np.isfinite(angle)):
            raise ValueError("table: an angle is not finite")
        if not np.issubdtype(perm.dtype, np.integer) or \
                not np.array_equal(np.sort(perm), np.arange(m)):
            raise ValueError(f"table: the permutation is not a permutation of 0..{m - 1}")
        g = _grad2_alloc(m)
        for k in range(m):
            _grad2_set_angle(g, k, float(angle[k]))
        for k in range(m):
            g.contents.perm[k] = int(perm[k])
        self._g = g
        self.basis = _basis_grad2(g)

    def check_lattice(self, c, strict=True):
        """Refuses coordinates whose finest octave passes 2^52 (render's rule):
        beyond it doubles have no fractional bits and a cell index would
        overflow the C side's long. strict=False: returns False instead."""
        o = self.octaves
        f = max(abs(o.freq[k]) for k in range(o.n))
        if f * c < 2.0 ** 52:
            return True
        if not strict:
            return False
        what = (f"lacunarity with octaves {o.n}" if self.sum == "fbm" else
                f"octaves {o.n}" if self.sum else "the noise")
        raise ValueError(f"coordinates: the finest octave's frequency {f:g} times the largest "
                         f"coordinate {c:g} is {f * c:g}, beyond 2^52 = 4.5e15 where the noise "
                         f"lattice has no fractional positions ({what}); use fewer octaves, a "
                         f"smaller lacunarity or coordinates nearer the origin")

    def grad2(self):
        return ctypes.cast(self._g, ctypes.c_void_p) if self._g else self._b.contents.grad2

    @functools.cached_property
    def kernel(self):
        """This noise as the extension's NoiseFunction (it keeps self alive;
        the cycle is the garbage collector's)."""
        if self.sum == "marble":
            raise ValueError("noise: marble is a texture of the plane: use grid()")
        if self.kind == "improved" and not self.octaves.turbulence:
            kind = _K_PERM3
        elif self.sum is None:
            kind = {"noise2": _K_GRAD2, "wavelet": _K_WAVELET, "gctbf": _K_GCTBF}[self.kind]
        else:
            kind = _K_SUM
        g = self.grad2()
        return NoiseFunction(self, functools.partial(_points_nz, self), kind, int(self.planar),
                             ctypes.addressof(self._b.contents) if self._b else None,
                             ctypes.addressof(self.basis), ctypes.addressof(self.octaves),
                             g.value if isinstance(g, ctypes.c_void_p) else g,
                             int(self.sum is not None))

    # The freeing functions are bound as defaults: at interpreter exit the
    # cached noises are collected after the module's globals are gone.
    def close(self, basis_free=_basis_free, grad2_free=_grad2_free):
        if self._b:
            basis_free(self._b)
            self._b = None
        if self._g:
            grad2_free(self._g)
            self._g = None

    def __del__(self):
        self.close()


@functools.lru_cache(maxsize=8, typed=True)
def _cached(*args):
    return _Noise(*args)


# Argument types whose equal values are the same value: an entry made from
# them is what _Noise would build (or refuse) from any equal arguments of the
# same types, which the typed cache keys apart (1 and 1.0 and True).
_PLAIN = frozenset((int, float, str, bool, type(None)))


def _make(noise, seed, basis, octaves, gain, lacunarity, table, table_size, reference, terms,
          lambda_, points, count, tile):
    """The built noise: the last few seeded ones are kept (building a table
    costs more than a point), a given table is built afresh each call.
    Built noises are never changed, so threads may share them.

    What is accepted never depends on earlier calls: the cache is keyed by
    the arguments with their types when they are plain Python values, else
    by the values they convert to once their types are checked (numpy
    integers and floats, say): equal keys are then the same values, which
    _Noise accepts or refuses alike. (Untyped, seed=1.0 == 1 would hit a
    seed=1 entry by hash and equality alone.) A refusal is never cached."""
    args = (noise, seed, basis, octaves, gain, lacunarity, None, table_size, reference, terms,
            lambda_, points, count, tile)
    if table is None and _PLAIN.issuperset(map(type, args)):
        return _cached(*args)
    args = (_name("noise", noise), integer("seed", seed, 0, _SEED_MAX),
            _name("basis", basis), _int("octaves", octaves, -2**63, 2**63 - 1),
            _real("gain", gain), _real("lacunarity", lacunarity), None,
            _int("table_size", table_size, -2**62, 2**62), bool(reference),
            _name("terms", terms), _real("lambda_", lambda_),
            _int("points", points, -2**62, 2**62), _name("count", count),
            _int("tile", tile, -2**62, 2**62))
    if table is not None:
        return _Noise(*args[:6], table, *args[7:])
    return _cached(*args)


_DOC_OPTIONS = """
    noise : str
        improved, noise2, gctbf, wavelet, or a sum of octaves over ``basis``:
        fractal, turbulence, fbm (``points`` has no marble).
    seed : int
        the tables' seed (the permutation, gradient table, feature points or
        wavelet tile), as ``render --seed``, 0..2^32 - 1; default 1.
    basis : str
        the noise under a sum: improved (default), table (noise2), gctbf, wavelet.
    octaves : int
        1..30 octaves of a sum (6).
    gain, lacunarity : float
        fbm's amplitude and frequency ratios (0.5, 2).
    table : (angles, permutation), optional
        noise2's gradient table given instead of seeded: m angles in radians
        and a permutation of 0..m-1 (as ``noiselab.cheng`` optimises them).
    table_size : int
        gradients in noise2's seeded table (512).
    reference : bool
        improved noise with Perlin's own permutation, not the seed's.
    terms, lambda_, points, count : str, float, int, str
        gctbf's sum ("F1", "F2 - F1", ...), feature points per unit cube (4),
        at most per cube (50), count rule (inverse, closest, closest-last).
    tile : int
        wavelet tile period, even, 8..256 (64).

    A value ``render`` refuses raises ValueError, checked by the same library
    call in render's words (octaves 1..30, gain [-1e3, 1e3], lacunarity
    [1e-6, 1e6], amplitude [-1e6, 1e6], stripes [1e-9, 1e9], size 1..65536,
    extent [1e-9, 1e9], x0, y0, z [-1e9, 1e9], each finite: nl_basis.h).
"""


def grid(noise: str = "improved", size: int = 512, *, extent: float = 4.0, x0: float = 0.0,
         y0: float = 0.0, z: float = 0.5, seed: int = 1, basis: str = "improved",
         octaves: int = 6, gain: float = 0.5, lacunarity: float = 2.0, amplitude: float = 0.5,
         stripes: float = 1.0, table: Optional[Table] = None, table_size: int = 512,
         reference: bool = False, terms: str = "F1", lambda_: float = 4.0, points: int = 50,
         count: str = "inverse", tile: int = 64,
         out: Optional[NDArray[np.float64]] = None, workers: int = -1) -> NDArray[np.float64]:
    """A size x size raster of a noise, as ``scripts/noiselab render`` makes it.

    Pixel (row r, column c) holds the noise at x = x0 + (c + 1/2) extent / size,
    y = y0 + (r + 1/2) extent / size, in the plane z (2D noises ignore z):
    row 0 is y0, the top of render's image. Computed by the library's row
    kernels (SIMD, the scalar code's bits); the GIL is released meanwhile
    and Ctrl-C raises KeyboardInterrupt between blocks of rows.

    Parameters
    ----------
    size : int
        pixels per side, 1..65536.
    extent, x0, y0, z : float
        side of the square in noise units (4), its origin (0, 0), the plane (0.5).
    amplitude, stripes : float
        marble's displacement and stripes per unit (0.5, 1).
    out : numpy.ndarray, optional
        a C-contiguous float64 (size, size) array to write into (a fresh one
        costs its page faults, as much as the noise on a loaded machine).
    workers : int
        threads for the rows, as scipy's ``workers``: -1 (default) every
        processor, as ``render --threads``; 1 the calling thread only. The
        values are the same bytes for any count; small rasters (below 2^17
        samples a block) stay on one thread.
    %OPTIONS%
    Returns
    -------
    numpy.ndarray of float64, shape (size, size)

    Example
    -------
    >>> import noiselab.noise as nn
    >>> v = nn.grid("fbm", 256, octaves=6, gain=0.5, lacunarity=2, seed=7)
    >>> v.shape, v.dtype
    ((256, 256), dtype('float64'))
    """
    win = _window(size, extent, x0, y0, z)
    size = win.w
    so = _sum_options(octaves, gain, lacunarity, amplitude, stripes)
    nz = _make(noise, seed, basis, octaves, gain, lacunarity, table, table_size, reference,
               terms, lambda_, points, count, tile)
    c = max(abs(win.x0), abs(win.x0 + win.size), abs(win.y0), abs(win.y0 + win.size))
    nz.check_lattice(c if nz.planar else max(c, abs(win.z)))
    res = _out(out, (size, size))
    # nl_noise_fractal_grid's rows (nl_texture_marble_grid's for marble), a
    # block of rows at a time with the GIL released and Ctrl-C honoured
    # between blocks (_ext.c), a block of a few ms: the SIMD row kernels of
    # improved and noise2 take ~1 ns a sample and octave, gctbf and wavelet
    # rows tens of times more (as the point blocks of _ext.c)
    block = 65536 if nz.kind in ("improved", "noise2") else 4096
    ext.grid(ctypes.addressof(nz.basis), ctypes.addressof(nz.octaves), win.x0, win.y0, win.z,
             win.size, win.w, win.h, nz.sum == "marble", 2 * np.pi * so.stripes, so.amplitude,
             block, res, _workers(workers))
    return res


def _workers(workers):
    """scipy's ``workers``: a positive count, or -1 for every processor
    (os.cpu_count, the processors online: the library's default rule)."""
    if isinstance(workers, bool) or not isinstance(workers, (int, np.integer)) or \
            not (workers == -1 or 1 <= workers <= 1024):
        raise ValueError(f"workers: {workers!r} must be -1 (every processor) or 1..1024")
    return int(workers) if workers != -1 else (os.cpu_count() or 1)


def _out(out, shape, dtype=np.dtype(np.float64)):
    if out is None:
        return np.empty(shape, dtype=dtype)
    if not isinstance(out, np.ndarray) or out.dtype != dtype or out.shape != shape \
            or not out.flags.c_contiguous or not out.flags.writeable:
        desc = f"{out.dtype} {out.shape}" if isinstance(out, np.ndarray) else type(out).__name__
        raise ValueError(f"out: expected a writeable C-contiguous {dtype} array of shape "
                         f"{shape}, got {desc}")
    return out


def bound(noise: str = "improved", *, seed: int = 1, basis: str = "improved", octaves: int = 6,
          gain: float = 0.5, lacunarity: float = 2.0, table: Optional[Table] = None,
          table_size: int = 512, reference: bool = False, terms: str = "F1",
          lambda_: float = 4.0, points: int = 50, count: str = "inverse",
          tile: int = 64) -> float:
    """The analytic bound B of a noise, |value| <= B (turbulence: 0 <= value <= B):
    the basis's bound times the sum of |amplitudes| (nl_noise_octaves_bound);
    render maps an integer image's grey levels by it. Marble's values lie in
    [0, 1]. Options as grid's.

    Parameters
    ----------
    noise : str            a noise of grid()/points() ("improved", "fbm", ...)
    seed, basis, octaves, gain, lacunarity, table, table_size, reference, terms,
    lambda_, points, count, tile : as grid's (the bound depends on the basis, the
        amplitudes and, for cellular terms, on lambda_ and points)

    Returns
    -------
    float : B >= 0

    Example
    -------
    >>> import noiselab.noise as nn
    >>> round(nn.bound("improved"), 6), round(nn.bound("fbm", octaves=2, gain=0.5), 6)
    (1.224745, 1.837117)
    """
    if noise == "marble":
        return 1.0
    nz = _Noise(noise, seed, basis, octaves, gain, lacunarity, table, table_size, reference,
                terms, lambda_, points, count, tile)
    try:
        return _octaves_bound(ctypes.byref(nz.octaves), nz.basis.bound)
    finally:
        nz.close()


def _dtype(arrays):
    """The result's dtype, as numpy's arithmetic would give it: float32 when
    the coordinates are float32 arrays or scalars, with Python numbers
    beside them (numpy's value-based casting: a Python float does not widen
    a float32 array); float64 otherwise (float64 or integer coordinates)."""
    typed = [a for a in arrays if isinstance(a, (np.ndarray, np.generic))]
    if typed and all(a.dtype == np.float32 for a in typed):
        return np.dtype(np.float32)
    return np.dtype(np.float64)


def _coords(names, arrays, dtype=np.float64):
    """dtype (float64, or float32 for the float32 path), C-contiguous,
    broadcast copies of coordinate arrays (views when they are). NaN,
    infinity and the lattice limit are checked by the C side, block by
    block beside the kernel (nl_noise_points_refused)."""
    conv = []
    for name, given in zip(names, arrays):
        a = np.asarray(given)
        if a.dtype.kind in "OSUV" and not isinstance(given, np.ndarray):
            # a str or an object is no coordinate: say which argument got what
            raise TypeError(f"{name}: coordinates must be real numbers or arrays of them, "
                            f"got {type(given).__name__} {given!r:.40}" +
                            (" (the noise is the argument noise=)" if isinstance(given, str)
                             else ""))
        if a.dtype != dtype:
            # float16 has 11 bits (a coordinate past 2048 is not where it was
            # meant) and bool is no coordinate: as documented, only integers
            # and float32 are converted
            if a.dtype.kind not in "iu" and a.dtype not in (np.float32, np.float64):
                raise TypeError(f"{name}: coordinates must be real numbers (integer, float32 "
                                f"or float64), got dtype {a.dtype}")
            a = a.astype(dtype)
        conv.append(a)
    try:
        shape = np.broadcast(*conv).shape
    except ValueError:
        shapes = ", ".join(f"{n} {a.shape}" for n, a in zip(names, conv))
        raise ValueError(f"coordinates do not broadcast together: {shapes}") from None
    # numpy's broadcasting by assignment into a fresh array, which is what
    # np.broadcast_arrays and a contiguous copy give, at a third of their
    # cost on small arrays (a call on one point was 45 us, most of it there)
    out = []
    for a in conv:
        if a.shape != shape or not a.flags.c_contiguous:
            c = np.empty(shape, dtype=dtype)
            c[...] = a
            a = c
        out.append(a)
    return out


def _refuse(nz, names, arrays, k):
    """The one-line error for the point at flat index k, which the C side
    refused (nl_noise_points_refused): a coordinate that is not finite, else
    the lattice limit of nz's finest octave."""
    vals = [(name, float(a.ravel()[k])) for name, a in zip(names, arrays) if a is not None]
    for name, v in vals:
        if not np.isfinite(v):
            raise ValueError(f"{name}: coordinate {k} (flat index) is {v}, not a finite number")
    nz.check_lattice(max(abs(v) for _, v in vals))
    raise AssertionError(f"point {k} refused by the library but not here")


def _scalars(*v):
    return all(type(a) in (float, int, np.float64) for a in v if a is not None)


def points(x: ArrayLike, y: ArrayLike, z: Optional[ArrayLike] = None, noise: str = "improved",
           *, seed: int = 1, basis: str = "improved", octaves: int = 6, gain: float = 0.5,
           lacunarity: float = 2.0, table: Optional[Table] = None, table_size: int = 512,
           reference: bool = False, terms: str = "F1", lambda_: float = 4.0, points: int = 50,
           count: str = "inverse", tile: int = 64,
           out: Optional[NDArray[np.float64]] = None, workers: int = -1) -> NDArray[np.float64]:
    """A noise at arrays of points: x, y (and z) broadcast together as numpy does.

    Coordinates are float64 or float32 (integer arrays are converted to
    float64; other dtypes, float16, bool, longdouble, complex, object or
    str, raise TypeError). float32 coordinates (arrays or numpy scalars,
    with Python numbers beside them) give float32 values, as numpy's own
    functions do: improved noise, its fbm and fractal sums and noise2 through
    the library's float32 kernels (within 2e-6 of the double noise at the
    same coordinates, nl_noise.h), the other noises in double rounded to
    float32. A NaN or infinite coordinate, or
    one whose finest octave passes 2^52, is a ValueError naming the first such
    point (flat index): then ``out`` holds the values of the points before it
    in C order, and its entries from it on may have been written (the library
    checks the points a block of 512 at a time, beside the kernel, where they
    are in cache). z defaults to the plane 0.5 that ``grid`` and
    render use; 2D noise (noise2) takes no z. Every noise is one call of
    the extension for the whole array, run a block at a time with the GIL
    released and Ctrl-C (KeyboardInterrupt) honoured between blocks: SIMD
    batch kernels for improved, noise2 and the fractal and fbm sums over
    improved, point loops in C for the others. On Python floats, points()
    returns a numpy float64 through the extension's scalar path (no array
    is made); ``function`` spares the options' lookup as well.
    A point gives the bits ``grid`` gives at the same coordinates (for sums,
    when every octave's frequency is a power of two, as with lacunarity 2:
    the row kernels scale x0 and dx separately).

    Parameters
    ----------
    x, y, z : array_like
        coordinates, any shapes that broadcast together.
    out : numpy.ndarray, optional
        a C-contiguous array of the broadcast shape and the result's dtype
        (float64, or float32 for float32 coordinates) to write into; it
        may overlap x, y or z (``out=x``): the values are then those of the
        call without out, computed into a temporary first, as numpy's ufuncs
        buffer overlaps.
    workers : int
        threads for the improved and noise2 batches and their sums (float64),
        as scipy's ``workers``: -1 (default) every processor, 1 the calling
        thread only; the same bytes for any count, and batches below 2^17
        samples stay on one thread.
    %OPTIONS%
    Returns
    -------
    numpy.ndarray of float64 (float32 for float32 coordinates) with the broadcast shape

    Example
    -------
    >>> import numpy as np, noiselab.noise as nn
    >>> x = np.linspace(0, 4, 5)
    >>> nn.points(x, 1.5, 0.5, "improved", seed=3).shape
    (5,)
    >>> y = x.copy()
    >>> np.array_equal(nn.points(y, 1.5, 0.5, "fbm", out=y), nn.points(x, 1.5, 0.5, "fbm"))
    True
    """
    nz = _make(noise, seed, basis, octaves, gain, lacunarity, table, table_size, reference,
               terms, lambda_, points, count, tile)
    f = nz.kernel
    nthreads = _workers(workers)
    if out is None and _scalars(x, y, z):
        # the extension's scalar path: no array is made (a point the
        # library refuses comes back through _points_nz for its message)
        return f(x, y) if z is None else f(x, y, z)
    return _points_nz(nz, x, y, z, out=out, threads=nthreads)


def _points_nz(nz, x, y, z=None, *, out=None, threads=None):
    """points() of the built noise nz: the arrays' path."""
    # float32 coordinates keep float32 (numpy's habit): through the float32
    # kernels where the library has them, else computed in double and
    # rounded to float32
    dtype = _dtype((x, y) if z is None else (x, y, z))
    f32 = dtype == np.float32 and ext.has_f32(nz.kernel)
    cdt = np.float32 if f32 else np.float64
    if nz.planar:
        if z is not None:
            raise ValueError(f"z: {nz.kind} is a 2D noise and takes no z")
        names, (xs, ys), zs = "xy", _coords("xy", (x, y), cdt), None
    else:
        names = "xyz"
        xs, ys, zs = _coords(names, (x, y, 0.5 if z is None else z), cdt)
    out = _out(out, xs.shape, dtype)
    # The sums accumulate octave by octave into out, and every kernel writes a
    # block before it reads the next: an out that overlaps a coordinate would
    # feed written values back as coordinates. As numpy's ufuncs buffer such
    # an overlap, the noise is computed into a temporary and copied.
    # xs, ys, zs are what the kernel reads: views of the given arrays where
    # those are of the kernel's dtype and C-contiguous (sharing their memory), else
    # fresh copies, which cannot overlap out.
    dest = out
    if dtype != cdt or any(np.may_share_memory(out, a) for a in (xs, ys, zs) if a is not None):
        out = np.empty(dest.shape, dtype=cdt)
    # one C call, a block at a time with the GIL released and signals
    # (Ctrl-C) checked between blocks (_ext.c)
    if f32:
        k = ext.points_f32(nz.kernel, xs, ys, zs, out)
    else:
        k = ext.points(nz.kernel, xs, ys, zs, out, threads or (os.cpu_count() or 1))
    if out is not dest:
        dest.ravel()[:k] = out.ravel()[:k]
    if k < out.size:
        _refuse(nz, names, (xs, ys, zs), k)
    if dest.ndim == 0 and not any(isinstance(a, np.ndarray) for a in (x, y, z)):
        return dest[()]   # scalars in, a numpy scalar out, as numpy's functions do
    return dest


def function(noise: str = "improved", *, seed: int = 1, basis: str = "improved",
             octaves: int = 6, gain: float = 0.5, lacunarity: float = 2.0,
             table: Optional[Table] = None, table_size: int = 512, reference: bool = False,
             terms: str = "F1", lambda_: float = 4.0, points: int = 50, count: str = "inverse",
             tile: int = 64) -> NoiseFunction:
    """A noise built once, as a function: ``f = function("fbm", octaves=4); f(x, y, z)``.

    ``f(x, y[, z])`` is ``points(x, y, z, noise, ...)`` with these options:
    on Python floats or ints (or numpy float64 scalars) it takes the
    extension's fast path (no array is made, the options are not looked up
    again: about python3-noise's ``pnoise3`` per call, docs/python.md) and
    returns a numpy float64; on arrays, with ``out=``, or for a point the
    library refuses it is ``points`` (broadcasting, the same errors). Use it
    in a loop over single points; for arrays both cost the same.

    Parameters
    ----------
    %OPTIONS%
    Returns
    -------
    NoiseFunction : callable f(x, y[, z], *, out=None)

    Example
    -------
    >>> import noiselab.noise as nn
    >>> f = nn.function("improved", seed=3)
    >>> f(1.25, 2.5, 0.5) == nn.points(1.25, 2.5, 0.5, seed=3)
    True
    >>> f([0.5, 1.5], 2.5).shape
    (2,)
    """
    return _make(noise, seed, basis, octaves, gain, lacunarity, table, table_size, reference,
                 terms, lambda_, points, count, tile).kernel


# The options both functions share, written once.
for _f in (grid, points, function):
    _f.__doc__ = (_f.__doc__ or "").replace("%OPTIONS%", _DOC_OPTIONS)


def _cells(seed, lambda_, points, count):
    return _Noise("gctbf", seed, "improved", 1, 0.5, 2.0, None, 512, False, "F1", lambda_,
                  points, count, 64)


def cellular(x: ArrayLike, y: ArrayLike, z: ArrayLike = 0.5, n: int = 4, *, seed: int = 1,
             lambda_: float = 4.0, points: int = 50,
             count: str = "inverse") -> NDArray[np.float64]:
    """Worley's cellular distances F1..Fn (Qin & Yang 2000's feature points,
    src/cellular/nl_cellular.h) at arrays of points, broadcast as numpy does.

    Returns an array of the broadcast shape plus a last axis of n (1..4):
    F1 <= F2 <= ... The feature points are gctbf's for the same seed,
    lambda_, points and count, so F1 equals points(..., "gctbf") with
    terms="F1". One C call for all points (nl_cellular_points).

    Parameters
    ----------
    x, y, z : array_like   coordinates, broadcast together (z default 0.5)
    n : int                how many distances, 1..4
    seed, lambda_, points, count : the feature points, as gctbf's

    Returns
    -------
    ndarray : the broadcast shape plus a last axis of n, float64

    Example
    -------
    >>> import numpy as np, noiselab.noise as nn
    >>> F = nn.cellular(np.linspace(0, 3, 4), 0.5, 0.5, n=2, seed=2)
    >>> F.shape, bool(np.all(F[:, 0] <= F[:, 1]))
    ((4, 2), True)
    """
    n = _int("n", n, 1, 4)
    xs, ys, zs = _coords("xyz", (x, y, z))
    nz = _cells(seed, lambda_, points, count)
    try:
        out = np.empty(xs.shape + (n,))
        px, py, pz = _ptr(xs), _ptr(ys), _ptr(zs)
        k = _points_refused(px, py, pz, xs.size, 1.0)
        if k < xs.size:
            _refuse(nz, "xyz", (xs, ys, zs), k)
        _cellular_points(nz._b.contents.cell, px, py, pz, xs.size, n, _ptr(out))
    finally:
        nz.close()
    return out


def cellular_grid(size: int = 512, n: int = 4, *, extent: float = 4.0, x0: float = 0.0,
                  y0: float = 0.0, z: float = 0.5, seed: int = 1, lambda_: float = 4.0,
                  points: int = 50, count: str = "inverse") -> NDArray[np.float64]:
    """F1..Fn on grid()'s raster through the cellular row kernel:
    (size, size, n) float64, [r, c, i] = F_{i+1} at grid's pixel (r, c).

    Parameters
    ----------
    size : int             pixels a side
    n : int                how many distances, 1..4
    extent, x0, y0, z : grid()'s window (extent units across, pixel centres)
    seed, lambda_, points, count : the feature points, as gctbf's

    Returns
    -------
    ndarray (size, size, n) float64

    Example
    -------
    >>> import noiselab.noise as nn
    >>> nn.cellular_grid(16, 3, seed=5).shape
    (16, 16, 3)
    """
    win = _window(size, extent, x0, y0, z)
    size, ext, x0, y0, z = win.w, win.size, win.x0, win.y0, win.z
    n = _int("n", n, 1, 4)
    nz = _cells(seed, lambda_, points, count)
    out = np.empty((size, size, n))
    try:
        d = ext / size
        for r in range(size):
            _cellular_row(nz._b.contents.cell, x0 + 0.5 * d, d, y0 + (r + 0.5) * d, z, size, n,
                          _ptr(out[r]))
    finally:
        nz.close()
    return out
