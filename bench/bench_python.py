"""The Python package's cost over the C calls it makes, in one process.

    NOISELAB_BUILD=build /usr/bin/python3 bench/bench_python.py [REPEATS]

Each case is timed through noiselab (the public function, its checks
included) and as the bare C call it makes (through ctypes, arguments
prepared once), alternately, REPEATS times (default 21), in CPU seconds
of the calling thread (the C calls run in it; another process's load on a
shared machine does not count); the minimum of each is printed with their
ratio, as a TSV:

  case  n  python_s  c_s  ratio

  fbm_grid_1024     nn.grid("fbm", 1024, out=...) against nl_noise_fractal_grid
  improved_points   nn.points(x, y, z, out=...) of 10^6 random points against
                    nl_noise_perm3_points
  improved_point    one nn.points(x, y, z) scalar call against one bare
                    nl_noise_perm3_eval call (per call, over 10^5 calls)

A measurement made by hand on a quiet machine (never a timed test): the
issue's targets are a grid within 5% of the C call and 10^6 points within 10%.
"""
import ctypes
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import noiselab.noise as nn  # noqa: E402
from noiselab import noise as _impl  # noqa: E402


def best(f, repeats):
    ts = []
    for _ in range(repeats):
        t = time.thread_time()
        f()
        ts.append(time.thread_time() - t)
    return min(ts)


def pair(py, c, repeats):
    """Alternate the two so that both see the same machine."""
    tp, tc = [], []
    for _ in range(repeats):
        tp.append(best(py, 1))
        tc.append(best(c, 1))
    return min(tp), min(tc)


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 21
    print("case\tn\tpython_s\tc_s\tratio")

    size = 1024
    out = np.empty((size, size))
    nz = _impl._make("fbm", 1, "improved", 6, 0.5, 2.0, None, 512, False, "F1", 4.0, 50,
                     "inverse", 64)
    win = _impl._Window(0.0, 0.0, 0.5, 4.0, size, size)
    args = (ctypes.byref(nz.basis), ctypes.byref(nz.octaves), ctypes.byref(win), _impl._ptr(out))
    tp, tc = pair(lambda: nn.grid("fbm", size, out=out),
                  lambda: _impl._fractal_grid(*args), repeats)
    print(f"fbm_grid_1024\t{size * size}\t{tp:.6g}\t{tc:.6g}\t{tp / tc:.4f}")

    n = 10**6
    rng = np.random.default_rng(1)
    x, y, z = (rng.uniform(-100, 100, n) for _ in range(3))
    res = np.empty(n)
    imp = _impl._make("improved", 1, "improved", 6, 0.5, 2.0, None, 512, False, "F1", 4.0, 50,
                      "inverse", 64)
    p = ctypes.addressof(imp._b.contents.perm3)
    px, py_, pz, po = (_impl._ptr(a) for a in (x, y, z, res))
    tp, tc = pair(lambda: nn.points(x, y, z, out=res),
                  lambda: _impl._perm3_points(p, px, py_, pz, n, po), repeats)
    print(f"improved_points\t{n}\t{tp:.6g}\t{tc:.6g}\t{tp / tc:.4f}")

    calls = 10**5
    xs = x[:calls].tolist()

    def py_points():
        for v in xs:
            nn.points(v, 1.5, 0.5)

    def c_points():
        for v in xs:
            _impl._perm3_eval(p, v, 1.5, 0.5)
    tp, tc = pair(py_points, c_points, max(3, repeats // 7))
    print(f"improved_point\t1\t{tp / calls:.6g}\t{tc / calls:.6g}\t{tp / tc:.4f}")


if __name__ == "__main__":
    main()
