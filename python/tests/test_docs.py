"""Every public function teaches itself: help() shows an Example, and the
examples run (doctest; those that need a file are marked to skip)."""
import doctest
import inspect

import pytest

import noiselab
import noiselab.byexample
import noiselab.cheng
import noiselab.noise
import noiselab.results
import noiselab.stats

MODULES = [noiselab.noise, noiselab.stats, noiselab.cheng, noiselab.byexample,
           noiselab.results]


@pytest.mark.parametrize("mod", MODULES, ids=lambda m: m.__name__)
def test_every_public_function_has_an_example(mod):
    missing = [name for name, f in vars(mod).items()
               if not name.startswith("_") and (inspect.isfunction(f) or inspect.isclass(f))
               and f.__module__ in (mod.__name__, "noiselab._gmm")
               and not name.endswith("Result")
               and name not in ("Params", "Results")
               and "Example" not in (f.__doc__ or "")]
    assert not missing, f"{mod.__name__}: no Example in {missing}"


@pytest.mark.parametrize("mod", MODULES, ids=lambda m: m.__name__)
def test_every_public_function_says_its_parameters_and_returns(mod):
    """numpydoc's sections, as scipy's: a function says what it takes and what
    it gives (a function without arguments only what it gives)."""
    missing = []
    for name in getattr(mod, "__all__", []):
        f = getattr(mod, name)
        if not inspect.isfunction(f):
            continue
        doc = inspect.getdoc(f) or ""
        want = ["Returns"] + (["Parameters"] if inspect.signature(f).parameters else [])
        missing += [f"{name} ({s})" for s in want if f"{s}\n---" not in doc]
    assert not missing, f"{mod.__name__}: no section {missing}"


@pytest.mark.parametrize("mod", MODULES, ids=lambda m: m.__name__)
def test_examples_run(mod):
    r = doctest.testmod(mod, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert r.failed == 0


def test_a_stale_mirror_is_an_import_error(tmp_path):
    """Every ctypes mirror of a library struct is checked against the
    library's own layout (nl_abi_sizeof, nl_abi_offsetof) at import: a copy
    of the package with one member retyped (nl_noise_basis's bound a float)
    or one moved (nl_gmm's k and d swapped: the same size) fails to import,
    naming the struct."""
    import os
    import shutil
    import subprocess
    import sys
    from conftest import ROOT
    cases = [("noise.py", '("bound", ctypes.c_double)', '("bound", ctypes.c_float)',
              "noise", "nl_noise_basis"),
             ("_gmm.py", '("k", ctypes.c_size_t), ("d", ctypes.c_size_t)',
              '("d", ctypes.c_size_t), ("k", ctypes.c_size_t)', "stats", "nl_gmm with d")]
    for i, (name, old, new, module, words) in enumerate(cases):
        pkg = tmp_path / str(i) / "noiselab"
        shutil.copytree(os.path.join(ROOT, "python", "noiselab"), pkg)
        src = (pkg / name).read_text()
        assert old in src
        (pkg / name).write_text(src.replace(old, new))
        # cwd: python -c looks there first, and the tests run in python/
        r = subprocess.run([sys.executable, "-c", f"import noiselab.{module}"],
                           env=dict(os.environ, PYTHONPATH=str(pkg.parent)), cwd=tmp_path,
                           capture_output=True, text=True)
        assert r.returncode != 0
        last = r.stderr.strip().splitlines()[-1]
        assert last.startswith("ImportError:") and f"mirrors struct {words}" in last, last
