"""The Python package's cost over the C calls it makes, and its scalar call
against python3-noise's, in one process.

    NOISELAB_BUILD=build taskset -c 1 /usr/bin/python3 bench/bench_python.py [REPEATS]

(`scripts/noiselab bench` runs it as build/bench/bench_python.) Each case is
timed through noiselab (the public function, its checks included) and
through its peer, alternately, REPEATS times (default 21), in CPU seconds
of the calling thread (the C calls run in it; another process's load on a
shared machine does not count); the minimum of each is printed, as a TSV:

  case  unit  ours  peer  peer_value  ratio (ours / peer)

  fbm grid 1024^2       nn.grid("fbm", 1024, out=...) (the extension: blocks
                        of rows, the GIL released, signals checked between)
                        against one ctypes call of nl_noise_fractal_grid on
                        the same array
  improved, 10^6 points nn.points(x, y, z, out=...) (the extension: blocks of
                        64k points, likewise) against one ctypes call of
                        nl_noise_perm3_points_checked on the same arrays
                        (ctypes adds ~1 us to a call of ~4 ms)
  scalar call           f = nn.function("improved"); f(x, 1.5, 0.5) per
                        call, over 10^5 Python floats, against
                        python3-noise's noise.pnoise3(x, 1.5, 0.5) in the
                        same loop (skipped when python3-noise is missing)
  points() scalar       nn.points(x, 1.5, 0.5): the options looked up each
                        call
  ufunc floor           np.add(x, 1.5): what any numpy ufunc costs on Python
                        floats before its loop runs (why the scalar path is
                        a hand-written call, not a ufunc: docs/python.md)

A measurement, never a timed test; docs/python.md gives the targets
(scalar <= 1.5x pnoise3, 10^6 points <= 1.05x the C batch).
"""
import ctypes
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import noiselab.noise as nn  # noqa: E402
from noiselab import noise as _impl  # noqa: E402

try:
    import noise as pynoise   # Debian's python3-noise
except ImportError:
    pynoise = None


def pair(ours, peer, repeats):
    """Alternate the two so that both see the same machine, in the order
    ours, peer, peer, ours (neither always runs first, after the other)."""
    to, tp = [], []
    for k in range(repeats):
        order = ((ours, to), (peer, tp)) if k % 2 == 0 else ((peer, tp), (ours, to))
        for f, ts in order:
            t = time.thread_time()
            f()
            ts.append(time.thread_time() - t)
    return min(to), min(tp)


def line(case, unit, ours, peer, peer_value):
    ratio = f"{ours / peer_value:.4f}" if peer_value else "-"
    print(f"{case}\t{unit}\t{ours:.6g}\t{peer}\t{peer_value:.6g}\t{ratio}", flush=True)


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 21
    print(f"# load average {os.getloadavg()[0]:.2f}, CPUs allowed "
          f"{sorted(os.sched_getaffinity(0))}")
    print("# case\tunit\tours\tpeer\tpeer_value\tratio")

    size = 1024
    out = np.empty((size, size))
    nz = _impl._make("fbm", 1, "improved", 6, 0.5, 2.0, None, 512, False, "F1", 4.0, 50,
                     "inverse", 64)
    win = _impl._Window(0.0, 0.0, 0.5, 4.0, size, size)
    args = (ctypes.byref(nz.basis), ctypes.byref(nz.octaves), ctypes.byref(win), _impl._ptr(out))
    to, tp = pair(lambda: nn.grid("fbm", size, out=out),
                  lambda: _impl._fractal_grid(*args), repeats)
    line("fbm grid 1024^2", "CPU s", to, "C nl_noise_fractal_grid (ctypes)", tp)

    n = 10**6
    rng = np.random.default_rng(1)
    x, y, z = (rng.uniform(-100, 100, n) for _ in range(3))
    res = np.empty(n)
    imp = _impl._make("improved", 1, "improved", 6, 0.5, 2.0, None, 512, False, "F1", 4.0, 50,
                      "inverse", 64)
    p = ctypes.addressof(imp._b.contents.perm3)
    px, py_, pz, pr = (_impl._ptr(a) for a in (x, y, z, res))
    # both write into the same array (another one's pages and cache sets
    # would differ), which holds the same values after each
    _impl._perm3_checked(p, None, px, py_, pz, n, pr)
    ref = res.copy()
    to, tp = pair(lambda: nn.points(x, y, z, out=res),
                  lambda: _impl._perm3_checked(p, None, px, py_, pz, n, pr), repeats)
    nn.points(x, y, z, out=res)
    assert np.array_equal(res, ref)
    line("improved, 10^6 points", "CPU s", to, "C nl_noise_perm3_points_checked (ctypes)", tp)

    calls = 10**5
    xs = x[:calls].tolist()
    f = nn.function("improved")

    def loop(g):
        def run():
            for v in xs:
                g(v, 1.5, 0.5)
        return run
    reps = max(3, repeats // 3)
    if pynoise is not None:
        to, tp = pair(loop(f), loop(pynoise.pnoise3), reps)
        line("scalar call", "ns per call", to / calls * 1e9, "python3-noise pnoise3",
             tp / calls * 1e9)
    else:
        print("# scalar call: python3-noise is not installed (its pnoise3 is the peer)")
    to, tp = pair(loop(nn.points), loop(f), max(3, repeats // 7))
    line("points() scalar", "ns per call", to / calls * 1e9, "nn.function", tp / calls * 1e9)
    to, tp = pair(loop(lambda a, b, c: np.add(a, b)), loop(f), max(3, repeats // 7))
    line("ufunc floor (np.add on floats)", "ns per call", to / calls * 1e9, "nn.function",
         tp / calls * 1e9)


if __name__ == "__main__":
    main()
