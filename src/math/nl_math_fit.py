#!/usr/bin/python3
"""Fit the polynomial coefficients of nl_math.h's sinpi and cospi kernels.

On the reduced argument |r| <= 1/4, with u = r^2 in [0, 1/16]:
    sin(pi r) = r * P(u),  P of degree 6 (sin of degree 13)
    cos(pi r) = Q(u),      Q of degree 7 (cos of degree 14)
P and Q are Chebyshev interpolants (mpmath.chebyfit, within a small factor of
the minimax polynomial) of sin(pi sqrt(u)) / sqrt(u) and cos(pi sqrt(u)),
computed with 200-bit arithmetic and rounded to the nearest double. The
script prints each fit's largest relative error, then the coefficients as
the C lines of nl_math.h (exact hexadecimal, lowest degree first), which
nl_math.h holds verbatim. Made with
Debian's python3-mpmath (1.2.1; 1.3.0 gives the same output):

    /usr/bin/python3 src/math/nl_math_fit.py
"""
import mpmath as mp

mp.mp.prec = 200
QUARTER_SQUARED = mp.mpf(1) / 16


def sin_ratio(u):
    if u == 0:
        return mp.pi
    r = mp.sqrt(u)
    return mp.sin(mp.pi * r) / r


def cos_of_root(u):
    return mp.cos(mp.pi * mp.sqrt(u))


def fit(name, f, degree, low):
    coef, err = mp.chebyfit(f, [0, QUARTER_SQUARED], degree + 1, error=True)
    coef = list(reversed(coef))   # chebyfit lists the highest degree first
    print("/* %s: degree %d in u, largest relative error %s */"
          % (name, degree, mp.nstr(err / low, 3)))
    for k, c in enumerate(coef):
        print("#define NL_MATH__%s%d %s   /* %s */"
              % (name, k, float(c).hex(), mp.nstr(c, 17)))


fit("SINPI_P", sin_ratio, 6, sin_ratio(QUARTER_SQUARED))
fit("COSPI_Q", cos_of_root, 7, cos_of_root(QUARTER_SQUARED))
