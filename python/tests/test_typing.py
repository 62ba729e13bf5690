"""Type hints: every public function and method is annotated (each parameter
and the return), the package carries py.typed (PEP 561), and, where Debian's
mypy is installed, mypy finds the package clean and a caller's wrong
argument type (the check the hints are for)."""
import importlib
import inspect
import os
import subprocess
import sys

import pytest

from conftest import ROOT

MODULES = ["noiselab", "noiselab.noise", "noiselab.stats", "noiselab.cheng",
           "noiselab.byexample", "noiselab.results"]
PACKAGE = os.path.join(ROOT, "python", "noiselab")


def public_callables():
    for m in MODULES:
        mod = importlib.import_module(m)
        for name in mod.__all__:
            obj = getattr(mod, name)
            if inspect.isfunction(obj):
                yield f"{m}.{name}", obj
            elif inspect.isclass(obj) and obj.__module__.startswith("noiselab"):
                for mname, meth in vars(obj).items():
                    if isinstance(meth, (classmethod, staticmethod)):
                        meth = meth.__func__
                    elif isinstance(meth, property):
                        meth = meth.fget
                    if inspect.isfunction(meth) and (not mname.startswith("_")
                                                     or mname == "__init__"):
                        yield f"{m}.{name}.{mname}", meth


def test_every_public_function_is_annotated():
    seen, missing = 0, []
    for qual, f in public_callables():
        seen += 1
        sig = inspect.signature(f)
        for p in list(sig.parameters.values()):
            if p.name in ("self", "cls"):
                continue
            if p.annotation is inspect.Parameter.empty:
                missing.append(f"{qual}({p.name})")
        if sig.return_annotation is inspect.Signature.empty:
            missing.append(f"{qual} -> ?")
    assert seen > 40, seen   # the walk found the API (functions, methods, properties)
    assert not missing, missing


def test_py_typed_marker_is_installed():
    assert os.path.isfile(os.path.join(PACKAGE, "py.typed"))
    with open(os.path.join(ROOT, "python", "meson.build"), encoding="utf-8") as f:
        build = f.read()
    assert "'noiselab/py.typed'" in build and "'noiselab/_ext.pyi'" in build


def _mypy(*args, cwd):
    return subprocess.run([sys.executable, "-m", "mypy", "--no-incremental",
                           "--cache-dir", os.devnull, *args], cwd=cwd, capture_output=True,
                          text=True)


CALLER = """
import numpy as np
import noiselab.noise as nn
import noiselab.stats as ns

v: np.ndarray = nn.grid("fbm", 64, octaves=4)
f = nn.function("improved", seed=3)
w = f(0.5, 1.5, 2.5)
D, p = ns.kstest(np.linspace(0.01, 0.99, 20), "uniform")
g = ns.GaussianMixture(2, covariance_type="diag").fit(np.zeros((10, 2)))
labels: np.ndarray = g.predict(np.zeros((3, 2)))
"""


def test_mypy_finds_the_package_clean_and_a_wrong_call(tmp_path):
    pytest.importorskip("mypy", reason="Debian's mypy is not installed")
    r = _mypy(PACKAGE, cwd=os.path.join(ROOT, "python"))
    assert r.returncode == 0, r.stdout + r.stderr
    good = tmp_path / "caller.py"
    good.write_text(CALLER)
    env_path = os.path.join(ROOT, "python")
    r = _mypy("--python-version", "3.11", str(good), cwd=env_path)
    assert r.returncode == 0, r.stdout + r.stderr
    bad = tmp_path / "bad.py"
    bad.write_text(CALLER + 'nn.grid("fbm", "64")\nns.chisquare([1, 2], axis="rows")\n')
    r = _mypy(str(bad), cwd=env_path)
    assert r.returncode == 1, r.stdout + r.stderr
    assert 'Argument 2 to "grid" has incompatible type "str"' in r.stdout, r.stdout
    assert 'Argument "axis" to "chisquare" has incompatible type "str"' in r.stdout, r.stdout
