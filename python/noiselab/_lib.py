"""Loading libnoiselab and turning its status codes into exceptions.

The extension noiselab._ext (_ext.c: the noise calls) holds the whole
library (linked in whole), so an installed package or a wheel is one file
of C. It is imported from the package (installed: meson install, pip), else
from a build tree: $NOISELAB_BUILD/python/, then build/python/ beside
python/noiselab/ (a checkout built by `scripts/noiselab setup`, so that
`PYTHONPATH=python` works with no installation).

Where ctypes finds the library for everything else, first found wins:
  1. the file named by NOISELAB_LIBRARY (a path to libnoiselab.so);
  2. the extension itself (ctypes opens it: the same copy of the library);
  3. a build tree: $NOISELAB_BUILD/libnoiselab.so, then build/ beside
     python/noiselab/;
  4. LIBDIR recorded when meson installed this package (_config.py);
  5. LIBDIR of an installed noiselab, from `pkg-config --variable=libdir
     noiselab` (meson install puts noiselab.pc there);
  6. the dynamic loader's own search (ctypes.util.find_library).
"""

import ctypes
import ctypes.util
import importlib.machinery
import importlib.util
import os
import subprocess
import sys

import numpy as np

__all__ = ["NoiselabError", "Error", "ext", "lib", "path", "check", "fn",
           "mirror", "integer", "real", "c_double_p"]

NL_OK, NL_EINVAL, NL_EIO, NL_EFORMAT, NL_ENOMEM, NL_ENUM = range(6)


class NoiselabError(RuntimeError):
    """A numerical failure of the library (NL_ENUM: singular matrix, no convergence)."""




_HERE = os.path.dirname(os.path.abspath(__file__))
_BUILDS = [os.environ["NOISELAB_BUILD"]] if os.environ.get("NOISELAB_BUILD") else []
_BUILDS.append(os.path.join(os.path.dirname(os.path.dirname(_HERE)), "build"))


def _load_ext():
    """noiselab._ext: the package's own, else a build tree's; None if neither."""
    name = __name__.rpartition(".")[0] + "._ext"
    try:
        return importlib.import_module(name)
    except ImportError:
        pass
    for build in _BUILDS:
        for suffix in importlib.machinery.EXTENSION_SUFFIXES:
            f = os.path.join(build, "python", "_ext" + suffix)
            if os.path.exists(f):
                spec = importlib.util.spec_from_file_location(name, f)
                if spec is None or spec.loader is None:
                    continue
                mod = importlib.util.module_from_spec(spec)
                try:
                    spec.loader.exec_module(mod)
                except ImportError:   # another numpy's ABI: stats and the rest still load
                    continue
                sys.modules[name] = mod
                return mod
    return None


ext = _load_ext()


def _candidates():
    env = os.environ.get("NOISELAB_LIBRARY")
    if env:
        yield env
        return
    if ext is not None:
        yield ext.__file__
    for build in _BUILDS:
        yield os.path.join(build, "libnoiselab.so")
    try:
        from . import _config
        yield os.path.join(_config.LIBDIR, "libnoiselab.so")
    except ImportError:
        pass
    try:
        libdir = subprocess.run(["pkg-config", "--variable=libdir", "noiselab"],
                                capture_output=True, text=True, check=True).stdout.strip()
        if libdir:
            yield os.path.join(libdir, "libnoiselab.so")
    except (OSError, subprocess.CalledProcessError):
        pass
    found = ctypes.util.find_library("noiselab")
    if found:
        yield found


def _load():
    tried = []
    for path in _candidates():
        if os.path.sep in path and not os.path.exists(path):
            tried.append(path)
            continue
        try:
            return ctypes.CDLL(path), path
        except OSError as e:
            tried.append(f"{path} ({e})")
    raise OSError("libnoiselab not found (tried: " + ", ".join(tried or ["nothing"]) +
                  "); build it with `scripts/noiselab setup` or set NOISELAB_LIBRARY")


lib, path = _load()


def check(status, err, names=None):
    """Raises the exception for a non-zero nl_status, with the library's message.

    names maps how the library names an input at the start of its message
    (the command-line option, "--tile", or the C field, "cellular: lambda")
    to the Python parameter, which the message then names instead."""
    if status == NL_OK:
        return
    msg = err.msg.decode("utf-8", "replace")
    for lib_name, py_name in (names or {}).items():
        if msg.startswith(lib_name) and msg[len(lib_name):len(lib_name) + 1] in (":", " "):
            msg = py_name + msg[len(lib_name):]
            break
    if status in (NL_EINVAL, NL_EFORMAT):
        raise ValueError(msg)
    if status == NL_EIO:
        raise OSError(msg)
    if status == NL_ENOMEM:
        raise MemoryError(msg)
    raise NoiselabError(msg)


def fn(name, restype, *argtypes):
    """The library function name with its C signature."""
    f = getattr(lib, name)
    f.restype = restype
    f.argtypes = list(argtypes)
    return f


c_double_p = ctypes.POINTER(ctypes.c_double)


_abi_sizeof = fn("nl_abi_sizeof", ctypes.c_size_t, ctypes.c_char_p, ctypes.c_char_p)
_abi_offsetof = fn("nl_abi_offsetof", ctypes.c_long, ctypes.c_char_p, ctypes.c_char_p)


def mirror(c_type, **members):
    """Class decorator of a ctypes Structure that mirrors the library's struct
    c_type: its size and every field's offset and size are checked against
    the library's own (abi/nl_abi.h) when the class is made, at import, so
    that a mirror gone stale (a member added, removed, retyped or moved in C) raises
    ImportError naming the struct instead of reading the wrong bytes.
    members maps a field to its C designator where the names differ
    (lambda_="lambda", gctbf_cell="gctbf.cell")."""
    def check(cls):
        where = f"{cls.__module__}.{cls.__qualname__}"
        size = _abi_sizeof(c_type.encode(), None)
        if size == 0:
            raise ImportError(f"{where}: {path} does not describe struct {c_type}: the package "
                              f"and the library come from different versions")
        if size != ctypes.sizeof(cls):
            raise ImportError(f"{where} mirrors struct {c_type} in {ctypes.sizeof(cls)} bytes, "
                              f"{path} has {size}: the package and the library come from "
                              f"different versions")
        for field in cls._fields_:
            name = field[0]
            c_name = members.get(name, name)
            want = (_abi_offsetof(c_type.encode(), c_name.encode()),
                    _abi_sizeof(c_type.encode(), c_name.encode()))
            got = (getattr(cls, name).offset, getattr(cls, name).size)
            if want != got:
                raise ImportError(f"{where} mirrors struct {c_type} with {c_name} at offset "
                                  f"{got[0]}, {got[1]} bytes; {path} has offset {want[0]}, "
                                  f"{want[1]} bytes: the package and the library come from "
                                  f"different versions")
        return cls
    return check


@mirror("nl_error")
class Error(ctypes.Structure):
    """nl_error: the library's one-line message."""
    _fields_ = [("msg", ctypes.c_char * 512)]


# The checks Python makes itself: a value's type, and an integer's range
# where the C call takes a narrower type. Ranges of values are the library's
# to check (one validation for the tools and Python).
def integer(name, v, lo, hi, interval="[{lo}, {hi}]"):
    """v as an int in lo..hi; TypeError for a non-integer (bool included)."""
    if isinstance(v, bool) or not isinstance(v, (int, np.integer)):
        raise TypeError(f"{name}: expected an integer, got {type(v).__name__}")
    if not lo <= v <= hi:
        raise ValueError(f"{name}: {v} is outside " + interval.format(lo=lo, hi=hi))
    return int(v)


def real(name, v):
    """v as a C double; whether it is finite and in range is the library's to say."""
    try:
        return float(v)
    except (TypeError, ValueError):
        raise TypeError(f"{name}: expected a number, got {v!r}") from None
