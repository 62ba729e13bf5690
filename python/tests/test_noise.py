"""noiselab.noise against the render tool (same seed, same bits) and itself."""
import ctypes
import os
import subprocess

import numpy as np
import pytest

from conftest import BUILD
import noiselab.noise as nn

RENDER = os.path.join(BUILD, "tools", "noiselab-render")


def render(tmp_path, args, size):
    out = tmp_path / "v.tsv"
    subprocess.run([RENDER, *args, "--size", str(size), "-o", str(out)], check=True,
                   capture_output=True)
    t = np.genfromtxt(out, names=True, delimiter="\t")
    return t["value"].reshape(size, size), t["x"].reshape(size, size), t["y"].reshape(size, size)


CASES = [
    ("improved", ["--seed", "7"], dict(seed=7)),
    ("improved", ["--reference", "--z", "1.25"], dict(reference=True, z=1.25)),
    ("noise2", ["--seed", "3", "--table-size", "64"], dict(seed=3, table_size=64)),
    ("fractal", ["--octaves", "5", "--seed", "2"], dict(octaves=5, seed=2)),
    ("turbulence", ["--octaves", "4", "--basis", "table"], dict(octaves=4, basis="table")),
    ("fbm", ["--octaves", "6", "--gain", "0.7", "--lacunarity", "2", "--seed", "9"],
     dict(octaves=6, gain=0.7, lacunarity=2.0, seed=9)),
    ("fbm", ["--octaves", "3", "--lacunarity", "1.9", "--basis", "wavelet", "--tile", "32"],
     dict(octaves=3, lacunarity=1.9, basis="wavelet", tile=32)),
    ("gctbf", ["--terms", "F2 - F1", "--seed", "5"], dict(terms="F2 - F1", seed=5)),
    # lambda 4 has a tie p(3) = p(4), where closest-last takes the larger count
    ("gctbf", ["--count", "closest-last", "--seed", "3"], dict(count="closest-last", seed=3)),
    ("wavelet", ["--tile", "16", "--extent", "40", "--seed", "4"],
     dict(tile=16, extent=40.0, seed=4)),
    ("marble", ["--octaves", "4", "--amplitude", "0.8", "--stripes", "2"],
     dict(octaves=4, amplitude=0.8, stripes=2.0)),
]


@pytest.mark.parametrize("noise,args,kw", CASES)
def test_grid_is_render(tmp_path, noise, args, kw):
    """The same seed and options give render's values bit for bit (its .tsv
    prints each double so that it reads back exactly)."""
    size = 24
    ref, _, _ = render(tmp_path, [noise, *args], size)
    v = nn.grid(noise, size, **kw)
    assert v.shape == (size, size) and v.dtype == np.float64
    assert np.array_equal(v, ref), np.max(np.abs(v - ref))


POINT_CASES = [c for c in CASES if c[0] != "marble"]


@pytest.mark.parametrize("noise,args,kw", POINT_CASES)
def test_points_are_grid(noise, args, kw):
    """points() at the grid's pixel centres gives the grid's bits (every case
    here has power-of-two octave frequencies but one: lacunarity 1.9, whose
    row kernel scales x0 and dx apart, which the test allows to 1e-12)."""
    size = 16
    kw = dict(kw)
    extent, z = kw.pop("extent", 4.0), kw.pop("z", 0.5)
    v = nn.grid(noise, size, extent=extent, z=z, **kw)
    d = extent / size
    x = (0.0 + 0.5 * d) + np.arange(size) * d
    y = 0.0 + (np.arange(size)[:, None] + 0.5) * d
    basis = kw.get("basis", noise)
    zz = None if basis in ("noise2", "table") else z
    p = nn.points(x[None, :], y, zz, noise, **kw)
    assert p.shape == (size, size)
    if kw.get("lacunarity", 2.0) == 2.0:
        assert np.array_equal(p, v), np.max(np.abs(p - v))
    else:
        assert np.allclose(p, v, rtol=0, atol=1e-12)


def test_given_table_is_seeded_table():
    """A table given as arrays is the noise of those arrays: a seeded table's
    own angles and permutation, read back from the library, give its values."""
    import ctypes
    nz = nn._Noise("noise2", 11, "improved", 1, 0.5, 2.0, None, 32, False, "F1", 4.0, 50,
                   "inverse", 64)
    g = ctypes.cast(nz.grad2(), ctypes.POINTER(nn._Grad2)).contents
    angles = np.array([g.angle[k] for k in range(32)])
    perm = np.array([g.perm[k] for k in range(32)])
    nz.close()
    a = nn.grid("noise2", 20, seed=11, table_size=32)
    b = nn.grid("noise2", 20, table=(angles, perm))
    assert np.array_equal(a, b)
    x = np.linspace(-3, 3, 50)
    assert np.array_equal(nn.points(x, 0.3, None, "noise2", table=(angles, perm)),
                          nn.points(x, 0.3, None, "noise2", seed=11, table_size=32))


def test_out():
    buf = np.full((32, 32), np.nan)
    assert nn.grid("fbm", 32, seed=4, out=buf) is buf
    assert np.array_equal(buf, nn.grid("fbm", 32, seed=4))
    x = np.linspace(-2, 2, 9)
    pb = np.empty(9)
    assert nn.points(x, 0.5, 0.25, out=pb) is pb and np.array_equal(pb, nn.points(x, 0.5, 0.25))


def test_broadcast_and_dtypes():
    x = np.linspace(0, 3, 7, dtype=np.float32)
    y = np.arange(3, dtype=np.int64)[:, None]
    p = nn.points(x, y, 0.25)
    assert p.shape == (3, 7) and p.dtype == np.float64
    q = nn.points(x.astype(np.float64)[None, :].repeat(3, 0), y.astype(float).repeat(7, 1),
                  np.full((3, 7), 0.25))
    assert np.array_equal(p, q)
    assert nn.points(1.5, 2.5, 3.5).shape == ()


@pytest.mark.parametrize("call,exc,words", [
    (lambda: nn.points(np.array([1j]), 0.0), TypeError, "x: coordinates must be real"),
    (lambda: nn.points(np.array(["a"]), 0.0), TypeError, "x: coordinates must be real"),
    # float16 and bool: other dtypes than integer and float32 raise, as documented
    (lambda: nn.points(np.array([1.5], np.float16), 0.0), TypeError, "dtype float16"),
    (lambda: nn.points(0.0, np.array([True])), TypeError, "y: coordinates must be real"),
    (lambda: nn.points(0.0, 0.5, np.array([0.5], np.longdouble)), TypeError, "z: coordinates"),
    (lambda: nn.points(True, 0.5), TypeError, "dtype bool"),
    (lambda: nn.cellular(np.array([1.5], np.float16), 0.0), TypeError, "dtype float16"),
    (lambda: nn.cellular(0.5, np.array([False]), 0.5), TypeError, "dtype bool"),
    (lambda: nn.points(np.zeros(3), np.zeros(4)), ValueError, "do not broadcast"),
    (lambda: nn.points(0.0, np.array([0.0, np.nan])), ValueError, "y: coordinate 1"),
    (lambda: nn.points(np.inf, 0.0), ValueError, "not a finite number"),
    (lambda: nn.points(0.0, 0.0, 1.0, "noise2"), ValueError, "2D noise"),
    (lambda: nn.points(0.0, 0.0, noise="marble"), ValueError, "use grid"),
    (lambda: nn.grid("fbm", -1), ValueError, "size: -1 is outside"),
    (lambda: nn.grid("fbm", 4, lacunarity=1e3, octaves=8), ValueError, "beyond 2^52"),
    (lambda: nn.points(1e16, 0.0, 0.0), ValueError, "beyond 2^52"),
    (lambda: nn.grid("fbm", 4, out=np.empty((4, 4), np.float32)), ValueError, "out: expected"),
    (lambda: nn.points(np.zeros(3), 0.0, out=np.empty(4)), ValueError, "out: expected"),
    (lambda: nn.grid("fbm", 8, octaves=0), ValueError, "octaves: 0"),
    (lambda: nn.grid("perlin", 8), ValueError, "unknown noise 'perlin'"),
    (lambda: nn.grid("fbm", 8, basis="x"), ValueError, "unknown noise basis"),
    (lambda: nn.grid("gctbf", 8, terms="F9"), ValueError, "F9"),
    (lambda: nn.grid("wavelet", 8, tile=7), ValueError, "tile: 7 is outside [8, 256]"),
    (lambda: nn.grid("wavelet", 8, tile=9), ValueError, "tile: the wavelet tile period"),
    (lambda: nn.grid("noise2", 8, table=([0.0, 1.0], [0, 0])), ValueError, "not a permutation"),
])
def test_bad_input(call, exc, words):
    """Bad input raises with a one-line message naming it (the library's own
    message where the library checks)."""
    with pytest.raises(exc) as e:
        call()
    msg = str(e.value)
    assert words in msg and "\n" not in msg, msg


def test_cellular_distances():
    """F1..F4: sorted, F1 and F2 - F1 as the gctbf noise gives them, rows = points."""
    F = nn.cellular_grid(20, 4, seed=6)
    assert F.shape == (20, 20, 4) and np.all(np.diff(F, axis=-1) >= 0)
    assert np.array_equal(F[..., 0], nn.grid("gctbf", 20, seed=6, terms="F1"))
    assert np.allclose(F[..., 1] - F[..., 0], nn.grid("gctbf", 20, seed=6, terms="F2 - F1"),
                       rtol=0, atol=1e-15)
    d = 4.0 / 20
    x = (0.5 * d) + np.arange(20) * d
    y = (np.arange(20)[:, None] + 0.5) * d
    assert np.array_equal(nn.cellular(x[None, :], y, 0.5, 4, seed=6), F)
    with pytest.raises(ValueError, match="n: 5 is outside 1..4"):
        nn.cellular(0.0, 0.0, 0.0, n=5)


@pytest.mark.parametrize("call", ["grid", "points"])
def test_long_calls_release_the_gil(call):
    """While a long grid or batch of points runs in C on one thread, Python
    runs on another (the extension releases the GIL around each block): the
    main thread's loop keeps stamping times through the call's span. With
    the GIL held the main thread would run only in the switch interval
    before the call (a few % of the span)."""
    import threading
    import time
    span = []
    r = np.random.default_rng(3)
    pts = r.uniform(-50, 50, (3, 300000))

    def work():
        t0 = time.perf_counter()
        if call == "grid":
            nn.grid("fbm", 1536, octaves=12)
        else:
            nn.points(*pts, "fbm", octaves=12)
        span.extend([t0, time.perf_counter()])

    t = threading.Thread(target=work)
    stamps = []
    t.start()
    while t.is_alive():
        stamps.append(time.perf_counter())
    t.join()
    inside = [s for s in stamps if span[0] < s < span[1]]
    covered = (inside[-1] - inside[0]) / (span[1] - span[0]) if inside else 0.0
    assert covered > 0.5, (covered, span[1] - span[0])


@pytest.mark.parametrize("noise,kw", [("fbm", dict(octaves=5)), ("marble", dict(stripes=2.5)),
                                      ("turbulence", dict(basis="wavelet", tile=16)),
                                      ("gctbf", {}), ("noise2", {}),
                                      ("fbm", dict(lacunarity=1.7, gain=0.6))])
def test_grid_is_the_library_grid(noise, kw):
    """grid's rows, run a block at a time by the extension, are
    nl_noise_fractal_grid's (nl_texture_marble_grid's) bits, on a window
    that is not square in its pixel count's factors either."""
    size, x0, y0, z = 37, -3.25, 1.5, 0.75
    v = nn.grid(noise, size, x0=x0, y0=y0, z=z, extent=5.0, **kw)
    nz = nn._make(noise, 1, kw.get("basis", "improved"), kw.get("octaves", 6), kw.get("gain", 0.5),
                  kw.get("lacunarity", 2.0), None, 512, False, "F1", 4.0, 50, "inverse",
                  kw.get("tile", 64))
    win = nn._Window(x0, y0, z, 5.0, size, size)
    ref = np.empty((size, size))
    if noise == "marble":
        nn._marble_grid(ctypes.byref(nz.basis), ctypes.byref(nz.octaves), ctypes.byref(win),
                        2 * np.pi * kw["stripes"], 0.5, nn._ptr(ref))
    else:
        nn._fractal_grid(ctypes.byref(nz.basis), ctypes.byref(nz.octaves), ctypes.byref(win),
                         nn._ptr(ref))
    assert np.array_equal(v, ref)


def test_scalar_point_is_the_batch():
    """Scalars take the point call (no arrays): the batch kernel's bits."""
    r = np.random.default_rng(3)
    x, y, z = r.uniform(-50, 50, (3, 200))
    for noise, kw in (("improved", dict(seed=4)), ("noise2", dict(seed=4, table_size=64))):
        zz = None if noise == "noise2" else z
        batch = nn.points(x, y, zz, noise, **kw)
        one = [nn.points(float(a), float(b), None if zz is None else float(c), noise, **kw)
               for a, b, c in zip(x, y, z)]
        assert np.array_equal(batch, np.array(one)), noise
    assert isinstance(nn.points(1.0, 2.0, 3.0), np.float64)
    with pytest.raises(ValueError, match="y: coordinate 0"):
        nn.points(1.0, float("nan"), 0.0)


def test_lattice_bound_is_exact_when_the_quick_one_is_loose():
    """10^4 points near 1e14: the one-pass bound sqrt(sum x^2) ~ 1e16 passes
    2^52, the exact largest |x| does not: the points are accepted."""
    x = np.full(10_000, 1e14) + np.arange(10_000) * 0.25
    v = nn.points(x, 0.3, 0.7)
    assert np.array_equal(v[:5], [nn.points(float(a), 0.3, 0.7) for a in x[:5]])
    with pytest.raises(ValueError, match="beyond 2"):
        nn.points(np.append(x, 5e15), 0.3, 0.7)


def _pt_fns():
    """The library's point calls, the reference of the batches."""
    from noiselab._lib import fn, c_double_p
    ev3 = fn("nl_wavelet_eval3", ctypes.c_double, ctypes.c_void_p, ctypes.c_double,
             ctypes.c_double, ctypes.c_double)
    cev = fn("nl_cellular_eval", None, ctypes.c_void_p, c_double_p, ctypes.c_int, c_double_p)
    val = fn("nl_cellular_gctbf_value", ctypes.c_double, ctypes.POINTER(nn._Gctbf), c_double_p)
    return ev3, cev, val


_REAL_EXT = nn.ext


class _CountedExt:
    """noiselab._ext with its batch call counted: calls gets the kernel's
    kind (_ext.c: one call per array, run there a block at a time)."""

    def __init__(self, calls):
        self.calls = calls

    def points(self, f, *a):
        self.calls.append(f._kind)
        return _REAL_EXT.points(f, *a)

    def __getattr__(self, name):
        return getattr(_REAL_EXT, name)


def test_batches_are_the_point_calls(monkeypatch):
    """Wavelet, gctbf and F1..F4 at scattered points (negative and far ones
    among them) are one C call per array and give the point calls' bits."""
    ev3, cev, val = _pt_fns()
    r = np.random.default_rng(11)
    x = np.concatenate([r.uniform(-300, 300, 400), r.uniform(-1e9, 0, 50)])
    y = r.uniform(-50, 10, x.size)
    z = r.uniform(-1e4, 1e4, x.size)
    calls = []
    f = nn._cellular_points
    monkeypatch.setattr(nn, "_cellular_points", lambda *a: (calls.append("cellular"), f(*a))[1])
    monkeypatch.setattr(nn, "ext", _CountedExt(calls))

    w = nn.points(x, y, z, "wavelet", seed=4, tile=16)
    nz = nn._Noise("wavelet", 4, "improved", 1, 0.5, 2.0, None, 512, False, "F1", 4.0, 50,
                   "inverse", 16)
    ref = [ev3(nz._b.contents.tile, a, b, c) for a, b, c in zip(x, y, z)]
    nz.close()
    assert np.array_equal(w, ref)

    g = nn.points(x, y, z, "gctbf", seed=6, terms="F2 - F1 + 0.5 F1F3")
    F = nn.cellular(x, y, z, 4, seed=6)
    nz = nn._Noise("gctbf", 6, "improved", 1, 0.5, 2.0, None, 512, False, "F2 - F1 + 0.5 F1F3",
                   4.0, 50, "inverse", 64)
    b = nz._b.contents
    p, q, ref, refF = np.empty(3), np.empty(4), [], []
    for a, bb, c in zip(x, y, z):
        p[:] = a, bb, c
        cev(b.gctbf_cell, nn._ptr(p), b.gctbf.n, nn._ptr(q))
        ref.append(val(ctypes.byref(b.gctbf), nn._ptr(q)))
        cev(b.gctbf_cell, nn._ptr(p), 4, nn._ptr(q))
        refF.append(q.copy())
    nz.close()
    assert np.array_equal(g, ref)
    assert np.array_equal(F, np.array(refF))
    assert calls == [nn._K_WAVELET, nn._K_GCTBF, "cellular"]


def test_sums_over_any_basis_are_one_call(monkeypatch):
    """A sum over a basis without a batch kernel of its own (turbulence, the
    table, wavelet) is one nl_noise_fractal_points call with the grid's bits."""
    calls = []
    monkeypatch.setattr(nn, "ext", _CountedExt(calls))
    for noise, kw in (("turbulence", dict(octaves=4)), ("fbm", dict(basis="wavelet", tile=16)),
                      ("fractal", dict(basis="table", table_size=64))):
        size = 16
        v = nn.grid(noise, size, x0=-3.0, y0=-2.0, **kw)
        d = 4.0 / size
        xs = (-3.0 + 0.5 * d) + np.arange(size) * d
        ys = -2.0 + (np.arange(size)[:, None] + 0.5) * d
        zz = None if kw.get("basis") == "table" else 0.5
        assert np.array_equal(nn.points(xs[None, :], ys, zz, noise, **kw), v), noise
    assert calls == [nn._K_SUM] * 3


@pytest.mark.parametrize("noise,kw", [("improved", {}), ("fbm", dict(octaves=5)),
                                      ("noise2", {}), ("wavelet", dict(tile=16)),
                                      ("gctbf", {})])
def test_refusal_keeps_the_points_before(noise, kw):
    """A refused point (checked by the library beside the kernel): a
    one-line ValueError naming it, out= holding the values of the points
    before it (the contract of the docstring)."""
    r = np.random.default_rng(2)
    n = 3000
    x, y = r.uniform(-100, 100, n), r.uniform(-100, 100, n)
    z = None if noise == "noise2" else r.uniform(-100, 100, n)
    ref = nn.points(x, y, z, noise, **kw)
    for k, bad in ((1700, np.nan), (5, -np.inf), (2999, 2.0 ** 53)):
        yb = y.copy()
        yb[k] = bad
        out = np.full(n, -7.0)
        with pytest.raises(ValueError) as e:
            nn.points(x, yb, z, noise, out=out, **kw)
        msg = str(e.value)
        assert "\n" not in msg
        assert (f"y: coordinate {k} (flat index)" in msg) if np.isnan(bad) or np.isinf(bad) \
            else "beyond 2^52" in msg, msg
        assert np.array_equal(out[:k], ref[:k])


@pytest.mark.parametrize("kw,words", [
    (dict(noise="wavelet", tile=9), "tile: the wavelet tile period must be even and in 8..256"),
    (dict(noise="wavelet", tile=4), "tile: 4 is outside [8, 256]"),
    (dict(noise="noise2", table_size=2), "table_size: 2 is outside [4, 1048576]"),
    (dict(noise="gctbf", terms="F9"), "terms: "),
    (dict(noise="gctbf", lambda_=0.0), "lambda_: 0 must be in (0, 1000]"),
    (dict(noise="gctbf", points=0), "points: 0 is outside [1, 64]"),
    # render range-checks an option also where the noise ignores it
    (dict(noise="improved", tile=7), "tile: 7 is outside [8, 256]"),
    (dict(noise="fbm", points=65), "points: 65 is outside [1, 64]"),
    (dict(noise="improved", lambda_=-1.0), "lambda_: -1 must be in (0, 1000]"),
    (dict(noise="wavelet", table_size=2**21), "table_size: 2097152 is outside [4, 1048576]"),
    (dict(noise="fbm", basis="wavelet", tile=300), "tile: "),
])
def test_library_messages_name_the_python_parameter(kw, words):
    """The library names its inputs as render's options (--tile) or its C
    fields; from Python the message names the parameter the user typed.
    (tile=4 used to reach the library unchecked and crash the interpreter.)"""
    for call in (lambda: nn.grid(size=8, **kw), lambda: nn.points(0.5, 0.5, **kw),
                 lambda: nn.bound(**kw)):
        with pytest.raises(ValueError) as e:
            call()
        msg = str(e.value)
        assert msg.startswith(words) and "--" not in msg and "\n" not in msg, msg


# Each value render refuses, with render's option and Python's parameter:
# refused by the same library check (nl_basis_sum_check, nl_basis_window_check,
# nl_basis_make), in the same words but the name.
RANGE_CASES = [
    ("fbm", "gain", float("nan"), "nan is not a finite number"),
    ("fbm", "gain", 1e4, "10000 is outside [-1000, 1000]"),
    ("fbm", "lacunarity", 0, "0 is outside [1e-06, 1e+06]"),
    ("fbm", "lacunarity", -2, "-2 is outside [1e-06, 1e+06]"),
    ("fbm", "octaves", 31, "31 is outside [1, 30]"),
    ("improved", "extent", 1e10, "1e+10 is outside [1e-09, 1e+09]"),
    ("improved", "extent", 0, "0 is outside [1e-09, 1e+09]"),
    ("improved", "x0", 1e10, "1e+10 is outside [-1e+09, 1e+09]"),
    ("improved", "y0", float("-inf"), "-inf is not a finite number"),
    ("improved", "z", 1e10, "1e+10 is outside [-1e+09, 1e+09]"),
    ("marble", "stripes", 0, "0 is outside [1e-09, 1e+09]"),
    ("marble", "stripes", -1, "-1 is outside [1e-09, 1e+09]"),
    ("marble", "amplitude", 1e7, "1e+07 is outside [-1e+06, 1e+06]"),
    ("noise2", "table_size", 2**21, "2097152 is outside [4, 1048576]"),
    ("improved", "size", 65537, "65537 is outside [1, 65536]"),
]


@pytest.mark.parametrize("noise,name,value,words", RANGE_CASES)
def test_grid_refuses_what_render_refuses(noise, name, value, words):
    kw = {"size": 4, name: value}
    with pytest.raises(ValueError) as e:
        nn.grid(noise, **kw)
    assert str(e.value) == f"{name}: {words}"


@pytest.mark.parametrize("noise,name,value,words", RANGE_CASES)
def test_render_refuses_the_same(tmp_path, noise, name, value, words):
    args = [noise, f"--{name.replace('_', '-')}", str(value), "-o", str(tmp_path / "x.png")]
    if name != "size":
        args += ["--size", "4"]
    r = subprocess.run([RENDER, *args], capture_output=True, text=True)
    assert r.returncode == 2 and r.stderr.count("\n") == 1, r.stderr
    opt = f"--{name.replace('_', '-')}"
    # a non-finite value is refused already as a word, quoted (nl_parse_double)
    want = (f"{opt}: '{value}' is not a finite number" if "finite" in words else
            f"{opt}: {words}")
    assert r.stderr == f"noiselab render: {want}\n", r.stderr


@pytest.mark.parametrize("call", [
    lambda: nn.grid("improved", 4, seed=2**32),
    lambda: nn.points(0.5, 0.5, seed=2**40),
    lambda: nn.bound("fbm", lacunarity=0),
    lambda: nn.points(np.zeros(3), 0.5, noise="fbm", gain=np.inf),
    lambda: nn.cellular_grid(4, extent=-1),
    lambda: nn.cellular_grid(4, x0=np.nan),
])
def test_points_bound_and_cellular_refuse_them_too(call):
    with pytest.raises(ValueError):
        call()


ALIAS_CASES = [
    ("improved", {}), ("noise2", {}), ("gctbf", dict(terms="F2 - F1")), ("wavelet", dict(tile=16)),
    *[(s, dict(basis=b, octaves=4)) for s in ("fractal", "turbulence", "fbm")
      for b in ("improved", "table", "gctbf", "wavelet")],
]


@pytest.mark.parametrize("noise,kw", ALIAS_CASES)
@pytest.mark.parametrize("alias", ["x", "y", "z"])
def test_out_aliasing_a_coordinate_is_the_plain_call(noise, kw, alias):
    """out= that is x, y or z itself (or a view of it) gives the plain call's
    bits, as numpy's ufuncs buffer such overlaps: the sums accumulate octave
    by octave into out and would otherwise read back what they wrote."""
    rng = np.random.default_rng(48)
    planar = noise == "noise2" or kw.get("basis") == "table"
    if planar and alias == "z":
        pytest.skip("2D noise: no z")
    x, y, z = rng.uniform(-10, 10, (3, 2000))
    args = [x, y] if planar else [x, y, z]
    plain = nn.points(*[a.copy() for a in args], noise=noise, **kw)
    given = dict(x=x, y=y, z=z)[alias]
    got = nn.points(*args, noise=noise, out=given, **kw)
    assert got is given
    assert np.array_equal(got, plain), np.max(np.abs(got - plain))
    # a broadcast coordinate that out overlaps through a view of its buffer
    buf = rng.uniform(-10, 10, 2000)
    plain = nn.points(buf.copy(), *[a.copy() for a in args[1:]], noise=noise, **kw)
    got = nn.points(buf[:, None][:, 0], *args[1:], noise=noise, out=buf, **kw)
    assert np.array_equal(got, plain)


def test_out_aliasing_keeps_the_points_before_a_refusal():
    x = np.linspace(-3, 3, 1000)
    x[700] = np.nan
    plain = np.full(1000, 7.0)
    with pytest.raises(ValueError, match="x: coordinate 700"):
        nn.points(x.copy(), 0.5, 0.5, "fbm", out=plain)
    with pytest.raises(ValueError, match="x: coordinate 700"):
        nn.points(x, 0.5, 0.5, "fbm", out=x)
    assert np.array_equal(x[:700], plain[:700])


@pytest.mark.parametrize("name,good,bad", [
    ("seed", 1, 1.0), ("seed", 2, np.float64(2.0)), ("octaves", 4, 4.0), ("table_size", 64, 64.0),
    ("points", 20, 20.0), ("tile", 16, 16.0), ("seed", 1, True), ("octaves", 1, True),
])
@pytest.mark.parametrize("order", ["bad first", "good first"])
def test_what_is_accepted_does_not_depend_on_earlier_calls(name, good, bad, order):
    """A value is accepted or refused for what it is: the built-noise cache
    keys equal-comparing 1 and 1.0 (or True) apart, so a call with seed=1
    never lets seed=1.0 through later."""
    noise = {"table_size": "noise2", "points": "gctbf", "tile": "wavelet"}.get(name, "fbm")
    x = np.linspace(0, 1, 4)
    calls = [False, True] if order == "bad first" else [True, False]
    for ok in calls:
        if ok:
            nn.points(x, x, None if noise == "noise2" else 0.5, noise, **{name: good})
        else:
            with pytest.raises(TypeError, match=f"^{name}: expected an integer"):
                nn.points(x, x, None if noise == "noise2" else 0.5, noise, **{name: bad})


@pytest.mark.parametrize("z", ["fbm", "0.5", b"1", object(), ["a"]])
def test_a_string_for_z_names_z(z):
    with pytest.raises(TypeError) as e:
        nn.points(np.zeros(3), np.zeros(3), z)
    assert str(e.value).startswith("z: coordinates must be real numbers or arrays of them, got "
                                   f"{type(z).__name__}"), str(e.value)


@pytest.mark.parametrize("value", [-1, 2**32])
@pytest.mark.parametrize("call", ["grid", "points", "cheng"])
def test_seed_is_refused_in_render_words(tmp_path, value, call):
    r = subprocess.run([RENDER, "improved", "--seed", str(value), "--size", "4", "-o",
                        str(tmp_path / "x.tsv")], capture_output=True, text=True)
    assert r.returncode == 2 and r.stderr.startswith("noiselab render: --seed: "), r.stderr
    want = r.stderr[len("noiselab render: --"):].strip()
    import noiselab.cheng as nc
    with pytest.raises(ValueError) as e:
        if call == "grid":
            nn.grid("improved", 4, seed=value)
        elif call == "points":
            nn.points(0.5, 0.5, seed=value)
        else:
            nc.optimise(np.zeros((16, 16)), seed=value)
    assert str(e.value) == want


@pytest.mark.parametrize("noise,name", [
    ("fbm", "gain"), ("fbm", "lacunarity"), ("gctbf", "lambda_"), ("marble", "amplitude"),
    ("marble", "stripes"), ("improved", "extent"), ("improved", "x0"), ("improved", "y0"),
    ("improved", "z")])
@pytest.mark.parametrize("value", [float("nan"), float("inf"), -float("inf")])
def test_a_non_finite_option_is_refused_in_render_words(tmp_path, noise, name, value):
    """render refuses a non-finite number as a word ('nan'); Python names the
    parameter and the value in the same sentence (the library's check)."""
    opt = "--" + name.rstrip("_").replace("_", "-")
    r = subprocess.run([RENDER, noise, opt, str(value), "--size", "4", "-o",
                        str(tmp_path / "x.tsv")], capture_output=True, text=True)
    assert r.returncode == 2
    assert r.stderr == f"noiselab render: {opt}: '{value}' is not a finite number\n", r.stderr
    with pytest.raises(ValueError) as e:
        nn.grid(noise, 4, **{name: value})
    assert str(e.value) == f"{name}: {value} is not a finite number"


@pytest.mark.parametrize("name,value", [("terms", 5), ("count", 1), ("noise", ["fbm"]),
                                        ("basis", None)])
@pytest.mark.parametrize("wrap", [lambda v: v, lambda v: np.array(v)[()] if np.ndim(v) == 0
                                  and v is not None else v])
def test_a_name_that_is_no_str_is_a_type_error(name, value, wrap):
    """Plain Python values and numpy scalars take different ways to the
    cache (_make) and are refused alike."""
    kw = {"noise": "gctbf", name: wrap(value)}
    with pytest.raises(TypeError, match=f"^{name}: expected a str"):
        nn.points(np.zeros(2), 0.5, 0.5, **kw)


def test_count_is_refused_in_render_words(tmp_path):
    r = subprocess.run([RENDER, "gctbf", "--count", "last", "--size", "4", "-o",
                        str(tmp_path / "x.tsv")], capture_output=True, text=True)
    assert r.returncode == 2
    with pytest.raises(ValueError) as e:
        nn.grid("gctbf", 4, count="last")
    assert r.stderr == f"noiselab render: --{e.value}\n"
    # the three rules give three rasters: closest-last is no alias
    g = [nn.grid("gctbf", 32, count=c, seed=3) for c in ("inverse", "closest", "closest-last")]
    assert not np.array_equal(g[1], g[2]) and not np.array_equal(g[0], g[2])


@pytest.mark.parametrize("noise,kw", [("improved", {}), ("improved", dict(reference=True)),
                                      ("fbm", dict(octaves=5, lacunarity=2.3)),
                                      ("fractal", {}), ("turbulence", dict(octaves=3)),
                                      ("noise2", {}), ("fbm", dict(basis="table")),
                                      ("wavelet", dict(tile=16)), ("gctbf", {}),
                                      ("fbm", dict(basis="wavelet", tile=16, octaves=2))])
def test_function_scalar_calls_are_the_array_calls(noise, kw):
    """nn.function's fast path (Python floats and ints, no array made) gives
    the bits of the batch over the same points, for every way the extension
    evaluates a noise; points() on scalars takes the same path."""
    r = np.random.default_rng(5)
    planar = noise == "noise2" or kw.get("basis") == "table"
    x = r.uniform(-60, 60, (2 if planar else 3, 300))
    x[:, :5] = np.round(x[:, :5])   # lattice points among them
    ref = nn.points(*x, noise=noise, **kw)
    f = nn.function(noise, **kw)
    got = [f(*p) for p in x.T.tolist()]
    assert all(type(v) is np.float64 for v in got)
    assert np.array_equal(got, ref)
    ints = [f(*map(int, p)) for p in x[:, :5].T]
    assert np.array_equal(ints, ref[:5])
    assert np.array_equal([nn.points(*p, noise=noise, **kw) for p in x.T.tolist()[:20]], ref[:20])
    if not planar:   # z defaults to render's plane 0.5, as points' does
        assert f(x[0, 7], x[1, 7]) == nn.points(x[0, 7], x[1, 7], 0.5, noise, **kw)


def test_function_declines_to_points_for_what_it_does_not_take():
    """What the fast path does not take goes to points(), with its errors."""
    f = nn.function("improved")
    with pytest.raises(ValueError, match=r"x: coordinate 0 \(flat index\) is nan"):
        f(float("nan"), 1.0, 2.0)
    with pytest.raises(ValueError, match="beyond 2\\^52"):
        f(2.0 ** 60, 1.0, 2.0)
    with pytest.raises(TypeError, match="z: coordinates must be real numbers"):
        f(1.0, 2.0, "fbm")
    with pytest.raises(TypeError, match="dtype bool"):
        f(True, 2.0, 3.0)
    with pytest.raises(ValueError, match="z: noise2 is a 2D noise"):
        nn.function("noise2")(1.0, 2.0, 3.0)
    with pytest.raises(ValueError, match="marble is a texture"):
        nn.function("marble")
    out = np.empty(3)
    assert f([0.5, 1.5, 2.5], 1.0, 2.0, out=out) is out
    assert np.array_equal(out, nn.points([0.5, 1.5, 2.5], 1.0, 2.0))


def test_float32_in_float32_out():
    """float32 coordinates give float32 values, as numpy's functions do:
    through the library's float32 kernels (improved, its fbm and fractal
    sums, noise2) within the 2e-6 nl_noise.h states of the double noise at
    the same coordinates, the other noises in double rounded to float32;
    out= must then be float32, may alias a coordinate, and NaN is refused
    by name as in float64."""
    rng = np.random.default_rng(5)
    x, y, z = rng.uniform(-300, 300, (3, 20000)).astype(np.float32)
    for noise, tol in [("improved", 2e-6), ("fbm", 4e-6), ("fractal", 4e-6), ("noise2", 2e-6),
                       ("turbulence", 1e-6), ("wavelet", 1e-6)]:
        zz = None if noise == "noise2" else z
        a = nn.points(x, y, zz, noise)
        b = nn.points(x.astype(np.float64), y.astype(np.float64),
                      None if zz is None else zz.astype(np.float64), noise)
        assert a.dtype == np.float32 and a.shape == x.shape, noise
        assert np.max(np.abs(a - b)) <= tol, (noise, np.max(np.abs(a - b)))
    # a Python float beside float32 arrays keeps float32; float64 beside them widens
    assert nn.points(x, y, 0.5).dtype == np.float32
    assert nn.points(x, y.astype(np.float64), z).dtype == np.float64
    assert isinstance(nn.points(np.float32(0.3), np.float32(0.7), 0.5), np.float32)
    o = x.copy()
    assert np.array_equal(nn.points(o, y, z, "fbm", out=o), nn.points(x, y, z, "fbm"))
    with pytest.raises(ValueError, match="out: expected a writeable C-contiguous float32"):
        nn.points(x, y, z, out=np.empty(x.shape))
    bad = x.copy()
    bad[7] = np.nan
    with pytest.raises(ValueError, match=r"x: coordinate 7 \(flat index\) is nan"):
        nn.points(bad, y, z)


def test_workers_give_the_same_bytes():
    """workers= (scipy's name) splits grids by rows and the improved and
    noise2 batches by blocks across threads: 1, 2 and 3 threads give the same
    bytes, on work above the threaded size (2^17 samples) and below it;
    anything but -1 or 1..1024 is refused naming the argument."""
    rng = np.random.default_rng(9)
    x, y, z = rng.uniform(-40, 40, (3, 300_001))
    for noise in ("improved", "fbm", "fractal", "noise2", "turbulence"):
        zz = None if noise == "noise2" else z
        ref = nn.points(x, y, zz, noise, workers=1)
        for w in (2, 3, -1):
            assert np.array_equal(nn.points(x, y, zz, noise, workers=w), ref), (noise, w)
    for noise, size in (("fbm", 700), ("marble", 300), ("noise2", 64)):
        ref = nn.grid(noise, size, workers=1)
        for w in (2, 3):
            assert np.array_equal(nn.grid(noise, size, workers=w), ref), (noise, w)
    for bad in (0, -2, 1025, 1.5, True):
        with pytest.raises(ValueError, match="workers: .* must be -1 .* or 1..1024"):
            nn.grid("fbm", 8, workers=bad)
