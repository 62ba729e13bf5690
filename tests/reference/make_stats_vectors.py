#!/usr/bin/python3
"""Reference vectors for src/stats (KS, Kuiper, chi-square, linkage, GMM).

Writes TSV files to tests/data/stats/. The unit tests read only those files,
so CI needs no Python. Regenerate with Debian's packages:

    apt-get install -y python3-scipy python3-sklearn python3-numpy python3-astropy
    /usr/bin/python3 tests/reference/make_stats_vectors.py

Made with scipy 1.10.1, scikit-learn 1.2.1, numpy 1.24.2, astropy 5.2.1
(Debian 12). Every sample comes from numpy.random.default_rng with a fixed
seed, so the script is deterministic.
"""
import os
import sys

import numpy as np
import scipy
import scipy.cluster.hierarchy as sch
import scipy.stats as st
import sklearn
from sklearn.cluster import KMeans
from sklearn.mixture import GaussianMixture

try:
    from astropy.stats import kuiper_false_positive_probability as kuiper_fpp
except ImportError:  # astropy is only needed for the Kuiper vectors
    kuiper_fpp = None

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "stats")
TWO_PI = 2 * np.pi


def fmt(v):
    if isinstance(v, (str, np.str_)):
        return str(v)
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    return repr(float(v))


def write(name, cols, rows):
    with open(os.path.join(OUT, name), "w") as f:
        f.write("\t".join(cols) + "\n")
        for r in rows:
            f.write("\t".join(fmt(v) for v in r) + "\n")


def write_matrix(name, X, prefix="x"):
    X = np.atleast_2d(X)
    write(name, [f"{prefix}{j}" for j in range(X.shape[1])], X.tolist())


# ---- Kolmogorov-Smirnov -------------------------------------------------------

def ks_samples():
    """Samples on [0, 2pi): uniform (p spread over (0,1)), and distorted
    (u^1.3, u^0.7) for p near 0; n = 10, 100, 512, 5000."""
    cases = []
    for n in (10, 100, 512, 5000):
        for kind, seed in (("unif", 0), ("unif", 1), ("pow1.3", 2), ("pow0.9", 3)):
            rng = np.random.default_rng(seed + 10 * n)
            u = rng.random(n)
            if kind == "pow1.3":
                u = u ** 1.3
            elif kind == "pow0.9":
                u = u ** 0.9
            cases.append((f"ks_{kind}_{n}_s{seed}", TWO_PI * u))
    # As many angles as a 2D gradient table of Cheng's (cheng2009: 512 gradient
    # vectors): default_rng(0), 512 uniforms on [0, 2pi)
    cases.append(("ks_facts_512", np.random.default_rng(0).uniform(0, TWO_PI, 512)))
    # p near 1: a stratified (jittered-grid) sample is far more even than chance
    rng = np.random.default_rng(7)
    for n in (10, 100, 512, 5000):
        cases.append((f"ks_strat_{n}", TWO_PI * (np.arange(n) + 0.5 + 0.3 * (rng.random(n) - 0.5)) / n))
    return cases


def make_ks():
    rows, krows = [], []
    for name, x in ks_samples():
        write_matrix(name + ".tsv", x[:, None])
        cdf = st.uniform(0, TWO_PI).cdf
        r = st.kstest(x, cdf)
        u = np.sort(cdf(x))
        n = len(x)
        dplus = (np.arange(1.0, n + 1) / n - u).max()
        dminus = (u - np.arange(0.0, n) / n).max()
        rows.append((name + ".tsv", n, r.statistic, dplus, dminus, r.pvalue,
                     st.kstwobign.sf(r.statistic * np.sqrt(n))))
        if kuiper_fpp is not None:
            v = dplus + dminus
            if v >= 3.0 / n or n <= 100:
                krows.append((name + ".tsv", n, v, kuiper_fpp(v, n)))
    write("ks_one.tsv", ["file", "n", "d", "d_plus", "d_minus", "p", "p_kolmogorov"], rows)
    if krows:
        write("kuiper_one.tsv", ["file", "n", "v", "p"], krows)

    # kstwo.sf / kstwo.cdf on a grid that visits every method of Simard &
    # L'Ecuyer (Ruben-Gambino, Durbin-MTW, Pomeranz, Pelz-Good, Smirnov)
    grid = []
    for n in (1, 2, 3, 5, 10, 37, 100, 140, 141, 200, 512, 1000, 5000, 20000, 100001):
        ds = set()
        for lam in (0.05, 0.2, 0.3, 0.5, 0.7, 0.85, 1.0, 1.2, 1.5, 1.8, 2.0, 2.5, 3.0, 4.0, 6.0, 10.0):
            ds.add(lam / np.sqrt(n))
        for t in (0.4, 0.6, 0.9, 1.0, 1.5):
            ds.add(t / n)
        for d in (0.3, 0.5, 0.55, 0.8, 0.95, 1 - 0.5 / n, 1.0):
            ds.add(d)
        for d in sorted(ds):
            if 0 < d <= 1:
                grid.append((n, d, st.kstwo.sf(d, n), st.kstwo.cdf(d, n),
                             scipy.special.smirnov(n, d)))
    write("kstwo_grid.tsv", ["n", "d", "sf", "cdf", "smirnov"], grid)
    lam = np.linspace(0.05, 3.5, 70)
    write("kolmogorov.tsv", ["lambda", "sf"], [(l, st.kstwobign.sf(l)) for l in lam])


def make_ks2():
    rows = []
    specs = [(10, 10, 0.0), (10, 15, 0.3), (100, 100, 0.0), (100, 137, 0.25),
             (512, 512, 0.0), (512, 700, 0.1), (3000, 2000, 0.03), (12000, 800, 0.05)]
    for i, (n1, n2, shift) in enumerate(specs):
        rng = np.random.default_rng(100 + i)
        x = rng.normal(size=n1)
        y = rng.normal(loc=shift, size=n2)
        if i == 2:   # ties across samples
            x = np.round(x, 1)
            y = np.round(y, 1)
        f1, f2 = f"ks2_{i}_a.tsv", f"ks2_{i}_b.tsv"
        write_matrix(f1, x[:, None])
        write_matrix(f2, y[:, None])
        r = st.ks_2samp(x, y)
        rows.append((f1, f2, n1, n2, r.statistic, r.pvalue))
    write("ks2.tsv", ["file1", "file2", "n1", "n2", "d", "p"], rows)


# ---- Kuiper ---------------------------------------------------------------------

def make_kuiper():
    if kuiper_fpp is None:
        print("astropy missing: Kuiper vectors not regenerated", file=sys.stderr)
        return
    rows = []
    for n in (2, 3, 10, 11, 50, 100, 512, 5000):
        for v in (1.5 / n, 2.5 / n, 0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.8, 0.95):
            # astropy's small-V branches use factorial(n), finite to n = 170
            # (and its comb(n, t) overflows for large n near V = 1: skip NaN)
            if 1.0 / n < v < 1.0 and (v >= 3.0 / n or n <= 100):
                with np.errstate(all="ignore"):
                    p = kuiper_fpp(v, n)
                if np.isfinite(p):
                    rows.append((n, v, p))
    write("kuiper_grid.tsv", ["n", "v", "p"], rows)
    # Accuracy of the formula: Monte Carlo tail probabilities at n = 512
    # from 40000 uniform samples; the test checks agreement within 4 sigma.
    rng = np.random.default_rng(11)
    n, reps = 512, 40000
    vs = np.empty(reps)
    for r0 in range(0, reps, 2000):
        u = np.sort(rng.random((2000, n)), axis=1)
        i = np.arange(1, n + 1)
        vs[r0:r0 + 2000] = (i / n - u).max(axis=1) + (u - (i - 1) / n).max(axis=1)
    mc = []
    for v in (0.045, 0.055, 0.065, 0.075, 0.085, 0.095, 0.11):
        p = (vs >= v).mean()
        mc.append((n, v, p, np.sqrt(p * (1 - p) / reps), kuiper_fpp(v, n)))
    write("kuiper_mc.tsv", ["n", "v", "p_mc", "se_mc", "p_formula"], mc)


# ---- chi-square ------------------------------------------------------------------

def make_chisq():
    rows = []
    for i, (n, k) in enumerate(((512, 500), (512, 16), (1000, 10), (100, 2), (5000, 64))):
        rng = np.random.default_rng(200 + i)
        x = rng.uniform(0, TWO_PI, n) if i != 2 else TWO_PI * rng.random(n) ** 1.2
        f = f"chisq_{i}.tsv"
        write_matrix(f, x[:, None])
        obs, _ = np.histogram(x, bins=k, range=(0, TWO_PI))
        r = st.chisquare(obs)
        rows.append((f, n, k, r.statistic, k - 1, r.pvalue, n / k))
    write("chisq.tsv", ["file", "n", "k", "chi2", "df", "p", "min_expected"], rows)


# ---- hierarchical clustering -----------------------------------------------------

def make_linkage():
    rng = np.random.default_rng(300)
    centers = rng.normal(scale=6.0, size=(5, 6))
    X = np.vstack([c + rng.normal(size=(40, 6)) for c in centers])
    X = X[rng.permutation(len(X))]
    write_matrix("hclust_X.tsv", X)
    for method in ("single", "complete", "average"):
        Z = sch.linkage(X, method=method)
        write(f"hclust_{method}_Z.tsv", ["a", "b", "dist", "size"], Z.tolist())
        cols, labels = [], []
        for t in (np.median(Z[:, 2]), Z[-5, 2] + 1e-9, 0.5 * (Z[-3, 2] + Z[-4, 2])):
            cols.append(f"cut_{t:.17g}")
            labels.append(sch.fcluster(Z, t, criterion="distance"))
        for k in (1, 3, 5, 12):
            cols.append(f"maxclust_{k}")
            labels.append(sch.fcluster(Z, k, criterion="maxclust"))
        write(f"hclust_{method}_labels.tsv", cols, np.array(labels).T.tolist())



def make_linkage_metrics():
    """Every pdist metric with single, complete, average and weighted linkage
    on 14 points in 3-D with negative coordinates (standard normal), to be
    compared with the same points times 1e-200 too (the scale-free metrics:
    cosine, correlation, canberra, braycurtis; the others scale with them)."""
    rng = np.random.default_rng(45)
    X = rng.standard_normal((14, 3))
    write_matrix("hclust_metrics_X.tsv", X)
    rows = []
    for metric in ("euclidean", "sqeuclidean", "cityblock", "chebyshev", "cosine",
                   "correlation", "canberra", "braycurtis"):
        for method in ("single", "complete", "average", "weighted"):
            Z = sch.linkage(X, method, metric)
            rows += [[method, metric, int(r[0]), int(r[1]), r[2], int(r[3])] for r in Z]
    write("hclust_metrics_Z.tsv", ["method", "metric", "a", "b", "dist", "size"], rows)

# ---- Gaussian mixtures -------------------------------------------------------------

class GMMFromLabels(GaussianMixture):
    """GaussianMixture initialised from given labels through sklearn's own
    _initialize (one-hot responsibilities), the path init='kmeans' takes."""

    def __init__(self, labels=None, **kw):
        super().__init__(**kw)
        self.labels = labels

    def _initialize_parameters(self, X, random_state):
        resp = np.zeros((X.shape[0], self.n_components))
        resp[np.arange(X.shape[0]), self.labels] = 1
        self._initialize(X, resp)


def make_gmm():
    rng = np.random.default_rng(400)
    d, k = 4, 3
    parts = []
    for j in range(k):
        A = rng.normal(size=(d, d))
        parts.append(rng.normal(scale=4.0, size=d) + rng.normal(size=(200 + 50 * j, d)) @ A)
    X = np.vstack(parts)
    X = X[rng.permutation(len(X))]
    X[:, 3] = X[:, 3] * 0.5 + 0.1 * X[:, 0]
    write_matrix("gmm_X.tsv", X)
    rows = []
    for kk in (1, 2, 3, 4):
        labels = KMeans(kk, n_init=1, random_state=kk).fit(X).labels_
        write(f"gmm_labels_k{kk}.tsv", ["label"], [[int(l)] for l in labels])
        for cov in ("full", "diag", "tied", "spherical"):
            g = GMMFromLabels(labels=labels, n_components=kk, covariance_type=cov,
                              tol=1e-3, reg_covar=1e-6, max_iter=100)
            g.fit(X)
            s = g.score(X)
            rows.append((kk, cov, s * len(X), g.n_iter_, int(g.converged_), g.aic(X), g.bic(X)))
            if kk == 3:
                P = [[w, *m] for w, m in zip(g.weights_, g.means_)]
                write(f"gmm_params_k3_{cov}.tsv", ["weight"] + [f"mean{j}" for j in range(d)], P)
                # predict(X): each row's component (0-based, sklearn's order)
                write(f"gmm_predict_k3_{cov}.tsv", ["label"], [[int(l)] for l in g.predict(X)])
    write("gmm_fit.tsv", ["k", "covariance", "loglik", "iterations", "converged", "aic", "bic"], rows)


def main():
    os.makedirs(OUT, exist_ok=True)
    print(f"scipy {scipy.__version__}, scikit-learn {sklearn.__version__}, numpy {np.__version__}")
    make_ks()
    make_ks2()
    make_kuiper()
    make_chisq()
    make_linkage()
    make_linkage_metrics()
    make_gmm()


if __name__ == "__main__":
    main()
