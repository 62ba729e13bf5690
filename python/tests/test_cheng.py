"""noiselab.cheng: Cheng's optimiser on a small setting (2 octaves, a 16 x 16
control grid, a short schedule: milliseconds)."""
import numpy as np
import pytest
import scipy.stats as st

import noiselab.cheng as nc
import noiselab.noise as nn
import noiselab.stats as ns

YY, XX = np.mgrid[0:64, 0:64] / 64.0
DISC = ((XX - 0.5) ** 2 + (YY - 0.5) ** 2 < 0.1).astype(float)
SMALL = dict(grid=16, octaves=2, n_temps=8, moves_per_var=5)


def test_optimise_measures_and_lowers_e_con():
    r = nc.optimise(DISC, seed=2, **SMALL)
    assert r.angles.shape == (512,) and np.array_equal(np.sort(r.perm), np.arange(512))
    # E_KS is the KS distance of the angles from uniform on [0, 2 pi): scipy's
    d = st.kstest(r.angles, "uniform", args=(0, 2 * np.pi)).statistic
    assert abs(r.e_ks - d) <= 1e-15
    assert abs(ns.kstest(r.angles, "uniform", args=(0, 2 * np.pi)).statistic - d) <= 1e-15
    assert r.e_con < r.eval["e_con_random"]     # it followed the pattern
    assert r.e == pytest.approx(0.995 * r.e_ks + 0.005 * r.e_con, rel=1e-15)
    e = nc.evaluate(r.table, DISC, grid=16, octaves=2)
    assert (e.e_ks, e.e_con, e.e) == (r.e_ks, r.e_con, r.e)


def test_same_seed_same_table():
    a, b = nc.optimise(DISC, seed=5, **SMALL), nc.optimise(DISC, seed=5, **SMALL)
    c = nc.optimise(DISC, seed=6, **SMALL)
    assert np.array_equal(a.angles, b.angles) and np.array_equal(a.perm, b.perm)
    assert not np.array_equal(a.angles, c.angles)


def test_value_grid_is_the_fractal_sum():
    """c = (1 + V) / 2, V = s sum_l Noise(f_l p) / a_l with f_l = 8 2^l,
    a_l = 4 2^l, s = 1 / (sqrt(2)/2 sum 1/a_l) (nl_cheng.h, cloud): the table's
    fBm through noiselab.noise over [0, 8)^2 is the same sum, to rounding, on
    the domain at the noise's origin (origin 0; the default [1, 2]^2 starts
    each octave at f_l)."""
    r = nc.optimise(DISC, seed=3, **SMALL)
    v = nc.value_grid(r.table, 32, octaves=2, origin=0)
    f = nn.grid("fbm", 32, extent=8.0, basis="table", table=r.table, octaves=2, gain=0.5,
                lacunarity=2.0)
    s = 1.0 / (np.sqrt(2) / 2 * (1 / 4 + 1 / 8))
    assert np.allclose(v, (1 + s * f / 4) / 2, rtol=0, atol=1e-12)


@pytest.mark.parametrize("call,exc,words", [
    (lambda: nc.optimise(np.full((8, 8), np.nan), **SMALL), ValueError, "not finite"),
    (lambda: nc.optimise(np.zeros((2, 2, 2, 2)), **SMALL), ValueError, "pattern: expected"),
    (lambda: nc.optimise(DISC, stat="median", **SMALL), ValueError, "median"),
    (lambda: nc.optimise(DISC, octaves=9, grid=16), ValueError, "octaves"),
    (lambda: nc.optimise(DISC, speed=3), TypeError, "speed: not an option"),
    (lambda: nc.optimise(DISC, grid=0), ValueError, "grid"),
    (lambda: nc.value_grid((np.zeros(8), np.arange(8)), 8), ValueError, "config's m is 512"),
    # the experiments' --seed range; -1 used to wrap to 2^64 - 1, 1.5 to 1
    (lambda: nc.optimise(DISC, seed=-1, **SMALL), ValueError, "seed: -1 is outside"),
    (lambda: nc.optimise(DISC, seed=2**32, **SMALL), ValueError, "seed: 4294967296 is outside"),
    (lambda: nc.optimise(DISC, seed=1.5, **SMALL), TypeError, "seed: expected an integer"),
])
def test_bad_input(call, exc, words):
    with pytest.raises(exc) as e:
        call()
    assert words in str(e.value) and "\n" not in str(e.value), str(e.value)
