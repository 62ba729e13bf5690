#!/usr/bin/python3
"""Reference values of sin(pi x) and cos(pi x) for nl_math_sinpi and
nl_math_cospi (src/math/nl_math.h).

Writes tests/data/math/sinpi.tsv: for each x (exact, as a C99 hexadecimal
double) sin(pi x) and cos(pi x) computed by mpmath with 300-bit arithmetic,
each as a double-double (hi = the value rounded to double, lo = the rest
rounded to double), so that a test can measure a result's error in ulps to
about 2^-53 ulp. The inputs are the hard ones: zeros, integers,
half-integers and quarters, a few ulps either side of every multiple of
1/2 up to 8, tiny and subnormal x, x near 2^51, 2^52 and 2^53 (where the
reduction's rounding tricks change regime) and huge x; then 1000 random x
(fixed seed) of every sign and magnitude from 2^-40 to 2^60. Made with
Debian's python3-mpmath (1.3.0):

    /usr/bin/python3 tests/reference/make_sinpi_vectors.py
"""
import math
import os
import random

import mpmath as mp

mp.mp.prec = 300
OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "math", "sinpi.tsv")


def inputs():
    xs = [0.0, 5e-324, 2.0 ** -1074 * 3, 2.0 ** -1022, 1e-300, 2.0 ** -30, 1e-8, 0.1, 1 / 3]
    for n in range(1, 17):   # multiples of 1/4 up to 4, and a few ulps off each half
        xs.append(n / 4)
    for n in range(1, 17):
        h = n / 2
        lo = hi = h
        for _ in range(3):
            lo = math.nextafter(lo, 0)
            hi = math.nextafter(hi, math.inf)
            xs += [lo, hi]
    for e in (50, 51, 52, 53, 54, 60, 100, 1000):
        b = 2.0 ** e
        xs += [b, math.nextafter(b, 0), math.nextafter(b, math.inf), b - 0.5, b + 1, b + 2, b - 1,
               b - 1.5, b + 3]
    xs += [1.5 * 2.0 ** 52 + 1, 2.0 ** 52 + 0.5, 2.0 ** 51 + 0.25, 2.0 ** 51 + 0.75, 1e300,
           1.7976931348623157e308]
    rng = random.Random(20261127)
    for _ in range(1000):
        xs.append(rng.uniform(0.5, 1.0) * 2.0 ** rng.randint(-40, 60))
    return sorted(set(xs + [-x for x in xs if x != 0]))


def dd(v):
    hi = float(v)
    return hi, float(v - mp.mpf(hi))


def main():
    rows = []
    for x in inputs():
        t = mp.mpf(x)
        s = dd(mp.sinpi(t))
        c = dd(mp.cospi(t))
        rows.append("\t".join(v.hex() for v in (x,) + s + c))
    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    tmp = OUT + ".tmp"
    with open(tmp, "w") as f:
        f.write("x\tsin_hi\tsin_lo\tcos_hi\tcos_lo\n")
        f.write("\n".join(rows) + "\n")
    os.replace(tmp, OUT)


main()
