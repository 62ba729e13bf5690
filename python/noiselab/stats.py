"""Statistics of libnoiselab with scipy's and scikit-learn's habits.

  kstest(x, 'norm', args=(loc, scale), alternative=, method=)
                                          one-sample KS (scipy.stats.kstest)
  ks_2samp(x, y, alternative=, method=)   two-sample KS (scipy.stats.ks_2samp)
  kuiper(x, 'uniform', args=(0, 2*pi))    Kuiper's V (astropy's p-value)
  chisquare(f_obs, f_exp=None, axis=0)    Pearson (scipy.stats.chisquare)
  linkage(y, method, metric)              scipy.cluster.hierarchy.linkage's matrix,
                                          of observations or condensed distances
  GaussianMixture(n_components, ...)      fit, score, score_samples, aic, bic, predict

Results unpack as scipy's do, ``D, p = kstest(...)``, and carry scipy's
attribute names (statistic, pvalue) and the library's extra fields.
Distributions by name: the 14 scipy.stats names the library has (kstest
lists them) with scipy's shape, loc and scale arguments, or a vectorised
callable F(x, *args), called once with the whole sorted sample as scipy
calls it.
"""

import ctypes
import math
import warnings
from dataclasses import dataclass
from typing import Any, Callable, Iterator, Optional, Sequence, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._lib import Error, c_double_p, check, fn, mirror

_CDF = ctypes.CFUNCTYPE(ctypes.c_double, ctypes.c_double, ctypes.c_void_p)


@mirror("nl_stats_dist")
class _Dist(ctypes.Structure):
    _fields_ = [("kind", ctypes.c_int), ("loc", ctypes.c_double), ("scale", ctypes.c_double),
                ("shape", ctypes.c_double * 2), ("m", ctypes.c_size_t), ("x", c_double_p),
                ("F", c_double_p)]


@mirror("nl_stats_ks_result")
class _KsResult(ctypes.Structure):
    _fields_ = [("d", ctypes.c_double), ("d_plus", ctypes.c_double),
                ("d_minus", ctypes.c_double), ("p", ctypes.c_double), ("n", ctypes.c_size_t),
                ("n2", ctypes.c_size_t), ("method", ctypes.c_int)]


@mirror("nl_stats_kuiper_result")
class _KuiperResult(ctypes.Structure):
    _fields_ = [("v", ctypes.c_double), ("d_plus", ctypes.c_double),
                ("d_minus", ctypes.c_double), ("p", ctypes.c_double), ("n", ctypes.c_size_t)]


@mirror("nl_stats_chisq_result")
class _ChisqResult(ctypes.Structure):
    _fields_ = [("chi2", ctypes.c_double), ("df", ctypes.c_size_t), ("p", ctypes.c_double),
                ("min_expected", ctypes.c_double), ("low_expected", ctypes.c_int),
                ("n", ctypes.c_size_t), ("k", ctypes.c_size_t)]


_E = ctypes.POINTER(Error)
_dist_parse = fn("nl_stats_dist_parse", ctypes.c_int, ctypes.c_char_p,
                 ctypes.POINTER(ctypes.c_int), _E)
_dist_init = fn("nl_stats_dist_init_shape", ctypes.c_int, ctypes.POINTER(_Dist), ctypes.c_int,
                c_double_p, ctypes.c_size_t, ctypes.c_double, ctypes.c_double, _E)
_dist_nshape = fn("nl_stats_dist_nshape", ctypes.c_int, ctypes.c_int)
_dist_shape_names = fn("nl_stats_dist_shape_names", ctypes.c_char_p, ctypes.c_int)
_dist_cdf = ctypes.cast(fn("nl_stats_dist_cdf", ctypes.c_double, ctypes.c_double,
                           ctypes.c_void_p), _CDF)
_ks_test = fn("nl_stats_ks_test", ctypes.c_int, c_double_p, ctypes.c_size_t, _CDF,
              ctypes.c_void_p, ctypes.POINTER(_KsResult), _E)
_ks2_test = fn("nl_stats_ks2_test", ctypes.c_int, c_double_p, ctypes.c_size_t, c_double_p,
               ctypes.c_size_t, ctypes.POINTER(_KsResult), _E)
_ks_method_name = fn("nl_stats_ks_method_name", ctypes.c_char_p, ctypes.c_int)
_ks_statistic = fn("nl_stats_ks_statistic", None, c_double_p, ctypes.c_size_t, c_double_p,
                   c_double_p)
_ks_sf = fn("nl_stats_ks_sf", ctypes.c_double, ctypes.c_size_t, ctypes.c_double,
            ctypes.POINTER(ctypes.c_int))
_smirnov_sf = fn("nl_stats_smirnov_sf", ctypes.c_double, ctypes.c_size_t, ctypes.c_double)
_kolmogorov_sf = fn("nl_stats_kolmogorov_sf", ctypes.c_double, ctypes.c_double)
_kuiper_sf = fn("nl_stats_kuiper_sf", ctypes.c_double, ctypes.c_size_t, ctypes.c_double)
_alternative_parse = fn("nl_stats_ks_alternative_parse", ctypes.c_int, ctypes.c_char_p,
                        ctypes.POINTER(ctypes.c_int), _E)
_ks_one_sided = fn("nl_stats_ks_one_sided", None, ctypes.POINTER(_KsResult), ctypes.c_int)
_ks2_sf_method = fn("nl_stats_ks2_sf_method", ctypes.c_double, ctypes.c_size_t,
                    ctypes.c_size_t, ctypes.c_double, ctypes.c_int, ctypes.c_int,
                    ctypes.POINTER(ctypes.c_int))
# nl_stats_ks_method and nl_stats_ks_alternative (stats/nl_stats.h)
_SMIRNOV, _KOLMOGOROV, _TWO_SAMPLE_EXACT, _TWO_SAMPLE_ASYMP = 1, 5, 6, 7
_TWO_SIDED, _LESS, _GREATER = 0, 1, 2
_kuiper_test = fn("nl_stats_kuiper_test", ctypes.c_int, c_double_p, ctypes.c_size_t, _CDF,
                  ctypes.c_void_p, ctypes.POINTER(_KuiperResult), _E)
_chisq_test = fn("nl_stats_chisq_test", ctypes.c_int, c_double_p, c_double_p, ctypes.c_size_t,
                 ctypes.POINTER(_ChisqResult), _E)
_mean_sd = fn("nl_stats_mean_sd_checked", ctypes.c_int, c_double_p, ctypes.c_size_t, ctypes.c_int,
               c_double_p, c_double_p, _E)
_linkage_parse = fn("nl_cluster_linkage_method_parse", ctypes.c_int, ctypes.c_char_p,
                    ctypes.POINTER(ctypes.c_int), _E)
_metric_parse = fn("nl_cluster_metric_parse", ctypes.c_int, ctypes.c_char_p,
                   ctypes.POINTER(ctypes.c_int), _E)
_linkage_metric = fn("nl_cluster_linkage_metric", ctypes.c_int, c_double_p, ctypes.c_size_t,
                     ctypes.c_size_t, ctypes.c_int, ctypes.c_int, c_double_p, _E)
_linkage_condensed = fn("nl_cluster_linkage_condensed", ctypes.c_int, c_double_p,
                        ctypes.c_size_t, ctypes.c_int, c_double_p, _E)


def _ptr(a):
    return a.ctypes.data_as(c_double_p)


def _sample(name, x, ndim=1):
    """float64, C-contiguous (a view when it already is)."""
    a = np.asarray(x)
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{name}: expected real numbers, got dtype {a.dtype}")
    a = np.ascontiguousarray(a, dtype=np.float64)
    if ndim == 1:
        a = a.ravel()
    elif a.ndim != ndim:
        raise ValueError(f"{name}: expected a {ndim}-D array, got shape {a.shape}")
    return a


class _Pair:
    """scipy's result habit: the object unpacks and indexes as the tuple
    (statistic, pvalue) (``D, p = kstest(...)``) and keeps its attributes."""

    statistic: Any
    pvalue: Any

    def __iter__(self) -> Iterator[Any]:
        return iter((self.statistic, self.pvalue))

    def __len__(self) -> int:
        return 2

    def __getitem__(self, i: int) -> Any:
        return (self.statistic, self.pvalue)[i]


@dataclass(frozen=True)
class KstestResult(_Pair):
    """statistic (D, or D+ / D- one-sided), pvalue, and D+, D-, the sizes,
    the p-value's method and statistic_sign (scipy 1.10's: +1 when the
    statistic is D+, -1 when D-). Unpacks as (statistic, pvalue)."""
    statistic: float
    pvalue: float
    d_plus: float
    d_minus: float
    n: int
    n2: int
    method: str
    statistic_sign: int = 1


@dataclass(frozen=True)
class KuiperResult(_Pair):
    """statistic (V = D+ + D-), pvalue P(V_n >= V), D+ and D-. Unpacks as
    (statistic, pvalue)."""
    statistic: float
    pvalue: float
    d_plus: float
    d_minus: float
    n: int


@dataclass(frozen=True)
class ChisquareResult(_Pair):
    """statistic (chi2), pvalue, df = k - 1 and Cochran's warning (an
    expected count < 5); arrays of them for 2-D input (one per column, as
    scipy with axis=0). Unpacks as (statistic, pvalue)."""
    statistic: object
    pvalue: object
    df: object
    min_expected: object
    low_expected: object


class _Cdf:
    """A named distribution for the C tests, which evaluate it at each value."""

    def __init__(self, cdf, args):
        err = Error()
        kind = ctypes.c_int()
        check(_dist_parse(cdf.encode(), ctypes.byref(kind), ctypes.byref(err)), err)
        args = tuple(float(a) for a in args)
        k = _dist_nshape(kind.value)
        names = (_dist_shape_names(kind.value) or b"").decode()
        want = f"({names + ', ' if k else ''}loc, scale)"
        if len(args) < k or len(args) > k + 2:
            raise ValueError(f"args: {cdf} takes {want}, got {len(args)} values")
        shape = (ctypes.c_double * 2)(*args[:k])
        loc, scale = (args[k:] + (0.0, 1.0)[len(args) - k:])
        self.dist = _Dist()
        check(_dist_init(ctypes.byref(self.dist), kind.value, shape, k, loc, scale,
                         ctypes.byref(err)), err)
        self.fn = _dist_cdf
        self.params = ctypes.cast(ctypes.byref(self.dist), ctypes.c_void_p)


def _callable_statistic(x, cdf, args):
    """D+ and D- of x against a callable CDF, called once with the whole
    sorted sample as scipy calls it (not once per value from C); the
    statistic is the library's (nl_stats_ks_statistic), the checks and their
    words the C tests' (nl_gof.c)."""
    n = x.size
    if n == 0:
        raise ValueError("sample: no values")
    bad = np.flatnonzero(~np.isfinite(x))
    if bad.size:
        raise ValueError(f"sample: value {bad[0] + 1} is {x[bad[0]]:g} (NaN or infinite)")
    xs = np.sort(x)
    u = np.asarray(cdf(xs, *args))
    if u.shape != xs.shape or u.dtype.kind not in "biuf":
        raise ValueError(f"cdf: returned {u.dtype} of shape {u.shape} for {n} values: a "
                         f"callable CDF is called once with the sorted sample (as scipy "
                         f"calls it) and must return an array of its shape")
    u = np.ascontiguousarray(u, dtype=np.float64)
    out = np.flatnonzero(~((u >= 0.0) & (u <= 1.0)))
    if out.size:
        i = out[0]
        raise ValueError(f"CDF returned {u[i]:g} at x = {xs[i]:g}, outside [0, 1]")
    dp, dm = ctypes.c_double(), ctypes.c_double()
    _ks_statistic(_ptr(u), n, ctypes.byref(dp), ctypes.byref(dm))
    return dp.value, dm.value


def _check_cdf(cdf):
    if not isinstance(cdf, str) and not callable(cdf):
        raise TypeError(f"cdf: expected a distribution name or a callable, got {cdf!r}")


def _alternative(alternative):
    alt, err = ctypes.c_int(), Error()
    if not isinstance(alternative, str):
        raise TypeError(f"alternative: expected a str, got {type(alternative).__name__}")
    check(_alternative_parse(alternative.encode(), ctypes.byref(alt), ctypes.byref(err)), err)
    return alt.value


def _method(method, allowed):
    if method not in allowed:
        raise ValueError(f"method: {method!r} is not one of {', '.join(map(repr, allowed))}")
    return method


def _ks_result(res, sign):
    return KstestResult(res.d, res.p, res.d_plus, res.d_minus, res.n, res.n2,
                        _ks_method_name(res.method).decode(), sign)


def kstest(rvs: ArrayLike, cdf: Union[str, Callable[..., Any]], args: Sequence[float] = (),
           alternative: str = "two-sided", method: str = "auto") -> KstestResult:
    """One-sample Kolmogorov-Smirnov test, as scipy.stats.kstest (1.10).

    D and its p-value equal scipy's to 1e-15 (absolute) and 1e-10 (relative)
    for the exact laws (src/stats/nl_stats.h; the test suite measures it).

    Parameters
    ----------
    rvs : array_like
        the sample (flattened); NaN or infinite values are a ValueError.
    cdf : str or callable
        one of scipy.stats' names the library has (uniform, norm, expon, gamma,
        beta, lognorm, t, chi2, weibull_min, cauchy, logistic, laplace, pareto,
        rayleigh), or a vectorised F(x, *args): called once with the whole
        sorted sample, it returns an array of CDF values in [0, 1].
    args : tuple
        for a name, scipy's (shapes..., loc, scale), loc and scale optional
        (default 0, 1); extra arguments of a callable.
    alternative : str
        'two-sided' (D = max(D+, D-)), 'less' (D- = max(F - F_n): the
        sample's CDF lies below F) or 'greater' (D+ = max(F_n - F)); the
        one-sided p-values are the exact Smirnov law (scipy's ksone.sf).
    method : str
        the two-sided p-value: 'auto' and 'exact' the exact law
        (scipy's kstwo.sf), 'asymp' Kolmogorov's limit at D sqrt(n)
        (kstwobign.sf), 'approx' twice the one-sided law; one-sided tests
        are always exact, as in scipy.

    Returns
    -------
    KstestResult: unpacks as (statistic, pvalue); also d_plus, d_minus, n,
    method (the law that gave the p-value) and statistic_sign.

    Example
    -------
    >>> import numpy as np, noiselab.stats as ns
    >>> x = np.random.default_rng(1).normal(2.0, 3.0, 500)
    >>> D, p = ns.kstest(x, 'norm', args=(2.0, 3.0))
    >>> p > 0.01
    True
    >>> r = ns.kstest(x, 'norm', args=(2.0, 3.0), alternative='less')
    >>> r.statistic == r.d_minus, r.statistic_sign
    (True, -1)
    """
    x = _sample("rvs", rvs)
    alt = _alternative(alternative)
    _method(method, ("auto", "exact", "asymp", "approx"))
    _check_cdf(cdf)
    res, err = _KsResult(), Error()
    if isinstance(cdf, str):
        c = _Cdf(cdf, args)
        check(_ks_test(_ptr(x), x.size, c.fn, c.params, ctypes.byref(res), ctypes.byref(err)),
              err)
    else:
        res.d_plus, res.d_minus = _callable_statistic(x, cdf, args)
        res.d = max(res.d_plus, res.d_minus)
        res.n = x.size
        m = ctypes.c_int()
        res.p = _ks_sf(res.n, res.d, ctypes.byref(m))
        res.method = m.value
    if alt != _TWO_SIDED:
        _ks_one_sided(ctypes.byref(res), alt)
        return _ks_result(res, 1 if alt == _GREATER else -1)
    if method == "asymp":
        res.p = min(max(_kolmogorov_sf(res.d * math.sqrt(res.n)), 0.0), 1.0)
        res.method = _KOLMOGOROV
    elif method == "approx":
        res.p = min(max(2 * _smirnov_sf(res.n, res.d), 0.0), 1.0)
        res.method = _SMIRNOV
    return _ks_result(res, 1 if res.d_plus > res.d_minus else -1)


def ks_2samp(data1: ArrayLike, data2: ArrayLike, alternative: str = "two-sided",
             method: str = "auto") -> KstestResult:
    """Two-sample Kolmogorov-Smirnov test, as scipy.stats.ks_2samp (1.10).

    Parameters
    ----------
    data1, data2 : array_like
        the samples (flattened), finite.
    alternative : str
        'two-sided', 'less' (D- = max(F_2 - F_1)) or 'greater'
        (D+ = max(F_1 - F_2)).
    method : str
        'auto': the exact law (lattice paths) when both sizes are <= 10000,
        else the asymptotic one; 'exact' the exact law at any size (slow for
        large ones; where a count overflows it warns and falls back to
        'asymp', as scipy); 'asymp' the one-sample law at the effective size
        n1 n2 / (n1 + n2) (two-sided) or Hodges' corrected limit (one-sided).
        Where the exact law gives the p-value the statistic is reported on
        its lattice (h / lcm(n1, n2)), as scipy reports it.

    Returns
    -------
    KstestResult: unpacks as (statistic, pvalue); also d_plus, d_minus, n,
    n2, method and statistic_sign.

    Example
    -------
    >>> import numpy as np, noiselab.stats as ns
    >>> rng = np.random.default_rng(2)
    >>> D, p = ns.ks_2samp(rng.random(100), rng.random(80), method="asymp")
    >>> D < 0.3
    True
    """
    x, y = _sample("data1", data1), _sample("data2", data2)
    alt = _alternative(alternative)
    want = {"auto": -1, "exact": _TWO_SAMPLE_EXACT,
            "asymp": _TWO_SAMPLE_ASYMP}[_method(method, ("auto", "exact", "asymp"))]
    res, err = _KsResult(), Error()
    check(_ks2_test(_ptr(x), x.size, _ptr(y), y.size, ctypes.byref(res), ctypes.byref(err)),
          err)
    d = (res.d_plus if alt == _GREATER else res.d_minus if alt == _LESS else
         max(res.d_plus, res.d_minus))
    m = ctypes.c_int()
    res.p = _ks2_sf_method(x.size, y.size, d, alt != _TWO_SIDED, want, ctypes.byref(m))
    res.method = m.value
    if method == "exact" and m.value != _TWO_SAMPLE_EXACT:
        warnings.warn("ks_2samp: Exact calculation unsuccessful. Switching to method=asymp.",
                      RuntimeWarning, stacklevel=2)
    g = math.gcd(x.size, y.size)
    if m.value == _TWO_SAMPLE_EXACT or (method == "exact" and
                                        x.size // g < (2**31 - 1) / (y.size // g)):
        # the lattice value the exact p belongs to, as scipy reports it (also
        # after an exact try fell back: nl_stats_ks2_sf_method)
        lcm = float(x.size // g * y.size)
        d = round(d * lcm) / lcm
    res.d = d
    sign = -1 if alt == _LESS or (alt == _TWO_SIDED and res.d_minus > res.d_plus) else 1
    return _ks_result(res, sign)


def kuiper(rvs: ArrayLike, cdf: Union[str, Callable[..., Any]],
           args: Sequence[float] = ()) -> KuiperResult:
    """Kuiper's test, V = D+ + D-: the KS of a circle (it does not depend on
    where the circle is cut), p-value as astropy.stats.kuiper's.

    Parameters
    ----------
    rvs : array_like       the sample (angles scaled to the distribution's range)
    cdf : str or callable  as kstest's (a named distribution with args, or F)
    args : tuple           the distribution's shapes, loc and scale

    Returns
    -------
    KuiperResult : statistic (V), pvalue; unpacks as (statistic, pvalue)

    Example
    -------
    >>> import numpy as np, noiselab.stats as ns
    >>> theta = np.random.default_rng(3).uniform(0, 2 * np.pi, 512)
    >>> r = ns.kuiper(theta, 'uniform', args=(0, 2 * np.pi))
    >>> 0 <= r.pvalue <= 1
    True
    """
    x = _sample("rvs", rvs)
    _check_cdf(cdf)
    if not isinstance(cdf, str):
        dp, dm = _callable_statistic(x, cdf, args)
        v = dp + dm
        return KuiperResult(v, _kuiper_sf(x.size, v), dp, dm, x.size)
    c = _Cdf(cdf, args)
    res, err = _KuiperResult(), Error()
    check(_kuiper_test(_ptr(x), x.size, c.fn, c.params, ctypes.byref(res), ctypes.byref(err)),
          err)
    return KuiperResult(res.v, res.p, res.d_plus, res.d_minus, res.n)


def chisquare(f_obs: ArrayLike, f_exp: Optional[ArrayLike] = None,
              axis: Optional[int] = 0) -> ChisquareResult:
    """Pearson's chi-square test of observed counts, scipy.stats.chisquare
    (1.10) with ddof 0.

    Parameters
    ----------
    f_obs : array_like
        observed counts; a test of each slice along ``axis``.
    f_exp : array_like, optional
        expected counts, broadcast against f_obs; by default each slice's
        mean (equal expected counts). Each slice's expected counts must sum
        to its observed ones within scipy's relative tolerance 1e-8, else
        ValueError (scipy's check, in one line).
    axis : int or None
        the axis of the categories (0, scipy's default: columns of a 2-D
        table are separate tests); None flattens both arrays first.

    Returns
    -------
    ChisquareResult: unpacks as (statistic, pvalue); also df = k - 1,
    min_expected and low_expected (an expected count < 5, Cochran's rule).
    Scalars for 1-D input, else arrays of the slices' results (the shape of
    f_obs without ``axis``).

    Example
    -------
    >>> import noiselab.stats as ns
    >>> chi2, p = ns.chisquare([16, 18, 16, 14, 12, 12])
    >>> round(chi2, 6), ns.chisquare([16, 18, 16, 14, 12, 12]).df
    (2.0, 5)
    >>> ns.chisquare([[10, 20], [20, 20], [30, 20]]).statistic.tolist()   # per column
    [10.0, 0.0]
    """
    o = np.asarray(f_obs)
    if o.dtype.kind not in "biuf":
        raise TypeError(f"f_obs: expected real numbers, got dtype {o.dtype}")
    o = o.astype(np.float64)
    if f_exp is not None:
        e = np.asarray(f_exp)
        if e.dtype.kind not in "biuf":
            raise TypeError(f"f_exp: expected real numbers, got dtype {e.dtype}")
        try:
            o, e = np.broadcast_arrays(o, e.astype(np.float64))
        except ValueError:
            raise ValueError(f"f_exp: shape {e.shape} does not broadcast against f_obs's "
                             f"{o.shape}") from None
    if axis is None:
        o = o.ravel()
        if f_exp is not None:
            e = e.ravel()
        axis = 0
    if o.ndim == 0:
        raise ValueError("f_obs: expected an array of counts, got a scalar")
    axis = int(axis)
    if not -o.ndim <= axis < o.ndim:
        raise ValueError(f"axis: {axis} is out of bounds for f_obs of {o.ndim} dimensions")
    if f_exp is None:
        e = np.broadcast_to(o.mean(axis=axis, keepdims=True), o.shape)
    else:
        # scipy's check, in its words and tolerance
        rtol = 1e-8
        so, se = o.sum(axis=axis), e.sum(axis=axis)
        with np.errstate(invalid="ignore", divide="ignore"):
            rd = np.abs(so - se) / np.minimum(so, se)
        if np.any(rd > rtol):
            worst = np.unravel_index(np.nanargmax(np.where(rd > rtol, rd, np.nan)), rd.shape)
            where = f" (slice {worst[0] if len(worst) == 1 else worst})" if rd.ndim else ""
            raise ValueError(f"f_exp: for each axis slice, the sum of the observed frequencies "
                             f"must agree with the sum of the expected frequencies to a "
                             f"relative tolerance of {rtol}, but the relative difference is "
                             f"{float(rd[worst]):.3g}{where}")
    o2 = np.ascontiguousarray(np.moveaxis(o, axis, -1), dtype=np.float64)
    e2 = np.ascontiguousarray(np.moveaxis(e, axis, -1), dtype=np.float64)
    shape, k = o2.shape[:-1], o2.shape[-1]
    o2, e2 = o2.reshape(-1, k), e2.reshape(-1, k)
    rows = []
    for i in range(o2.shape[0]):
        res, err = _ChisqResult(), Error()
        check(_chisq_test(_ptr(o2[i]), _ptr(e2[i]), k, ctypes.byref(res), ctypes.byref(err)),
              err)
        rows.append((res.chi2, res.p, int(res.df), res.min_expected, bool(res.low_expected)))
    if not shape:
        return ChisquareResult(*rows[0])
    cols = [np.array([r[j] for r in rows]).reshape(shape) for j in range(5)]
    return ChisquareResult(*cols)


def mean_sd(x: ArrayLike, rounding: str = "running") -> Tuple[float, float]:
    """The mean and sample sd (divisor n - 1) of x in one of the library's two
    named roundings, so that the numbers of a committed table come back to
    the bit: 'running' is GSL's running mean and sd (gsl_stats_mean,
    gsl_stats_sd), 'summed' the sum in order over n, then the sum of squares.
    An empty x has no mean: ValueError (statistics.mean raises too).

    Parameters
    ----------
    x : array_like         real numbers, at least one, all finite
    rounding : str         'running' (GSL's) or 'summed'

    Returns
    -------
    (mean, sd) : two floats; sd is 0 for one value

    Example
    -------
    >>> import noiselab.stats as ns
    >>> ns.mean_sd([1.0, 2.0, 4.0])
    (2.3333333333333335, 1.5275252316519468)
    """
    a = _sample("x", x)
    if rounding not in ("running", "summed"):
        raise ValueError(f"rounding: {rounding!r} is not 'running' or 'summed'")
    m, sd, err = ctypes.c_double(), ctypes.c_double(), Error()
    check(_mean_sd(_ptr(a), a.size, 0 if rounding == "running" else 1, ctypes.byref(m),
                   ctypes.byref(sd), ctypes.byref(err)), err, {"sample": "x"})
    return m.value, sd.value


def linkage(y: ArrayLike, method: str = "single",
            metric: str = "euclidean") -> NDArray[np.float64]:
    """Agglomerative clustering, as scipy.cluster.hierarchy.linkage(y,
    method, metric).

    Parameters
    ----------
    y : array_like
        n >= 2 observations as the rows of an (n, d) array, or a condensed
        distance matrix: 1-D of length n(n-1)/2, the entries i < j row by row
        (scipy.spatial.distance.pdist's layout), taken as given (then
        ``metric`` is not used), finite and >= 0.
    method : str
        'single', 'complete', 'average', 'weighted', 'ward', 'centroid' or
        'median' (the last three need the Euclidean metric on observations;
        on condensed distances they read them as Euclidean, as scipy does).
    metric : str
        for observations: 'euclidean', 'sqeuclidean', 'cityblock',
        'chebyshev', 'cosine', 'correlation', 'canberra' or 'braycurtis',
        pdist's formulas.

    Returns
    -------
    Z : ndarray (n - 1, 4): merged clusters a < b, height, size (scipy's layout)

    Example
    -------
    >>> import numpy as np, noiselab.stats as ns
    >>> ns.linkage(np.array([[0.0], [1.0], [5.0]]), 'single').tolist()
    [[0.0, 1.0, 1.0, 2.0], [2.0, 3.0, 4.0, 3.0]]
    >>> ns.linkage(np.array([1.0, 5.0, 4.0]), 'single').tolist()   # condensed
    [[0.0, 1.0, 1.0, 2.0], [2.0, 3.0, 4.0, 3.0]]
    """
    a = np.asarray(y)
    if a.dtype.kind not in "biuf":
        raise TypeError(f"y: expected real numbers, got dtype {a.dtype}")
    m, err = ctypes.c_int(), Error()
    check(_linkage_parse(str(method).encode(), ctypes.byref(m), ctypes.byref(err)), err)
    met = ctypes.c_int()
    check(_metric_parse(str(metric).encode(), ctypes.byref(met), ctypes.byref(err)), err)
    if a.ndim == 1:
        c = np.ascontiguousarray(a, dtype=np.float64)
        n = int(round((1 + math.sqrt(1 + 8 * c.size)) / 2))
        if c.size == 0 or n * (n - 1) // 2 != c.size:
            raise ValueError(f"y: a condensed distance matrix has n(n-1)/2 entries for n >= 2 "
                             f"observations; {c.size} is no such number")
        Z = np.empty((n - 1, 4), dtype=np.float64)
        check(_linkage_condensed(_ptr(c), n, m.value, _ptr(Z), ctypes.byref(err)), err)
        return Z
    if a.ndim != 2:
        raise ValueError(f"y: expected observations (n, d) or a condensed distance matrix "
                         f"(1-D), got shape {a.shape}")
    x = np.ascontiguousarray(a, dtype=np.float64)
    n, d = x.shape
    if n < 2:
        raise ValueError(f"y: {n} observations; linkage needs at least 2")
    Z = np.empty((n - 1, 4), dtype=np.float64)
    check(_linkage_metric(_ptr(x), n, d, m.value, met.value, _ptr(Z), ctypes.byref(err)), err)
    return Z


from ._gmm import GaussianMixture  # noqa: E402  (after the helpers it imports)

__all__ = ["kstest", "ks_2samp", "kuiper", "chisquare", "linkage", "GaussianMixture", "mean_sd",
           "KstestResult", "KuiperResult", "ChisquareResult"]
