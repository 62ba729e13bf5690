"""noiselab.byexample against `noiselab example` (the tool's files, byte for byte)."""
import os
import subprocess

import numpy as np
import pytest

from conftest import BUILD, ROOT
import noiselab.byexample as nb
import noiselab.noise as nn

EXAMPLE = os.path.join(BUILD, "tools", "noiselab-example")


def exemplar(seed, size=64):
    """A coloured fBm texture in [0, 1]: three correlated channels."""
    a, b = (nn.grid("fbm", size, seed=seed + k) for k in (0, 1))
    return np.stack([(1 + a) / 2, (1 + 0.7 * a + 0.3 * b) / 2, (1 + b) / 2], axis=-1)


def tool(*args):
    subprocess.run([EXAMPLE, *map(str, args)], check=True, capture_output=True)


def test_analyse_synthesize_morph_are_the_tool(tmp_path):
    ea, eb = exemplar(1), exemplar(7)
    nb.write_image(ea, tmp_path / "a.exr", 32)   # float32: the tool reads the array's values
    nb.write_image(eb, tmp_path / "b.exr", 32)
    tool("analyse", tmp_path / "a.exr", "-o", tmp_path / "a.params")
    tool("analyse", tmp_path / "b.exr", "-o", tmp_path / "b.params")
    pa, pb = nb.analyse(ea), nb.analyse(eb)
    pa.save(tmp_path / "pa.params")
    assert (tmp_path / "pa.params").read_bytes() == (tmp_path / "a.params").read_bytes()
    assert np.array_equal(nb.analyse(tmp_path / "a.exr").weights, pa.weights)
    assert np.array_equal(nb.Params.load(tmp_path / "b.params").weights, pb.weights)
    assert pa.channels == 3 and pa.weights.shape == (3, pa.nbands)
    m = pa.matrix
    assert np.allclose(m @ m.T, np.eye(3), atol=1e-12) and np.linalg.det(m) > 0

    tool("synthesize", tmp_path / "a.params", "--size", 48, "--height", 40, "--seed", 5,
         "-o", tmp_path / "s.exr")
    s = nb.synthesize(pa, 48, 40, seed=5)
    assert s.shape == (40, 48, 3) and s.dtype == np.float32
    ref = nb.read_image(tmp_path / "s.exr")           # the tool writes half floats
    assert np.array_equal(s.astype(np.float16).astype(np.float32), ref)

    tool("morph", tmp_path / "a.params", tmp_path / "b.params", "--t", 0.3,
         "-o", tmp_path / "m.params")
    nb.morph(pa, pb, 0.3).save(tmp_path / "pm.params")
    assert (tmp_path / "pm.params").read_bytes() == (tmp_path / "m.params").read_bytes()
    assert np.allclose(nb.morph(pa, pb, 0.0).weights, pa.weights, rtol=1e-15)


def test_grey_exemplar():
    p = nb.analyse(nn.grid("fbm", 64, seed=3), calibrate=False, paper_histogram=True)
    assert p.channels == 1 and p.hist.shape == (1, 10)
    s = nb.synthesize(p, 32, seed=2)
    assert s.shape == (32, 32, 1) and np.all(np.isfinite(s))
    assert np.array_equal(s, nb.synthesize(p, 32, seed=2))


@pytest.mark.parametrize("call,exc,words", [
    (lambda: nb.analyse(np.zeros((8, 8))), ValueError, "16"),
    (lambda: nb.analyse(np.full((32, 32), np.inf)), ValueError, "not finite"),
    (lambda: nb.analyse(np.zeros((32, 32, 5))), ValueError, "channels <= 4"),
    (lambda: nb.analyse("/nonexistent/x.png"), OSError, "/nonexistent/x.png"),
    (lambda: nb.synthesize(nb.analyse(exemplar(1)), 0), ValueError, "width: 0"),
    (lambda: nb.synthesize("p", 8), TypeError, "params"),
    (lambda: nb.morph(nb.analyse(exemplar(1)), nb.analyse(exemplar(1)[..., 0]), 0.5),
     ValueError, "channel"),
])
def test_bad_input(call, exc, words):
    with pytest.raises(exc) as e:
        call()
    assert words in str(e.value) and "\n" not in str(e.value), str(e.value)


def test_failed_writes_leave_nothing(tmp_path):
    """Bad input and a full disk (RLIMIT_FSIZE, SIGXFSZ ignored, in a child)
    raise one-line errors and leave no file, not even a temporary one."""
    import subprocess
    import sys
    bad = [(lambda: nb.write_image(np.full((8, 8), np.nan), tmp_path / "a.png", 8), ValueError),
           (lambda: nb.write_image(np.zeros((8, 8)), tmp_path / "a.png", 7), ValueError),
           (lambda: nb.write_image(np.zeros((8, 8)), tmp_path / "no" / "a.png", 8), OSError)]
    for call, exc in bad:
        with pytest.raises(exc) as e:
            call()
        assert "\n" not in str(e.value)
    assert os.listdir(tmp_path) == []
    code = """if True:
        import resource, signal, sys
        import numpy as np, noiselab.byexample as nb
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (512, 512))
        img = np.random.default_rng(1).random((128, 128, 3))
        p = nb.analyse(np.random.default_rng(2).random((64, 64)))
        for write in (lambda: nb.write_image(img, sys.argv[1] + "/full.png", 16),
                      lambda: p.save(sys.argv[1] + "/full.params")):
            try:
                write()
            except OSError as e:
                print("OSError:", e)
    """
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "python"))
    r = subprocess.run([sys.executable, "-c", code, str(tmp_path)], env=env,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    assert len(lines) == 2 and all(line.startswith("OSError:") for line in lines), r.stdout
    assert os.listdir(tmp_path) == []


@pytest.fixture(scope="module")
def params():
    return nb.analyse(exemplar(1)[..., 0])


# Each value `noiselab example` refuses, refused here by the same library
# check (nl_byexample_synth_check, nl_byexample_morph_check), in the same words.
@pytest.mark.parametrize("kw,words", [
    (dict(scale=float("nan")), "scale: nan is not a finite number"),
    (dict(scale=float("inf")), "scale: inf is not a finite number"),
    (dict(scale=-1.0), "scale: -1 is outside [1e-06, 1e+06]"),
    (dict(scale=0), "scale: 0 is outside [1e-06, 1e+06]"),
    (dict(solid=True, z=float("nan")), "z: nan is not a finite number"),
    (dict(z=2e9), "z: 2e+09 is outside [-1e+09, 1e+09]"),
    (dict(width=32769), "width: 32769 is outside [1, 32768]"),
    (dict(height=40000), "height: 40000 is outside [1, 32768]"),
])
def test_synthesize_refuses_what_the_tool_refuses(params, kw, words):
    width = kw.pop("width", 16)
    with pytest.raises(ValueError) as e:
        nb.synthesize(params, width, **kw)
    assert str(e.value) == words


@pytest.mark.parametrize("kw,exc", [(dict(seed=-1), ValueError), (dict(seed=2**32), ValueError),
                                    (dict(scale="1"), TypeError), (dict(width=1.5), TypeError),
                                    (dict(width=2**32 + 16), ValueError)])
def test_synthesize_refuses_seeds_and_types(params, kw, exc):
    width = kw.pop("width", 16)
    with pytest.raises(exc):
        nb.synthesize(params, width, **kw)


@pytest.mark.parametrize("t,words", [(float("nan"), "t: nan is not a finite number"),
                                     (2.0, "t: 2 is outside [0, 1]"),
                                     (-0.25, "t: -0.25 is outside [0, 1]")])
def test_morph_refuses_what_the_tool_refuses(params, t, words):
    with pytest.raises(ValueError) as e:
        nb.morph(params, params, t)
    assert str(e.value) == words


@pytest.mark.parametrize("opt,value,words", [("--scale", "nan", "--scale: 'nan' is not a finite"),
                                             ("--scale", "0", "--scale: 0 is outside"),
                                             ("--scale", "-1", "--scale: -1 is outside"),
                                             ("--t", "2", "--t: 2 is outside [0, 1]")])
def test_tool_refuses_the_same(tmp_path, params, opt, value, words):
    params.save(tmp_path / "p.params")
    cmd = (["morph", tmp_path / "p.params", tmp_path / "p.params", "-o", tmp_path / "m.params"]
           if opt == "--t" else
           ["synthesize", tmp_path / "p.params", "--size", 16, "-o", tmp_path / "x.png"])
    r = subprocess.run([EXAMPLE, *map(str, cmd), opt, value], capture_output=True, text=True)
    assert r.returncode != 0 and words in r.stderr and r.stderr.count("\n") == 1, r.stderr


@pytest.mark.parametrize("dtype,bits", [(np.uint8, 8), (np.uint16, 16)])
def test_integer_levels_are_scaled_as_the_file_reads(tmp_path, dtype, bits):
    """uint8 and uint16 arrays are levels: the parameters are those of the
    same pixels read from a PNG of that depth (level / (2^bits - 1)), not of
    values 0..255 taken as they are."""
    top = np.iinfo(dtype).max
    levels = np.clip(np.round(exemplar(3) * top), 0, top).astype(dtype)
    path = tmp_path / "e.png"
    nb.write_image(levels, path, bits)
    scaled = levels.astype(np.float32) * np.float32(1.0 / top)
    assert np.array_equal(nb.read_image(path), scaled)
    got, ref = nb.analyse(levels), nb.analyse(path)
    assert np.array_equal(got.weights, ref.weights) and np.array_equal(got.mean, ref.mean)
    assert np.array_equal(got.weights, nb.analyse(scaled).weights)
    assert not np.allclose(got.mean, nb.analyse(levels.astype(float)).mean)


@pytest.mark.parametrize("dtype", [np.int64, np.int8, np.uint32])
def test_other_integer_images_are_refused(dtype):
    with pytest.raises(TypeError) as e:
        nb.analyse(np.zeros((32, 32), dtype))
    assert str(e.value).startswith(f"image: integer dtype {np.dtype(dtype)} has no agreed")
