"""noiselab.stats against scipy and scikit-learn, to the C tests' tolerances
(src/stats/test_gof.c, test_cluster.c, test_gmm.c): statistics D, D+, D-, V
1e-15 absolute; KS and two-sample p-values 1e-10 relative; chi-square 1e-12
(statistic) and 1e-10 (p) relative; Kuiper p 1e-9 relative against astropy's
committed values; linkage heights 1e-12 relative with the same merges;
GMM log-likelihood, AIC, BIC 1e-8 relative, same iteration count."""
import os
import zlib

import numpy as np
import pytest
import scipy.cluster.hierarchy as sch
import scipy.stats as st
from sklearn.mixture import GaussianMixture as SkGMM

from conftest import ROOT
import noiselab.stats as ns

DATA = os.path.join(ROOT, "tests", "data", "stats")


def rel(a, b, tol):
    return abs(a - b) <= tol * abs(b) + 1e-300


@pytest.mark.parametrize("n", [10, 100, 512, 5000])
@pytest.mark.parametrize("dist,args,draw", [
    ("norm", (1.5, 2.0), lambda r, n: r.normal(1.5, 2.0, n)),
    ("norm", (0.0, 1.0), lambda r, n: r.normal(0.1, 1.0, n)),
    ("expon", (0.5, 3.0), lambda r, n: 0.5 + r.exponential(3.0, n)),
    ("uniform", (0.0, 2 * np.pi), lambda r, n: r.uniform(0, 2 * np.pi, n) ** 1.02),
    ("gamma", (2.5, 0.1, 1.5), lambda r, n: 0.1 + r.gamma(2.5, 1.5, n)),
    ("lognorm", (0.7, 0.0, 2.0), lambda r, n: 2.0 * r.lognormal(0.0, 0.72, n)),
    ("weibull_min", (1.3,), lambda r, n: r.weibull(1.3, n)),
])
def test_kstest_is_scipy(n, dist, args, draw):
    x = draw(np.random.default_rng(n), n)
    a, b = ns.kstest(x, dist, args=args), st.kstest(x, dist, args=args)
    assert abs(a.statistic - b.statistic) <= 1e-15
    assert rel(a.pvalue, b.pvalue, 1e-10), (a.pvalue, b.pvalue)
    c = ns.kstest(x, getattr(st, dist).cdf, args=args)   # a callable CDF
    assert abs(c.statistic - b.statistic) <= 1e-15 and rel(c.pvalue, b.pvalue, 1e-10)


@pytest.mark.parametrize("n1,n2,shift", [(10, 12, 0.5), (100, 80, 0.2), (512, 512, 0.05),
                                          (3000, 2000, 0.0), (12000, 9000, 0.03)])
def test_ks_2samp_is_scipy(n1, n2, shift):
    r = np.random.default_rng(n1 + n2)
    x, y = r.normal(0, 1, n1), r.normal(shift, 1, n2)
    a, b = ns.ks_2samp(x, y), st.ks_2samp(x, y)
    assert abs(a.statistic - b.statistic) <= 1e-15
    assert rel(a.pvalue, b.pvalue, 1e-10), (a.pvalue, b.pvalue)


def test_kuiper_is_astropy():
    """Against astropy's kuiper_false_positive_probability, committed in
    tests/data/stats/kuiper_one.tsv (astropy is not a Debian dependency)."""
    with open(os.path.join(DATA, "kuiper_one.tsv"), encoding="utf-8") as f:
        head = f.readline().split()
        rows = [dict(zip(head, line.split())) for line in f]
    assert len(rows) >= 8
    for row in rows:
        row["v"], row["p"] = float(row["v"]), float(row["p"])
        x = np.loadtxt(os.path.join(DATA, row["file"]), skiprows=1)
        r = ns.kuiper(x, "uniform", args=(0, 2 * np.pi))
        assert abs(r.statistic - row["v"]) <= 1e-15
        assert rel(r.pvalue, row["p"], 1e-9), (row["file"], r.pvalue, row["p"])
        assert r.statistic == pytest.approx(r.d_plus + r.d_minus, abs=1e-15)


@pytest.mark.parametrize("k,n", [(2, 100), (10, 1000), (64, 5000), (500, 512)])
def test_chisquare_is_scipy(k, n):
    r = np.random.default_rng(k)
    obs = np.bincount(r.integers(0, k, n), minlength=k).astype(float)
    a, b = ns.chisquare(obs), st.chisquare(obs)
    assert rel(a.statistic, b.statistic, 1e-12) and rel(a.pvalue, b.pvalue, 1e-10)
    assert a.df == k - 1 and a.low_expected == (n / k < 5)
    exp = r.uniform(0.5, 1.5, k)
    exp *= obs.sum() / exp.sum()
    a, b = ns.chisquare(obs, exp), st.chisquare(obs, exp)
    assert rel(a.statistic, b.statistic, 1e-12) and rel(a.pvalue, b.pvalue, 1e-10)


@pytest.mark.parametrize("method", ["single", "complete", "average", "ward"])
def test_linkage_is_scipy(method):
    X = np.random.default_rng(5).normal(size=(300, 3))
    a, b = ns.linkage(X, method), sch.linkage(X, method)
    assert a.shape == (299, 4)
    assert np.array_equal(a[:, [0, 1, 3]], b[:, [0, 1, 3]])
    assert np.all(np.abs(a[:, 2] - b[:, 2]) <= 1e-12 * np.abs(b[:, 2]))


class _SkFromLabels(SkGMM):
    """scikit-learn's EM started from given labels, as make_stats_vectors.py does."""

    def __init__(self, labels=None, **kw):
        super().__init__(**kw)
        self.labels = labels

    def _initialize_parameters(self, X, random_state):
        resp = np.zeros((X.shape[0], self.n_components))
        resp[np.arange(X.shape[0]), self.labels] = 1
        self._initialize(X, resp)


@pytest.mark.parametrize("cov", ["full", "diag", "tied", "spherical"])
@pytest.mark.parametrize("k", [1, 2, 3])
def test_gmm_is_sklearn(cov, k):
    r = np.random.default_rng(40 + k)
    X = np.vstack([r.normal(4 * j, 1 + 0.3 * j, (150 + 30 * j, 3)) @ r.normal(size=(3, 3))
                   for j in range(3)])
    labels = r.integers(0, k, len(X))
    ours = ns.GaussianMixture(k, covariance_type=cov).fit(X, init_labels=labels)
    sk = _SkFromLabels(labels=labels, n_components=k, covariance_type=cov, tol=1e-3,
                       reg_covar=1e-6, max_iter=100).fit(X)
    assert ours.n_iter_ == sk.n_iter_ and ours.converged_ == sk.converged_
    for f in ("score", "aic", "bic"):
        assert rel(getattr(ours, f)(X), getattr(sk, f)(X), 1e-8), f
    assert np.allclose(ours.weights_, sk.weights_, atol=1e-6)
    assert np.allclose(ours.means_, sk.means_, atol=1e-6)
    assert np.allclose(ours.score_samples(X), sk.score_samples(X), rtol=1e-8, atol=0)
    assert np.mean(ours.predict(X) == sk.predict(X)) > 0.999
    assert np.allclose(ours.predict_proba(X), sk.predict_proba(X), atol=1e-6)
    # sklearn's shapes and values for the covariances and precisions
    for f in ("covariances_", "precisions_", "precisions_cholesky_"):
        a, b = getattr(ours, f), getattr(sk, f)
        assert a.shape == b.shape, f
        assert np.allclose(a, b, rtol=1e-5, atol=1e-8), f


def _two_blobs(seed=0):
    r = np.random.default_rng(seed)
    return np.vstack([r.normal(0, 1, (200, 2)), r.normal(8, 1, (200, 2))])


def test_gmm_is_an_estimator():
    """scikit-learn's estimator habits: clone, get/set_params, pickle,
    fit_predict, random_state as None, int, RandomState or Generator."""
    import pickle
    from sklearn.base import clone
    from sklearn.utils.estimator_checks import check_get_params_invariance, check_set_params
    X = _two_blobs()
    g = ns.GaussianMixture(2, covariance_type="diag", tol=1e-4, random_state=3)
    check_get_params_invariance("GaussianMixture", g)
    check_set_params("GaussianMixture", g)
    c = clone(g)
    assert c.get_params() == g.get_params() and c is not g
    assert g.set_params(max_iter=50) is g and g.max_iter == 50
    with pytest.raises(ValueError, match="'bogus' is not a parameter"):
        g.set_params(bogus=1)
    g.fit(X)
    back = pickle.loads(pickle.dumps(g))
    assert np.array_equal(back.score_samples(X), g.score_samples(X))
    assert np.array_equal(back.predict(X), g.predict(X))
    assert np.array_equal(back.means_, g.means_)
    unfitted = pickle.loads(pickle.dumps(ns.GaussianMixture(3)))
    assert unfitted.n_components == 3
    lab = ns.GaussianMixture(2, random_state=1).fit_predict(X)
    assert np.array_equal(lab, ns.GaussianMixture(2, random_state=1).fit(X).predict(X))
    for rs in (None, 7, np.random.RandomState(7), np.random.default_rng(7)):
        m = ns.GaussianMixture(2, random_state=rs).fit(X)
        assert sorted(np.round(m.means_[:, 0]).tolist()) == [0.0, 8.0], rs


@pytest.mark.parametrize("cov", ["full", "diag", "tied", "spherical"])
def test_gmm_sample_is_the_mixture(cov):
    """sample(n): rows grouped by component (sklearn's order), the same draws
    for the same int random_state, and each group's mean near its component's."""
    X = _two_blobs(1)
    g = ns.GaussianMixture(2, covariance_type=cov, random_state=5).fit(X)
    Xs, ys = g.sample(4000)
    assert Xs.shape == (4000, 2) and ys.shape == (4000,)
    assert np.all(np.diff(ys) >= 0)
    Xs2, ys2 = g.sample(4000)
    assert np.array_equal(Xs, Xs2) and np.array_equal(ys, ys2)
    for j in range(2):
        # 4 standard errors of a mean of about 2000 unit-variance draws
        assert np.allclose(Xs[ys == j].mean(axis=0), g.means_[j], atol=4 * 1.2 / np.sqrt(1000))
    assert abs(np.mean(ys == 0) - g.weights_[0]) < 4 * np.sqrt(0.25 / 4000)


def test_gmm_kmeans_init_finds_clusters():
    r = np.random.default_rng(0)
    X = np.vstack([r.normal(0, 1, (200, 2)), r.normal(8, 1, (200, 2))])
    g = ns.GaussianMixture(2, random_state=1).fit(X)
    assert sorted(np.round(g.means_[:, 0]).tolist()) == [0.0, 8.0]
    lab = g.predict(X)
    assert len(set(lab[:200])) == 1 and len(set(lab[200:])) == 1 and lab[0] != lab[-1]


@pytest.mark.parametrize("call,exc,words", [
    (lambda: ns.kstest([0.1, np.nan], "norm"), ValueError, "value 2 is nan"),
    (lambda: ns.kstest([0.1, 0.2], "gamma"), ValueError, "gamma"),
    (lambda: ns.kstest([0.1, 0.2], "norm", args=(0, -1)), ValueError, "scale"),
    (lambda: ns.kstest(np.array(["a"]), "norm"), TypeError, "rvs: expected real"),
    (lambda: ns.kstest([0.1], lambda x: 2.0), ValueError, ""),
    (lambda: ns.kstest([0.1], lambda x: 1 / 0), ZeroDivisionError, "division"),
    (lambda: ns.chisquare([1, 2, 3], [1, 2]), ValueError, "f_exp: shape (2,) does not broadcast"),
    (lambda: ns.linkage(np.zeros(5), "ward"), ValueError, "5 is no such number"),
    (lambda: ns.linkage(np.zeros((2, 2, 2)), "ward"), ValueError, "got shape (2, 2, 2)"),
    (lambda: ns.linkage(np.zeros((5, 2)), "medoid"), ValueError, "medoid"),
    (lambda: ns.GaussianMixture(2, covariance_type="ellipsoid").fit(np.zeros((3, 2))), ValueError,
     "covariance_type: 'ellipsoid' is not 'full', 'tied', 'diag' or 'spherical'"),
    (lambda: ns.GaussianMixture(2).score(np.zeros((3, 2))), ValueError, "not fitted"),
    (lambda: ns.GaussianMixture(5).fit(np.zeros((3, 2))), ValueError, ""),
])
def test_bad_input(call, exc, words):
    with pytest.raises(exc) as e:
        call()
    assert words in str(e.value) and "\n" not in str(e.value), str(e.value)


@pytest.mark.parametrize("x", [[], np.empty(0), np.empty((0, 3))])
def test_mean_sd_of_nothing_raises(x):
    """An empty sample has no mean (statistics.mean raises; numpy warns and
    gives NaN): the library refuses it, as the stat tool an empty column."""
    for rounding in ("running", "summed"):
        with pytest.raises(ValueError) as e:
            ns.mean_sd(x, rounding)
        assert str(e.value) == "x: no values"


# `stat gmm` refuses these (--tol, --reg-covar, --max-iter, --seed); the
# library's nl_gmm_options_check refuses the first three for both.
@pytest.mark.parametrize("kw,exc,words", [
    (dict(tol=np.inf), ValueError, "tol: inf is not a finite number"),
    (dict(tol=-1.0), ValueError, "tol: -1 is outside [0, 1e+300]"),
    (dict(reg_covar=np.inf), ValueError, "reg_covar: inf is not a finite number"),
    (dict(max_iter=2**40), ValueError, "max_iter: 1099511627776 is outside [1, 100000000]"),
    (dict(max_iter=-1), ValueError, "max_iter: -1 is outside"),
    (dict(random_state=-1), ValueError, "random_state: -1 is outside [0, 4294967295]"),
    (dict(random_state=2**32), ValueError, "random_state: 4294967296 is outside"),
    (dict(n_threads=0), ValueError, "n_threads: 0 is outside"),
    (dict(n_components=2.5), TypeError, "n_components: expected an integer"),
])
def test_gmm_refuses_what_stat_gmm_refuses(kw, exc, words):
    X = np.random.default_rng(1).random((20, 2))
    kw.setdefault("n_components", 2)
    with pytest.raises(exc) as e:
        ns.GaussianMixture(**kw).fit(X)
    assert str(e.value).startswith(words), str(e.value)


# ---- scipy's habits: unpacking, alternative= and method=, a vectorised CDF,
# chisquare per axis, linkage on condensed distances and metric=.

def test_results_unpack_as_scipy_does():
    x = np.random.default_rng(5).normal(0, 1, 200)
    for r, s in ((ns.kstest(x, "norm"), st.kstest(x, "norm")),
                 (ns.ks_2samp(x[:120], x[120:]), st.ks_2samp(x[:120], x[120:])),
                 (ns.chisquare([16, 18, 16, 14, 12, 12]), st.chisquare([16, 18, 16, 14, 12, 12]))):
        stat, p = r
        assert (stat, p) == (r.statistic, r.pvalue) == (r[0], r[1]) and len(r) == 2
        assert tuple(r) == (r.statistic, r.pvalue)
        assert rel(stat, s[0], 1e-12) and rel(p, s[1], 1e-10)
    v, p = ns.kuiper(x, "norm")
    assert v == ns.kuiper(x, "norm").d_plus + ns.kuiper(x, "norm").d_minus


# Tolerances: D, D+, D- bit for bit or 1e-15 absolute; the exact laws' p
# 1e-10 relative (the C tests' bound); the asymptotic laws 1e-12 relative.
KS_TOL = {"auto": 1e-10, "exact": 1e-10, "asymp": 1e-12, "approx": 1e-10}


@pytest.mark.parametrize("alternative", ["two-sided", "less", "greater"])
@pytest.mark.parametrize("method", ["auto", "exact", "asymp", "approx"])
def test_kstest_alternative_and_method_are_scipy(alternative, method):
    """Many random samples (sizes 1..3000, shifted and scaled away from the
    null so that small p-values are in), by name and by callable."""
    rng = np.random.default_rng(zlib.crc32(f"{alternative} {method}".encode()))
    for trial in range(40):
        n = int(rng.choice([1, 2, 5, 17, 100, 640, 3000]))
        x = rng.normal(rng.uniform(-0.3, 0.3), rng.uniform(0.8, 1.25), n)
        b = st.kstest(x, "norm", alternative=alternative, method=method)
        for cdf in ("norm", st.norm.cdf):
            a = ns.kstest(x, cdf, alternative=alternative, method=method)
            assert abs(a.statistic - b.statistic) <= 1e-15, (n, a, b)
            tol = KS_TOL[method] if alternative == "two-sided" else 1e-10   # exact Smirnov
            assert rel(a.pvalue, b.pvalue, tol), (n, a.pvalue, b.pvalue, a.method)
            assert a.statistic_sign == b.statistic_sign
            D, p = a
            assert (D, p) == (a.statistic, a.pvalue)


@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize("alternative", ["two-sided", "less", "greater"])
@pytest.mark.parametrize("method", ["auto", "exact", "asymp"])
def test_ks_2samp_alternative_and_method_are_scipy(alternative, method, seed):
    rng = np.random.default_rng(zlib.crc32(f"{alternative} {method} 2".encode()) + seed)
    sizes = [1, 3, 8, 20, 64, 100, 333, 1000]
    for trial in range(30):
        n1, n2 = (int(v) for v in rng.choice(sizes, 2))
        x, y = rng.normal(0, 1, n1), rng.normal(rng.uniform(-0.5, 0.5), 1, n2)
        if trial % 5 == 0:   # ties across the samples
            x, y = np.round(x, 1), np.round(y, 1)
        a = ns.ks_2samp(x, y, alternative=alternative, method=method)
        b = st.ks_2samp(x, y, alternative=alternative, method=method)
        assert abs(a.statistic - b.statistic) <= 1e-15, (n1, n2, a, b)
        if n1 == n2 == 1 and method == "asymp" and alternative == "two-sided":
            # scipy's effective size rounds 1/2 to 0 and kstwo.sf(d, 0) is
            # NaN; the library takes n = 1, P(D_1 >= d)
            assert np.isnan(b.pvalue) and 0 <= a.pvalue <= 1
            continue
        assert rel(a.pvalue, b.pvalue, 1e-10), (n1, n2, a.pvalue, b.pvalue, a.method)
        assert a.statistic_sign == b.statistic_sign


def test_ks_2samp_exact_beyond_auto_sizes_is_scipy():
    """method='exact' past auto's 10000 (scipy tries the lattice count, and
    where a count overflows warns and takes the asymptotic law of the
    lattice value: both here)."""
    import warnings
    rng = np.random.default_rng(7)
    x, y = rng.normal(0, 1, 10050), rng.normal(0.02, 1, 201)
    for alt, law in (("two-sided", "exact"), ("greater", "asymp"), ("less", "asymp")):
        with warnings.catch_warnings(record=True) as w:
            warnings.simplefilter("always")
            a = ns.ks_2samp(x, y, alternative=alt, method="exact")
            b = st.ks_2samp(x, y, alternative=alt, method="exact")
        assert a.method == law and ns.ks_2samp(x, y, alternative=alt).method == "asymp"
        assert len(w) == (0 if law == "exact" else 2), [str(m.message) for m in w]
        assert a.statistic == b.statistic and rel(a.pvalue, b.pvalue, 1e-12), (a, b)


def test_callable_cdf_is_called_once_with_the_sorted_sample():
    x = np.random.default_rng(3).normal(0, 1, 20000)
    calls = []

    def F(v, loc, scale):
        calls.append(np.array(v, copy=True))
        return st.norm.cdf(v, loc, scale)
    for test in (ns.kstest, ns.kuiper):
        calls.clear()
        r = test(x, F, args=(0.0, 1.0))
        assert len(calls) == 1 and np.array_equal(calls[0], np.sort(x))
    assert abs(ns.kstest(x, F, args=(0.0, 1.0)).statistic - st.kstest(x, "norm").statistic) \
        <= 1e-15
    with pytest.raises(ValueError, match="must return an array of its shape"):
        ns.kstest(x, lambda v: 0.5)


def test_chisquare_per_axis_is_scipy():
    rng = np.random.default_rng(11)
    obs = rng.integers(5, 50, (6, 4, 3)).astype(float)
    for axis in (0, 1, -1, None):
        a, b = ns.chisquare(obs, axis=axis), st.chisquare(obs, axis=axis)
        assert np.shape(a.statistic) == np.shape(b.statistic)
        assert np.allclose(a.statistic, b.statistic, rtol=1e-12, atol=0)
        assert np.allclose(a.pvalue, b.pvalue, rtol=1e-10, atol=0)
    exp = rng.uniform(0.5, 1.5, obs.shape)
    exp *= obs.sum(axis=0, keepdims=True) / exp.sum(axis=0, keepdims=True)
    a, b = ns.chisquare(obs, exp), st.chisquare(obs, exp)
    assert np.allclose(a.statistic, b.statistic, rtol=1e-12, atol=0)
    assert np.allclose(a.pvalue, b.pvalue, rtol=1e-10, atol=0)
    assert a.df.shape == (4, 3) and np.all(a.df == 5)
    # a 1-D f_exp broadcasts against every column, as in scipy
    col = np.full(6, obs[:, 0, 0].sum() / 6)
    a, b = ns.chisquare(obs[:, :1, 0], col[:, None]), st.chisquare(obs[:, :1, 0], col[:, None])
    assert np.allclose(a.statistic, b.statistic, rtol=1e-12, atol=0)


def test_chisquare_refuses_mismatched_sums_as_scipy():
    obs, exp = np.array([10.0, 20.0, 30.0]), np.array([10.0, 20.0, 30.0 + 3e-6])
    with pytest.raises(ValueError) as e:
        ns.chisquare(obs, exp)
    with pytest.raises(ValueError, match="relative tolerance of 1e-08"):
        st.chisquare(obs, exp)
    msg = str(e.value)
    assert msg.startswith("f_exp: for each axis slice, the sum of the observed frequencies "
                          "must agree with the sum of the expected frequencies to a relative "
                          "tolerance of 1e-08") and "\n" not in msg, msg
    ok = np.array([10.0, 20.0, 30.0 + 5e-7])   # inside scipy's rtol: both accept
    assert rel(ns.chisquare(obs, ok).statistic, st.chisquare(obs, ok).statistic, 1e-12)


METHODS = ["single", "complete", "average", "weighted", "ward", "centroid", "median"]
METRICS = ["euclidean", "sqeuclidean", "cityblock", "chebyshev", "cosine", "correlation",
           "canberra", "braycurtis"]


def same_linkage(a, b, atol=0.0):
    """Same merges and sizes; heights 1e-12 relative (the C tests' bound),
    or atol absolute."""
    return (np.array_equal(a[:, [0, 1, 3]], b[:, [0, 1, 3]]) and
            np.allclose(a[:, 2], b[:, 2], rtol=1e-12, atol=atol))


@pytest.mark.parametrize("method", METHODS)
def test_linkage_on_condensed_distances_is_scipy(method):
    from scipy.spatial.distance import pdist
    rng = np.random.default_rng(METHODS.index(method))
    for n in (2, 3, 17, 150):
        x = rng.normal(0, 1, (n, 3))
        y = pdist(x)
        assert same_linkage(ns.linkage(y, method), sch.linkage(y, method)), (n, method)
        assert same_linkage(ns.linkage(y, method), ns.linkage(x, method))
        # distances of no geometry (scipy reads them as given)
        y2 = rng.uniform(0.1, 5.0, n * (n - 1) // 2)
        assert same_linkage(ns.linkage(y2, method), sch.linkage(y2, method)), (n, method)


@pytest.mark.parametrize("metric", METRICS)
@pytest.mark.parametrize("method", ["single", "complete", "average", "weighted"])
def test_linkage_metric_is_scipy(metric, method):
    rng = np.random.default_rng(7 * METRICS.index(metric) + len(method))
    x = rng.uniform(0.1, 2.0, (60, 4))
    # cosine and correlation are 1 - u.v / (|u| |v|): near 0 their rounding
    # is that of 1.0, 2^-52 absolute, which is 1.4e-12 of a height of 1.6e-4
    # here (the library and pdist order the products differently)
    atol = 2 * np.finfo(float).eps if metric in ("cosine", "correlation") else 0.0
    assert same_linkage(ns.linkage(x, method, metric=metric),
                        sch.linkage(x, method, metric=metric), atol), (method, metric)


@pytest.mark.parametrize("call,words", [
    (lambda: ns.linkage(np.ones(4), "single"), "y: a condensed distance matrix"),
    (lambda: ns.linkage(np.array([1.0, -1.0, 2.0]), "single"), "distance 2 is -1"),
    (lambda: ns.linkage(np.array([1.0, np.nan, 2.0]), "average"), "distance 2 is nan"),
    (lambda: ns.linkage(np.ones((4, 2)), "ward", metric="cityblock"), "Euclidean"),
    (lambda: ns.linkage(np.ones((4, 2)), "single", metric="hamming"), "hamming"),
    (lambda: ns.kstest([0.1, 0.2], "norm", alternative="both"), "unknown alternative 'both'"),
    (lambda: ns.kstest([0.1, 0.2], "norm", method="fast"), "method: 'fast' is not one of"),
    (lambda: ns.ks_2samp([0.1, 0.2], [0.3], method="approx"), "method: 'approx'"),
    (lambda: ns.chisquare(np.ones((3, 2)), axis=2), "axis: 2 is out of bounds"),
])
def test_new_arguments_refuse_in_one_line(call, words):
    with pytest.raises(ValueError) as e:
        call()
    assert words in str(e.value) and "\n" not in str(e.value), str(e.value)


def test_submodules_load_lazily_and_every_module_has_all():
    import subprocess
    import sys
    code = ("import sys, noiselab; assert 'noiselab.stats' not in sys.modules; "
            "r = noiselab.stats.ks_2samp([1.0, 2.0], [3.0]); "
            "assert 'noiselab.stats' in sys.modules; print(sorted(dir(noiselab)))")
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "python"))
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env,
                       cwd="/")
    assert r.returncode == 0, r.stderr
    assert "'stats'" in r.stdout and "'noise'" in r.stdout
    import importlib
    import noiselab
    with pytest.raises(AttributeError, match="no attribute 'nosuch'"):
        noiselab.nosuch
    pkg = os.path.join(ROOT, "python", "noiselab")
    mods = sorted(f[:-3] for f in os.listdir(pkg) if f.endswith(".py"))
    assert "noise" in mods and "_lib" in mods
    for name in mods:
        m = importlib.import_module(f"noiselab.{name}" if name != "__init__" else "noiselab")
        assert isinstance(m.__all__, list), name
        for a in m.__all__:
            assert hasattr(m, a), (name, a)
        public = [k for k, v in vars(m).items() if not k.startswith("_") and
                  getattr(v, "__module__", None) == m.__name__ and callable(v)]
        assert set(public) <= set(m.__all__), (name, set(public) - set(m.__all__))
