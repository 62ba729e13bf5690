"""Cheng's controllable noise (Cheng 2009, src/cheng/nl_cheng.h): a 2D
gradient table optimised by multi-level simulated annealing so that a
fractal sum follows a control pattern while its angles stay uniform.

  res = noiselab.cheng.optimise(pattern, seed=1)      # pattern: (h, w) array in [0, 1]
  res.angles, res.perm, res.e_ks, res.e_con
  v = noiselab.cheng.value_grid(res.table, 256)      # the controlled value c on [0,1)^2
  nn.grid("fractal", 256, basis="table", table=res.table)   # its table under any sum

Every option is a field of nl_cheng_config, by the same name; the defaults
are the thesis's setting (512 angles, 4 octaves from f1 = 8, a1 = 4, w1 =
0.995, w2 = 0.005, KS objective, cloud control).
"""

import ctypes
from dataclasses import dataclass, field
from typing import Any, Dict, Tuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._lib import Error, c_double_p, check, fn, mirror
from . import noise as _noise

__all__ = ["optimise", "evaluate", "value_grid", "ChengResult"]

_MAXO = 8


@mirror("nl_cheng_schedule")
class _Schedule(ctypes.Structure):
    _fields_ = [("n_temps", ctypes.c_int), ("moves_per_var", ctypes.c_double),
                ("t_decades", ctypes.c_double), ("p0", ctypes.c_double), ("stall", ctypes.c_int)]


@mirror("nl_cheng_config")
class _Config(ctypes.Structure):
    _fields_ = [("stat", ctypes.c_int), ("con", ctypes.c_int), ("w1", ctypes.c_double),
                ("w2", ctypes.c_double), ("octaves", ctypes.c_int), ("f1", ctypes.c_double),
                ("a1", ctypes.c_double), ("m", ctypes.c_size_t), ("chisq_bins", ctypes.c_size_t),
                ("propagate", ctypes.c_int), ("sched", _Schedule), ("literal", ctypes.c_int),
                ("amp_vary", ctypes.c_int), ("amp_range", ctypes.c_double),
                ("log_gain", ctypes.c_double * _MAXO), ("origin", ctypes.c_double)]


_EVAL_DOUBLES = ("e_ks", "p_ks", "kuiper_v", "p_kuiper", "chi2", "p_chi2", "e_con", "e",
                 "rms_con", "roughness", "r_pattern", "e_con_offset", "e_con_contrast",
                 "e_con_shape", "seam_ratio", "contrast", "e_con_const", "e_con_random")


@mirror("nl_cheng_eval")
class _Eval(ctypes.Structure):
    _fields_ = [(n, ctypes.c_double) for n in _EVAL_DOUBLES] + \
        [("log_gain", ctypes.c_double * _MAXO), ("moves", ctypes.c_long),
         ("cpu_seconds", ctypes.c_double)]


@mirror("nl_cheng_pattern")
class _Pattern(ctypes.Structure):
    _fields_ = [("grid", ctypes.c_int), ("n", ctypes.c_size_t), ("x", c_double_p),
                ("y", c_double_p), ("d", c_double_p), ("cell", ctypes.POINTER(ctypes.c_int))]


_E = ctypes.POINTER(Error)
_G2 = ctypes.POINTER(_noise._Grad2)
_config_default = fn("nl_cheng_config_default", _Config)
_config_check = fn("nl_cheng_config_check", ctypes.c_int, ctypes.POINTER(_Config), _E)
_stat_parse = fn("nl_cheng_stat_parse", ctypes.c_int, ctypes.c_char_p,
                 ctypes.POINTER(ctypes.c_int), _E)
_con_parse = fn("nl_cheng_con_parse", ctypes.c_int, ctypes.c_char_p,
                ctypes.POINTER(ctypes.c_int), _E)
_pattern_from_pixels = fn("nl_cheng_pattern_from_pixels", ctypes.c_int,
                          ctypes.POINTER(ctypes.c_float), ctypes.c_int, ctypes.c_int,
                          ctypes.c_int, ctypes.c_int, ctypes.POINTER(ctypes.POINTER(_Pattern)),
                          _E)
_pattern_free = fn("nl_cheng_pattern_free", None, ctypes.POINTER(_Pattern))
_run = fn("nl_cheng_run", ctypes.c_int, ctypes.POINTER(_Config), ctypes.POINTER(_Pattern),
          ctypes.c_ulong, ctypes.POINTER(_Eval), ctypes.c_void_p, ctypes.POINTER(_G2), _E)
_evaluate = fn("nl_cheng_evaluate", ctypes.c_int, _G2, ctypes.POINTER(_Config),
               ctypes.POINTER(_Pattern), ctypes.POINTER(_Eval), _E)
_value_grid = fn("nl_cheng_value_grid", None, _G2, ctypes.POINTER(_Config), ctypes.c_int,
                 ctypes.c_int, c_double_p)


@dataclass(frozen=True)
class ChengResult:
    """The optimised table (angles, perm) and its evaluation: e_ks (E_KS, the KS
    distance of the angles from uniform, eq. 3.5-3.7), e_con (E_Con, eq. 3.8),
    e (eq. 3.9), r_pattern and the other fields of nl_cheng_eval."""
    angles: np.ndarray = field(repr=False)
    perm: np.ndarray = field(repr=False)
    e_ks: float
    e_con: float
    e: float
    eval: dict = field(repr=False)

    @property
    def table(self) -> Tuple[np.ndarray, np.ndarray]:
        """(angles, perm), as noiselab.noise takes a table."""
        return (self.angles, self.perm)


def _config(options):
    c = _config_default()
    err = Error()
    for k, v in options.items():
        if k == "stat":
            s = ctypes.c_int()
            check(_stat_parse(str(v).encode(), ctypes.byref(s), ctypes.byref(err)), err)
            c.stat = s.value
        elif k in ("con", "control"):
            s = ctypes.c_int()
            check(_con_parse(str(v).encode(), ctypes.byref(s), ctypes.byref(err)), err)
            c.con = s.value
        elif k in _Schedule.__dict__ and not k.startswith("_"):
            setattr(c.sched, k, v)
        elif k == "log_gain":
            g = np.asarray(v, dtype=np.float64)
            if g.shape != (c.octaves,) and g.size > _MAXO:
                raise ValueError(f"log_gain: at most {_MAXO} gains")
            for i, x in enumerate(g):
                c.log_gain[i] = float(x)
        elif k in _Config.__dict__ and not k.startswith("_"):
            setattr(c, k, v)
        else:
            raise TypeError(f"{k}: not an option of Cheng's optimiser")
    check(_config_check(ctypes.byref(c), ctypes.byref(err)), err)
    return c


def _pattern(pattern, grid):
    a = np.asarray(pattern)
    if a.dtype.kind not in "biuf":
        raise TypeError(f"pattern: expected a real array, got dtype {a.dtype}")
    if a.ndim == 2:
        a = a[:, :, None]
    if a.ndim != 3 or not 1 <= a.shape[2] <= 4 or a.shape[0] < 1 or a.shape[1] < 1:
        raise ValueError(f"pattern: expected (h, w) or (h, w, channels <= 4), got {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError("pattern: a value is not finite")
    px = np.ascontiguousarray(a, dtype=np.float32)
    p, err = ctypes.POINTER(_Pattern)(), Error()
    check(_pattern_from_pixels(px.ctypes.data_as(ctypes.POINTER(ctypes.c_float)), a.shape[1],
                               a.shape[0], a.shape[2], int(grid), ctypes.byref(p),
                               ctypes.byref(err)), err)
    return p


def _table(table, m):
    nz = _noise._Noise("noise2", 1, "improved", 1, 0.5, 2.0, table, 512, False, "F1", 4.0, 50,
                       "inverse", 64)
    if nz._g.contents.m != m:
        nz.close()
        raise ValueError(f"table: {len(table[0])} angles; the config's m is {m}")
    return nz


def _result(g, ev):
    m = g.contents.m
    angles = np.ctypeslib.as_array(g.contents.angle, shape=(m,)).copy()
    perm = np.ctypeslib.as_array(g.contents.perm, shape=(m,)).astype(np.int64)
    d = {n: getattr(ev, n) for n in _EVAL_DOUBLES}
    d.update(log_gain=list(ev.log_gain), moves=ev.moves, cpu_seconds=ev.cpu_seconds)
    return ChengResult(angles, perm, ev.e_ks, ev.e_con, ev.e, d)


def optimise(pattern: ArrayLike, seed: int = 1, grid: int = 64, **options: Any) -> ChengResult:
    """Optimises a gradient table for a control pattern (nl_cheng_run).

    Parameters
    ----------
    pattern : array_like, (h, w) or (h, w, channels)
        the control pattern, row 0 at y = 0: grey (or red) in [0, 1] is the
        target; with 2 or 4 channels the last is alpha (cells of mean alpha
        below 1/2 carry no control).
    seed : int
        the random start table and the annealer's generator, 0..2^32 - 1
        (an experiment's --seed).
    grid : int
        control points: the centres of a grid x grid raster (64).
    **options
        nl_cheng_config fields: stat ('ks', 'chisq', 'kuiper', 'chisq_raw'), con ('cloud',
        'marble', 'erosion', 'fire'), w1, w2, octaves, f1, a1, m, chisq_bins,
        propagate, literal, amp_vary, amp_range, log_gain, origin, and the schedule's
        n_temps, moves_per_var, t_decades, p0, stall.

    Returns
    -------
    ChengResult: angles, perm, e_ks, e_con, e, eval (every measure)

    Example
    -------
    >>> import numpy as np, noiselab.cheng as nc
    >>> yy, xx = np.mgrid[0:64, 0:64] / 64.0
    >>> disc = ((xx - .5) ** 2 + (yy - .5) ** 2 < .1).astype(float)
    >>> r = nc.optimise(disc, seed=2, grid=16, octaves=2, n_temps=4)   # doctest: +SKIP
    >>> r.e_con < r.eval["e_con_random"]                               # doctest: +SKIP
    True
    """
    c = _config(options)
    # the experiments' --seed range (nl_harness): -1 would wrap to 2^64 - 1
    seed = _noise.integer("seed", seed, 0, _noise._SEED_MAX)
    p = _pattern(pattern, grid)
    g, ev, err = _G2(), _Eval(), Error()
    try:
        check(_run(ctypes.byref(c), p, seed, ctypes.byref(ev), None, ctypes.byref(g),
                   ctypes.byref(err)), err)
        try:
            return _result(g, ev)
        finally:
            _noise._grad2_free(g)
    finally:
        _pattern_free(p)


def evaluate(table: Tuple[ArrayLike, ArrayLike], pattern: ArrayLike, grid: int = 64,
             **options: Any) -> ChengResult:
    """E_KS, E_Con and the other measures of a given table (angles, perm)
    against a pattern (nl_cheng_evaluate), as a ChengResult; options as optimise's.

    Parameters
    ----------
    table : (angles, perm) the gradient angles (M values in [0, 2 pi)) and a
        permutation of 0..M-1
    pattern : array_like (h, w) the control pattern, values in [0, 1]
    grid : int             the control grid's cells a side
    **options              as optimise's (stat, con, w1, w2, octaves, f1, ...)

    Returns
    -------
    ChengResult : e_ks, e_con and the other measures

    Example
    -------
    >>> import numpy as np, noiselab.cheng as nc
    >>> rng = np.random.default_rng(0)
    >>> table = (rng.uniform(0, 2 * np.pi, 512), rng.permutation(512))
    >>> e = nc.evaluate(table, np.ones((16, 16)), grid=16, octaves=2)
    >>> 0 < e.e_ks < 1
    True
    """
    c = _config(options)
    p = _pattern(pattern, grid)
    try:
        nz = _table(table, c.m)
        try:
            ev, err = _Eval(), Error()
            check(_evaluate(nz._g, ctypes.byref(c), p, ctypes.byref(ev), ctypes.byref(err)), err)
            ev.e_con_random = float("nan")
            return _result(nz._g, ev)
        finally:
            nz.close()
    finally:
        _pattern_free(p)


def value_grid(table: Tuple[ArrayLike, ArrayLike], size: int,
               **options: Any) -> NDArray[np.float64]:
    """The control value c(x, y) (all octaves, the config's variant) of a table
    at the pixel centres of a size x size raster of [0,1)^2, row 0 at y = 0.

    Parameters
    ----------
    table : (angles, perm) as evaluate's
    size : int             pixels a side
    **options              as optimise's (octaves, f1, a1, amp_vary, ...)

    Returns
    -------
    ndarray (size, size) float64, values in [0, 1]

    Example
    -------
    >>> import numpy as np, noiselab.cheng as nc
    >>> rng = np.random.default_rng(0)
    >>> table = (rng.uniform(0, 2 * np.pi, 512), rng.permutation(512))
    >>> v = nc.value_grid(table, 64)
    >>> v.shape, bool(0 <= v.min() and v.max() <= 1)
    ((64, 64), True)
    """
    c = _config(options)
    size = _noise._int("size", size, 1, 65536)
    nz = _table(table, c.m)
    try:
        out = np.empty((size, size))
        _value_grid(nz._g, ctypes.byref(c), size, size, out.ctypes.data_as(c_double_p))
        return out
    finally:
        nz.close()
