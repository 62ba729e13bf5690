"""Statistics of libnoiselab with scipy's and scikit-learn's habits.

  kstest(x, 'norm', args=(loc, scale))   one-sample KS (scipy.stats.kstest)
  ks_2samp(x, y)                          two-sample KS (scipy.stats.ks_2samp)
  kuiper(x, 'uniform', args=(0, 2*pi))    Kuiper's V (astropy's p-value)
  chisquare(f_obs, f_exp=None)            Pearson (scipy.stats.chisquare)
  linkage(X, method)                      scipy.cluster.hierarchy.linkage's matrix
  GaussianMixture(n_components, ...)      fit, score, score_samples, aic, bic, predict

Results carry scipy's attribute names (statistic, pvalue) and the library's
extra fields. Distributions by name: 'uniform', 'norm', 'expon' with scipy's
loc/scale arguments, or any callable F(x, *args) returning a CDF value in
[0, 1] (called once per sample value from C).
"""

import ctypes
from dataclasses import dataclass

import numpy as np

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
_kuiper_test = fn("nl_stats_kuiper_test", ctypes.c_int, c_double_p, ctypes.c_size_t, _CDF,
                  ctypes.c_void_p, ctypes.POINTER(_KuiperResult), _E)
_chisq_test = fn("nl_stats_chisq_test", ctypes.c_int, c_double_p, c_double_p, ctypes.c_size_t,
                 ctypes.POINTER(_ChisqResult), _E)
_mean_sd = fn("nl_stats_mean_sd_checked", ctypes.c_int, c_double_p, ctypes.c_size_t, ctypes.c_int,
               c_double_p, c_double_p, _E)
_linkage_parse = fn("nl_cluster_linkage_method_parse", ctypes.c_int, ctypes.c_char_p,
                    ctypes.POINTER(ctypes.c_int), _E)
_linkage = fn("nl_cluster_linkage", ctypes.c_int, c_double_p, ctypes.c_size_t, ctypes.c_size_t,
              ctypes.c_int, c_double_p, _E)


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


@dataclass(frozen=True)
class KstestResult:
    """statistic (D), pvalue, and D+, D-, the sizes and the p-value's method."""
    statistic: float
    pvalue: float
    d_plus: float
    d_minus: float
    n: int
    n2: int
    method: str


@dataclass(frozen=True)
class KuiperResult:
    """statistic (V = D+ + D-), pvalue P(V_n >= V), D+ and D-."""
    statistic: float
    pvalue: float
    d_plus: float
    d_minus: float
    n: int


@dataclass(frozen=True)
class ChisquareResult:
    """statistic (chi2), pvalue, df = k - 1 and Cochran's warning (an expected count < 5)."""
    statistic: float
    pvalue: float
    df: int
    min_expected: float
    low_expected: bool


class _Cdf:
    """A CDF for the C tests: a named distribution or a Python callable."""

    def __init__(self, cdf, args):
        err = Error()
        if isinstance(cdf, str):
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
        elif callable(cdf):
            self.error = None

            def call(x, _):
                if self.error is not None:
                    return 0.0
                try:
                    return float(cdf(x, *args))
                except Exception as e:   # an exception cannot cross C: kept, raised after
                    self.error = e
                    return 0.0
            self.fn = _CDF(call)
            self.params = None
        else:
            raise TypeError(f"cdf: expected a distribution name or a callable, got {cdf!r}")

    def raise_pending(self):
        if getattr(self, "error", None) is not None:
            raise self.error


def kstest(rvs, cdf, args=()):
    """One-sample Kolmogorov-Smirnov test, two-sided, exact p-value.

    As scipy.stats.kstest(rvs, cdf, args) with method 'auto': D agrees with
    scipy to the last bit and the p-value (scipy.stats.kstwo.sf) to 1e-10
    relative (src/stats/nl_stats.h).

    Parameters
    ----------
    rvs : array_like
        the sample (flattened); NaN or infinite values are a ValueError.
    cdf : str or callable
        one of scipy.stats' names the library has (uniform, norm, expon, gamma,
        beta, lognorm, t, chi2, weibull_min, cauchy, logistic, laplace, pareto,
        rayleigh), or F(x, *args) -> [0, 1].
    args : tuple
        for a name, scipy's (shapes..., loc, scale), loc and scale optional
        (default 0, 1); extra arguments of a callable.

    Returns
    -------
    KstestResult with statistic, pvalue (and d_plus, d_minus, n, method)

    Example
    -------
    >>> import numpy as np, noiselab.stats as ns
    >>> x = np.random.default_rng(1).normal(2.0, 3.0, 500)
    >>> r = ns.kstest(x, 'norm', args=(2.0, 3.0))
    >>> r.pvalue > 0.01
    True
    """
    x = _sample("rvs", rvs)
    c = _Cdf(cdf, args)
    res, err = _KsResult(), Error()
    s = _ks_test(_ptr(x), x.size, c.fn, c.params, ctypes.byref(res), ctypes.byref(err))
    c.raise_pending()
    check(s, err)
    return KstestResult(res.d, res.p, res.d_plus, res.d_minus, res.n, res.n2,
                        _ks_method_name(res.method).decode())


def ks_2samp(data1, data2):
    """Two-sample Kolmogorov-Smirnov test, as scipy.stats.ks_2samp(method='auto').

    The p-value is exact (lattice paths) when both sizes are <= 10000, else
    the one-sample law at the effective size.

    Example
    -------
    >>> import numpy as np, noiselab.stats as ns
    >>> rng = np.random.default_rng(2)
    >>> ns.ks_2samp(rng.random(100), rng.random(80)).statistic < 0.3
    True
    """
    x, y = _sample("data1", data1), _sample("data2", data2)
    res, err = _KsResult(), Error()
    check(_ks2_test(_ptr(x), x.size, _ptr(y), y.size, ctypes.byref(res), ctypes.byref(err)),
          err)
    return KstestResult(res.d, res.p, res.d_plus, res.d_minus, res.n, res.n2,
                        _ks_method_name(res.method).decode())


def kuiper(rvs, cdf, args=()):
    """Kuiper's test, V = D+ + D-: the KS of a circle (it does not depend on
    where the circle is cut), p-value as astropy.stats.kuiper's.

    Parameters as kstest.

    Example
    -------
    >>> import numpy as np, noiselab.stats as ns
    >>> theta = np.random.default_rng(3).uniform(0, 2 * np.pi, 512)
    >>> r = ns.kuiper(theta, 'uniform', args=(0, 2 * np.pi))
    >>> 0 <= r.pvalue <= 1
    True
    """
    x = _sample("rvs", rvs)
    c = _Cdf(cdf, args)
    res, err = _KuiperResult(), Error()
    s = _kuiper_test(_ptr(x), x.size, c.fn, c.params, ctypes.byref(res), ctypes.byref(err))
    c.raise_pending()
    check(s, err)
    return KuiperResult(res.v, res.p, res.d_plus, res.d_minus, res.n)


def chisquare(f_obs, f_exp=None):
    """Pearson's chi-square test of observed counts, scipy.stats.chisquare.

    f_exp defaults to equal expected counts (the mean of f_obs); df = k - 1.

    Example
    -------
    >>> import noiselab.stats as ns
    >>> r = ns.chisquare([16, 18, 16, 14, 12, 12])
    >>> round(r.statistic, 6), r.df
    (2.0, 5)
    """
    o = _sample("f_obs", f_obs)
    e = np.full(o.size, o.mean()) if f_exp is None else _sample("f_exp", f_exp)
    if e.size != o.size:
        raise ValueError(f"f_exp: {e.size} expected counts for {o.size} observed")
    res, err = _ChisqResult(), Error()
    check(_chisq_test(_ptr(o), _ptr(e), o.size, ctypes.byref(res), ctypes.byref(err)), err)
    return ChisquareResult(res.chi2, res.p, res.df, res.min_expected, bool(res.low_expected))


def mean_sd(x, rounding="running"):
    """The mean and sample sd (divisor n - 1) of x in one of the library's two
    named roundings, so that the numbers of a committed table come back to
    the bit: 'running' is GSL's running mean and sd (gsl_stats_mean,
    gsl_stats_sd), 'summed' the sum in order over n, then the sum of squares.
    An empty x has no mean: ValueError (statistics.mean raises too).

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


def linkage(X, method="single"):
    """Agglomerative clustering of the rows of X (Euclidean), as
    scipy.cluster.hierarchy.linkage(X, method).

    Parameters
    ----------
    X : array_like, shape (n, d)
        n >= 2 observations (a condensed distance matrix is not accepted).
    method : str
        'single', 'complete', 'average' or 'ward'.

    Returns
    -------
    Z : ndarray (n - 1, 4): merged clusters a < b, height, size (scipy's layout)

    Example
    -------
    >>> import numpy as np, noiselab.stats as ns
    >>> ns.linkage(np.array([[0.0], [1.0], [5.0]]), 'single').tolist()
    [[0.0, 1.0, 1.0, 2.0], [2.0, 3.0, 4.0, 3.0]]
    """
    x = _sample("X", X, ndim=2)
    m, err = ctypes.c_int(), Error()
    check(_linkage_parse(str(method).encode(), ctypes.byref(m), ctypes.byref(err)), err)
    n, d = x.shape
    if n < 2:
        raise ValueError(f"X: {n} observations; linkage needs at least 2")
    Z = np.empty((n - 1, 4), dtype=np.float64)
    check(_linkage(_ptr(x), n, d, m.value, _ptr(Z), ctypes.byref(err)), err)
    return Z


from ._gmm import GaussianMixture  # noqa: E402  (after the helpers it imports)

__all__ = ["kstest", "ks_2samp", "kuiper", "chisquare", "linkage", "GaussianMixture", "mean_sd",
           "KstestResult", "KuiperResult", "ChisquareResult"]
