#!/usr/bin/python3
"""Reference vectors for nl_stats_welch_p and nl_stats_ftest_p (src/stats).

Writes tests/data/stats/meantest.tsv: for each case the summaries (m1, s1,
n1, m2, s2, n2), Welch's p from scipy.stats.ttest_ind_from_stats(
equal_var=False) and the two-sided F-test p = min(1, 2 min(f.cdf, f.sf)) of
F = s2^2 / s1^2 on (n2 - 1, n1 - 1) degrees of freedom. Made with Debian's
python3-scipy (1.10.1):

    /usr/bin/python3 tests/reference/make_meantest_vectors.py
"""
import os

import numpy as np
import scipy.stats as st

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "stats", "meantest.tsv")

CASES = [  # m1, s1, n1, m2, s2, n2: equal, shifted, far apart, unequal n and spread
    (0.5, 0.02, 10, 0.5, 0.02, 10),
    (0.51, 0.02, 10, 0.50, 0.03, 10),
    (0.0, 1.0, 3, 1.0, 1.0, 3),
    (0.0, 1.0, 2, 0.1, 2.5, 7),
    (10.0, 0.1, 10, 10.5, 0.1, 10),
    (-3.25, 0.75, 24, -3.0, 0.2, 5),
    (1e-6, 3e-7, 10, 1.2e-6, 2e-7, 10),
    (100.0, 5.0, 3, 100.0, 0.05, 3),
    (0.2, 0.01, 1000, 0.2004, 0.012, 900),
    (0.0, 0.5, 10, 0.0, 0.0, 10),
]


def main():
    with open(OUT, "w") as f:
        f.write("m1\ts1\tn1\tm2\ts2\tn2\twelch_p\tftest_p\n")
        for m1, s1, n1, m2, s2, n2 in CASES:
            welch = st.ttest_ind_from_stats(m1, s1, n1, m2, s2, n2, equal_var=False).pvalue
            if s1 == 0 or s2 == 0:
                ftest = 0.0
            else:
                F = s2 * s2 / (s1 * s1)
                ftest = min(1.0, 2 * min(st.f.cdf(F, n2 - 1, n1 - 1), st.f.sf(F, n2 - 1, n1 - 1)))
            row = [m1, s1, n1, m2, s2, n2, float(welch), float(ftest)]
            f.write("\t".join(str(v) if isinstance(v, int) else repr(float(v)) for v in row) + "\n")


if __name__ == "__main__":
    np.seterr(all="ignore")
    main()
