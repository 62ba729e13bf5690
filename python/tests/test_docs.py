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
def test_examples_run(mod):
    r = doctest.testmod(mod, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert r.failed == 0
