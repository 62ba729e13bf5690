"""noiselab.stats against scipy and scikit-learn, to the C tests' tolerances
(src/stats/test_gof.c, test_cluster.c, test_gmm.c): statistics D, D+, D-, V
1e-15 absolute; KS and two-sample p-values 1e-10 relative; chi-square 1e-12
(statistic) and 1e-10 (p) relative; Kuiper p 1e-9 relative against astropy's
committed values; linkage heights 1e-12 relative with the same merges;
GMM log-likelihood, AIC, BIC 1e-8 relative, same iteration count."""
import os

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


@pytest.mark.parametrize("cov", ["full", "diag"])
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
    (lambda: ns.chisquare([1, 2, 3], [1, 2]), ValueError, "f_exp: 2 expected"),
    (lambda: ns.linkage(np.zeros(5), "ward"), ValueError, "2-D"),
    (lambda: ns.linkage(np.zeros((5, 2)), "medoid"), ValueError, "medoid"),
    (lambda: ns.GaussianMixture(2, covariance_type="tied"), ValueError, "tied"),
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
