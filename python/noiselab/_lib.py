"""Loading libnoiselab and turning its status codes into exceptions.

Where the library is looked for, first found wins:
  1. the file named by NOISELAB_LIBRARY (a path to libnoiselab.so);
  2. the build tree this package sits in: python/noiselab/ beside build/
     (a checkout built by `scripts/noiselab setup`), so that
     `PYTHONPATH=python` works with no installation;
  3. LIBDIR recorded when meson installed this package (_config.py);
  4. LIBDIR of an installed noiselab, from `pkg-config --variable=libdir
     noiselab` (meson install puts noiselab.pc there);
  5. the dynamic loader's own search (ctypes.util.find_library).
"""

import ctypes
import ctypes.util
import os
import subprocess

NL_OK, NL_EINVAL, NL_EIO, NL_EFORMAT, NL_ENOMEM, NL_ENUM = range(6)


class NoiselabError(RuntimeError):
    """A numerical failure of the library (NL_ENUM: singular matrix, no convergence)."""


class Error(ctypes.Structure):
    """nl_error: the library's one-line message."""
    _fields_ = [("msg", ctypes.c_char * 512)]


def _candidates():
    env = os.environ.get("NOISELAB_LIBRARY")
    if env:
        yield env
        return
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(os.path.dirname(here))
    yield os.path.join(root, "build", "libnoiselab.so")
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


def check(status, err):
    """Raises the exception for a non-zero nl_status, with the library's message."""
    if status == NL_OK:
        return
    msg = err.msg.decode("utf-8", "replace")
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
