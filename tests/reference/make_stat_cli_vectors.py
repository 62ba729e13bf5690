#!/usr/bin/python3
"""Reference vectors for `noiselab stat`: one-sample KS against
named distributions with scipy's shape/loc/scale convention (all 14 the
command names, with the one-sided alternatives) and against a tabulated
CDF, Kuiper's V against the same CDFs, two-sample KS with each
alternative, Ward linkage, and linkage with pdist's metrics and the
weighted, centroid and median methods.

Writes TSV/CSV files to tests/reference/stat_cli/; tests/cli_stat.sh reads
only those, so the tests need no Python. Regenerate with Debian's scipy:

    /usr/bin/python3 tests/reference/make_stat_cli_vectors.py

Made with scipy 1.10.1, numpy 1.24.2 (Debian 12). Samples come from
numpy.random.default_rng with fixed seeds, so the script is deterministic.
"""
import os

import numpy as np
import scipy
import scipy.cluster.hierarchy as sch
import scipy.stats as st

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "stat_cli")


def fmt(v):
    if isinstance(v, (str, np.str_)):
        return str(v)
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    return repr(float(v))


def write(name, cols, rows, sep="\t"):
    with open(os.path.join(OUT, name), "w") as f:
        f.write(sep.join(cols) + "\n")
        for r in rows:
            f.write(sep.join(fmt(v) for v in r) + "\n")


def kuiper_v(u):
    """Kuiper's V = D+ + D- of sorted CDF values u (scipy has no Kuiper test;
    the p-value is checked in src/stats against astropy, tests/data/stats)."""
    u = np.sort(u)
    n = len(u)
    i = np.arange(1, n + 1)
    return np.max(i / n - u) + np.max(u - (i - 1) / n)


def make_ks():
    rng = np.random.default_rng(20261123)
    # (sample file, how drawn, distribution tested, loc, scale)
    samples = {
        "norm_200.tsv": rng.normal(0.0, 1.0, 200),
        "norm_shift_300.tsv": rng.normal(0.25, 1.2, 300),
        "expon_150.tsv": 0.5 + rng.exponential(2.0, 150),
        "unif_80.tsv": rng.uniform(2.0, 5.0, 80),
        "beta_120.tsv": rng.beta(2.0, 1.0, 120),
        "u01_100.tsv": rng.uniform(0.0, 1.0, 100),
    }
    for name, x in samples.items():
        write(name, ["x"], [[v] for v in x])
    # the same normal sample as CSV, with a header, to check the CSV reader
    write("norm_200.csv", ["x", "twice"], [[v, 2 * v] for v in samples["norm_200.tsv"]], sep=",")
    # a tabulated CDF: F(x) = x^2 on [0, 1] (Beta(2, 1)) at 11 points
    xp = np.linspace(0.0, 1.0, 11)
    fp = xp ** 2
    write("cdf_beta21.tsv", ["x", "F"], [[a, b] for a, b in zip(xp, fp)])
    cases = [
        ("norm_200.tsv", "norm", 0.0, 1.0),
        ("norm_200.tsv", "norm", 0.1, 0.9),
        ("norm_shift_300.tsv", "norm", 0.0, 1.0),
        ("norm_shift_300.tsv", "norm", 0.25, 1.2),
        ("expon_150.tsv", "expon", 0.5, 2.0),
        ("expon_150.tsv", "expon", 0.0, 1.0),
        ("unif_80.tsv", "uniform", 2.0, 3.0),
        ("unif_80.tsv", "uniform", 1.9, 3.5),
        ("beta_120.tsv", "cdf_beta21.tsv", 0.0, 1.0),
        ("u01_100.tsv", "cdf_beta21.tsv", 0.0, 1.0),
    ]
    rows = []
    for fname, dist, loc, scale in cases:
        x = samples[fname]
        if dist.endswith(".tsv"):
            cdf = lambda t: np.interp(t, xp, fp)
            r = st.kstest(x, cdf)
            u = cdf(x)
        else:
            r = st.kstest(x, dist, args=(loc, scale))
            u = getattr(st, dist).cdf(x, loc, scale)
        rows.append([fname, dist, loc, scale, r.statistic, r.pvalue, kuiper_v(u)])
    write("ks_dist.tsv", ["file", "dist", "loc", "scale", "D", "p", "V"], rows)


# (distribution, shapes, loc, scale, n) drawn from; each is tested against
# itself and against a neighbour (the same shapes scaled by 1.15, loc + 0.1
# scale) so that both large and small p-values are checked.
SHAPED = [
    ("norm", (), 0.3, 1.5, 90),
    ("uniform", (), -1.0, 4.0, 70),
    ("expon", (), 0.2, 2.0, 120),
    ("gamma", (2.5,), 0.0, 1.3, 150),
    ("beta", (2.0, 5.0), 0.0, 1.0, 110),
    ("lognorm", (0.6,), 0.0, np.exp(0.4), 130),
    ("t", (4.0,), 0.5, 1.0, 100),
    ("chi2", (3.0,), 0.0, 1.0, 80),
    ("weibull_min", (1.7,), 0.0, 2.0, 140),
    ("cauchy", (), -0.5, 0.7, 60),
    ("logistic", (), 1.0, 0.8, 160),
    ("laplace", (), 0.0, 1.2, 50),
    ("pareto", (3.0,), 0.0, 1.0, 200),
    ("rayleigh", (), 0.1, 1.5, 75),
]


def make_ks_shapes():
    """kstest against every named distribution with scipy's (shapes, loc,
    scale), with the two one-sided alternatives beside the two-sided test."""
    rng = np.random.default_rng(20261127)
    rows = []
    for name, shapes, loc, scale, n in SHAPED:
        dist = getattr(st, name)
        x = dist.rvs(*shapes, loc=loc, scale=scale, size=n, random_state=rng)
        fname = f"dist_{name}_{n}.tsv"
        write(fname, ["value"], [[v] for v in x])
        near = tuple(a * 1.15 for a in shapes)
        for sh, lo, sc in [(shapes, loc, scale), (near, loc + 0.1 * scale, scale * 1.1)]:
            args = tuple(sh) + (lo, sc)
            r = {a: st.kstest(x, name, args=args, alternative=a)
                 for a in ("two-sided", "less", "greater")}
            v = kuiper_v(dist.cdf(x, *args))
            rows.append([fname, name, ",".join(repr(float(a)) for a in sh) or "-", lo, sc,
                         r["two-sided"].statistic, r["two-sided"].pvalue,
                         r["less"].statistic, r["less"].pvalue,
                         r["greater"].statistic, r["greater"].pvalue, v])
    write("ks_shapes.tsv", ["file", "dist", "shape", "loc", "scale", "D", "p", "D_less", "p_less",
                            "D_greater", "p_greater", "V"], rows)


def make_ks2_alternatives():
    """ks_2samp with each alternative: equal sizes (the product form), unequal
    sizes (Hodges' path count), sizes whose path counts overflow a double and
    sizes past 10000 (both asymptotic)."""
    rng = np.random.default_rng(20261128)
    sizes = [(40, 40, 0.3), (37, 52, 0.4), (120, 75, -0.2), (300, 500, 0.1),
             (700, 900, 0.05), (12000, 300, 0.15)]
    rows = []
    for n1, n2, shift in sizes:
        a = np.round(rng.normal(0.0, 1.0, n1), 3)   # rounded: ties across the samples
        b = np.round(rng.normal(shift, 1.0, n2), 3)
        fa, fb = f"ks2_{n1}_{n2}_a.tsv", f"ks2_{n1}_{n2}_b.tsv"
        write(fa, ["value"], [[v] for v in a])
        write(fb, ["value"], [[v] for v in b])
        for alt in ("two-sided", "less", "greater"):
            r = st.ks_2samp(a, b, alternative=alt)
            rows.append([fa, fb, alt, r.statistic, r.pvalue])
    write("ks2_alt.tsv", ["file1", "file2", "alternative", "D", "p"], rows)


def make_linkage_metrics():
    """linkage with pdist's metrics, weighted linkage, and centroid and median
    linkage (Euclidean), in long form: every row of every Z, and fcluster's
    maxclust 4 labels."""
    rng = np.random.default_rng(20261129)
    centres = np.array([[1.0, 1.0, 2.0, 0.5], [4.0, 1.5, 1.0, 3.0], [2.0, 5.0, 4.0, 1.0]])
    # positive coordinates (canberra and braycurtis), clusters of 14 points
    X = np.vstack([c + rng.gamma(2.0, 0.4, (14, 4)) for c in centres])
    write("metric_X.tsv", ["x0", "x1", "x2", "x3"], X.tolist())
    cases = [(m, d) for m in ("single", "complete", "average", "weighted")
             for d in ("sqeuclidean", "cityblock", "chebyshev", "cosine", "correlation",
                       "canberra", "braycurtis")]
    cases += [("weighted", "euclidean"), ("centroid", "euclidean"), ("median", "euclidean")]
    zrows, lrows = [], []
    for method, metric in cases:
        Z = sch.linkage(X, method, metric)
        for r in Z:
            zrows.append([method, metric, int(r[0]), int(r[1]), r[2], int(r[3])])
        for i, lab in enumerate(sch.fcluster(Z, 4, "maxclust")):
            lrows.append([method, metric, i, int(lab)])
    write("metric_Z.tsv", ["method", "metric", "a", "b", "dist", "size"], zrows)
    write("metric_labels.tsv", ["method", "metric", "row", "maxclust_4"], lrows)


def make_ward():
    rng = np.random.default_rng(7)
    centres = np.array([[0.0, 0.0, 0.0], [4.0, 0.5, 1.0], [1.0, 5.0, -1.0], [5.0, 5.0, 3.0]])
    X = np.vstack([c + rng.normal(0, 0.8, (15, 3)) for c in centres])
    write("ward_X.tsv", ["x0", "x1", "x2"], X.tolist())
    Z = sch.linkage(X, "ward")
    write("ward_Z.tsv", ["a", "b", "dist", "size"], Z.tolist())
    write("ward_labels.tsv", ["maxclust_4", "distance_6"],
          np.array([sch.fcluster(Z, 4, "maxclust"), sch.fcluster(Z, 6.0, "distance")]).T.tolist())


def main():
    os.makedirs(OUT, exist_ok=True)
    make_ks()
    make_ks_shapes()
    make_ks2_alternatives()
    make_linkage_metrics()
    make_ward()
    with open(os.path.join(OUT, "VERSIONS"), "w") as f:
        f.write(f"scipy {scipy.__version__}\nnumpy {np.__version__}\n")


if __name__ == "__main__":
    main()
