"""Procedural noise by example (Lagae et al. 2010, src/byexample/nl_byexample.h):
an exemplar image analysed to the parameters of a multiresolution wavelet
noise (PCA, histograms, band weights), a texture of any size synthesized
from them, and two parameter sets morphed.

  p = noiselab.byexample.analyse(image)        # (h, w) or (h, w, 3) array, or a file name
  img = noiselab.byexample.synthesize(p, 512, seed=1)   # float32 (512, 512, channels)
  m = noiselab.byexample.morph(p, q, 0.5)
  p.save("wood.params"); p = Params.load("wood.params")  # the `example` command's files

The options and defaults are `scripts/noiselab example`'s: PCA colour
decorrelation, the 33-quantile Gaussian histogram, the calibrated synthesis
(calibrate=False is the paper's).
"""

import ctypes
import os
from typing import Any, Optional, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._lib import Error, check, fn, mirror
from ._lib import integer as _int

__all__ = ["analyse", "synthesize", "morph", "read_image", "write_image", "Params"]

_MAXB = 16
_HMAX = 33
_CALIBRATE = 4   # NL_BYEXAMPLE_CALIBRATE


@mirror("nl_image")
class _Image(ctypes.Structure):
    _fields_ = [("width", ctypes.c_int), ("height", ctypes.c_int), ("channels", ctypes.c_int),
                ("data", ctypes.POINTER(ctypes.c_float))]


@mirror("nl_byexample_params")
class _Params(ctypes.Structure):
    _fields_ = [("channels", ctypes.c_int), ("nbands", ctypes.c_int), ("tile", ctypes.c_int),
                ("histogram", ctypes.c_int), ("sigma2", ctypes.c_double),
                ("mean", ctypes.c_double * 3), ("matrix", (ctypes.c_double * 3) * 3),
                ("hist_kind", ctypes.c_int), ("nhist", ctypes.c_int),
                ("hist", (ctypes.c_double * _HMAX) * 3), ("w", (ctypes.c_double * _MAXB) * 3),
                ("calibrate", ctypes.c_int), ("target", (ctypes.c_double * _MAXB) * 3),
                ("corr", (ctypes.c_double * _MAXB) * 3)]


@mirror("nl_byexample_options")
class _Options(ctypes.Structure):
    _fields_ = [("decorrelate", ctypes.c_int), ("histogram", ctypes.c_int),
                ("sigma2", ctypes.c_double), ("tile", ctypes.c_int), ("hist_kind", ctypes.c_int),
                ("calibrate", ctypes.c_int)]


@mirror("nl_byexample_synth_options")
class _SynthOptions(ctypes.Structure):
    _fields_ = [("scale", ctypes.c_double), ("solid", ctypes.c_int), ("z", ctypes.c_double),
                ("spline", ctypes.c_int)]


_E = ctypes.POINTER(Error)
_IP = ctypes.POINTER(_Image)
_PP = ctypes.POINTER(_Params)
_image_alloc = fn("nl_image_alloc", _IP, ctypes.c_int, ctypes.c_int, ctypes.c_int)
_image_free = fn("nl_image_free", None, _IP)
_image_read = fn("nl_image_read", ctypes.c_int, ctypes.c_char_p, ctypes.POINTER(_IP), _E)
_image_write = fn("nl_image_write", ctypes.c_int, _IP, ctypes.c_char_p, ctypes.c_int, _E)
_analyse = fn("nl_byexample_analyse", ctypes.c_int, _IP, ctypes.POINTER(_Options), _PP, _E)
_synthesize = fn("nl_byexample_synthesize", ctypes.c_int, _PP, ctypes.c_int, ctypes.c_int,
                 ctypes.c_ulong, ctypes.POINTER(_SynthOptions), ctypes.POINTER(_IP), _E)
_morph = fn("nl_byexample_morph", ctypes.c_int, _PP, _PP, ctypes.c_double, _PP, _E)
# The library checks synthesis and morphing arguments (nl_byexample_synth_check,
# nl_byexample_morph_check) and names them as `noiselab example` spells them.
_NAMES = {"--size": "width", "--height": "height", "--scale": "scale", "--z": "z", "--t": "t"}
_save = fn("nl_byexample_params_save", ctypes.c_int, _PP, ctypes.c_char_p, _E)
_load = fn("nl_byexample_params_load", ctypes.c_int, ctypes.c_char_p, _PP, _E)
_param_count = fn("nl_byexample_param_count", ctypes.c_int, _PP)


# `noiselab example --seed`'s range: a seed the tool refuses is refused here.
_SEED_MAX = 2**32 - 1


def _number(name, v):
    """A real number as a C double; its range is checked by the library."""
    if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name}: expected a number, got {type(v).__name__}")
    return float(v)


def _to_numpy(im):
    c = im.contents
    a = np.ctypeslib.as_array(c.data, shape=(c.height * c.width * c.channels,))
    return a.copy().reshape(c.height, c.width, c.channels)


def _from_numpy(name, a):
    a = np.asarray(a)
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{name}: expected a real array, got dtype {a.dtype}")
    if a.dtype in (np.uint8, np.uint16):
        # An image file of 8 or 16 bits is read as level / (2^bits - 1), in
        # [0, 1] (nl_image_read through OpenImageIO, as skimage's img_as_float
        # scales): the same pixels as an array give the same parameters. The
        # reader multiplies by the float 1/max, so this does too, bit for bit.
        a = a.astype(np.float32) * np.float32(1.0 / np.iinfo(a.dtype).max)
    elif a.dtype.kind in "iu":
        raise TypeError(f"{name}: integer dtype {a.dtype} has no agreed grey scale: pass "
                        f"floats (an image file reads as [0, 1]) or uint8 / uint16 levels, "
                        f"scaled by 1/255 and 1/65535")
    if a.ndim == 2:
        a = a[:, :, None]
    if a.ndim != 3 or not 1 <= a.shape[2] <= 4 or a.shape[0] < 1 or a.shape[1] < 1:
        raise ValueError(f"{name}: expected (h, w) or (h, w, channels <= 4), got {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{name}: a value is not finite")
    im = _image_alloc(a.shape[1], a.shape[0], a.shape[2])
    src = np.ascontiguousarray(a, dtype=np.float32)
    ctypes.memmove(im.contents.data, src.ctypes.data, src.nbytes)
    return im


def read_image(path: Union[str, "os.PathLike[str]"]) -> NDArray[np.float32]:
    """An image file (any format OpenImageIO reads) as a float32 (h, w, channels) array.

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    ndarray (h, w, channels) float32, values as the file's levels scaled to [0, 1]
    (floating-point files as stored)

    Example
    -------
    >>> img = read_image("data/exemplars/wood.png")            # doctest: +SKIP
    """
    im, err = _IP(), Error()
    check(_image_read(os.fsencode(os.fspath(path)), ctypes.byref(im), ctypes.byref(err)), err)
    try:
        return _to_numpy(im)
    finally:
        _image_free(im)


def write_image(image: ArrayLike, path: Union[str, "os.PathLike[str]"],
                bits: int = 16) -> None:
    """Writes an (h, w[, channels]) array as the library writes images (atomic;
    format from the extension; bits 8/16 for PNG, 16/32 for EXR). Values
    as ``analyse`` takes them: floats in [0, 1] map to the file's range,
    uint8 and uint16 levels are scaled by 1/255 and 1/65535 first.

    Parameters
    ----------
    image : array_like (h, w) or (h, w, channels)
    path : str or os.PathLike    the format from its extension
    bits : int             8 or 16 for PNG, 16 or 32 for EXR

    Returns
    -------
    None; OSError naming the path when it cannot be written

    Example
    -------
    >>> write_image(np.zeros((8, 8, 3)), "black.png", 8)       # doctest: +SKIP
    """
    im = _from_numpy("image", image)
    try:
        err = Error()
        check(_image_write(im, os.fsencode(os.fspath(path)), int(bits), ctypes.byref(err)), err)
    finally:
        _image_free(im)


class Params:
    """The parameters of a texture by example (nl_byexample_params): channels,
    nbands, mean, matrix (the PCA rotation), hist (quantiles), weights (per
    channel and band, finest first). Save and load the `example` command's
    files with save() and Params.load()."""

    def __init__(self, raw: Any) -> None:
        self._p = raw

    @property
    def channels(self) -> int:
        return self._p.channels

    @property
    def nbands(self) -> int:
        return self._p.nbands

    @property
    def mean(self) -> NDArray[np.float64]:
        return np.array(self._p.mean[:self.channels])

    @property
    def matrix(self) -> NDArray[np.float64]:
        c = self.channels
        return np.array([[self._p.matrix[i][j] for j in range(c)] for i in range(c)])

    @property
    def hist(self) -> NDArray[np.float64]:
        return np.array([self._p.hist[c][:self._p.nhist] for c in range(self.channels)])

    @property
    def weights(self) -> NDArray[np.float64]:
        return np.array([self._p.w[c][:self.nbands] for c in range(self.channels)])

    @property
    def param_count(self) -> int:
        """The parameters the paper counts (66 for a 512^2 RGB exemplar)."""
        return _param_count(ctypes.byref(self._p))

    def save(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Writes the parameters file (atomically), as `example analyse -o` does."""
        err = Error()
        check(_save(ctypes.byref(self._p), os.fsencode(os.fspath(path)), ctypes.byref(err)), err)

    @classmethod
    def load(cls, path: Union[str, "os.PathLike[str]"]) -> "Params":
        """Reads a parameters file written by save() or `noiselab example`."""
        p, err = _Params(), Error()
        check(_load(os.fsencode(os.fspath(path)), ctypes.byref(p), ctypes.byref(err)), err)
        return cls(p)

    def __repr__(self):
        return (f"Params({self.channels} channels, {self.nbands} bands, "
                f"{self.param_count} parameters)")


def analyse(image: Union[ArrayLike, str, "os.PathLike[str]"], *, rgb: bool = False,
            histogram: bool = True, paper_histogram: bool = False,
            calibrate: bool = True) -> Params:
    """Analyses an exemplar into Params (nl_byexample_analyse), as
    `noiselab example analyse` does.

    Parameters
    ----------
    image : array_like (h, w) or (h, w, channels), or a file name
        grey, grey+alpha, RGB or RGBA (alpha dropped), at least 16 x 16.
        Floats are taken as they are; uint8 and uint16 are levels, scaled
        to [0, 1] by 1/255 and 1/65535 as an image file of that depth reads
        (and as skimage's img_as_float does); other integer dtypes raise
        TypeError.
    rgb : bool             plain RGB channels instead of the PCA decorrelation
    histogram : bool       histogram matching (sec. 5.2)
    paper_histogram : bool the paper's 10 quantiles instead of 33 Gaussian ones
    calibrate : bool       store the band targets for the calibrated synthesis

    Returns
    -------
    Params : the exemplar's parameters (channels, bands, weights, histograms)

    Example
    -------
    >>> import numpy as np, noiselab.noise as nn, noiselab.byexample as nb
    >>> img = nn.grid("fbm", 64, seed=3)
    >>> p = nb.analyse(img)
    >>> p.channels, nb.synthesize(p, 32, seed=1).shape
    (1, (32, 32, 1))
    """
    if isinstance(image, (str, bytes, os.PathLike)):
        im, err = _IP(), Error()
        check(_image_read(os.fsencode(os.fspath(image)), ctypes.byref(im), ctypes.byref(err)),
              err)
    else:
        im = _from_numpy("image", image)
    try:
        o = _Options(0 if rgb else 1, 1 if histogram else 0, 0.0, 0,
                     0 if paper_histogram else 1, _CALIBRATE if calibrate else 0)
        p, err = _Params(), Error()
        check(_analyse(im, ctypes.byref(o), ctypes.byref(p), ctypes.byref(err)), err)
        return Params(p)
    finally:
        _image_free(im)


def synthesize(params: Params, width: int, height: Optional[int] = None, *, seed: int = 1,
               scale: float = 1.0, solid: bool = False, z: float = 0.0) -> NDArray[np.float32]:
    """A width x height texture from Params (nl_byexample_synthesize), float32
    (height, width, channels), as `noiselab example synthesize` makes it
    before writing its file. scale: pixel size in exemplar pixels; solid:
    a slice z of 3D wavelet noise.

    What the tool refuses raises here, checked by the same library call
    (nl_byexample_synth_check): width and height outside 1..32768, a seed
    outside 0..2^32 - 1 or a scale outside [1e-6, 1e6] or not finite, |z| >
    1e9 or not finite are a ValueError; a non-integer size or seed, or a
    scale or z that is not a number, a TypeError.

    Parameters
    ----------
    params : Params        from analyse() or morph()
    width, height : int    pixels (height defaults to width)
    seed : int             the noise's seed, 0..2^32 - 1
    scale : float          pixel size in exemplar pixels
    solid : bool           a slice of 3D wavelet noise instead of 2D
    z : float              the slice's z (solid only)

    Returns
    -------
    ndarray (height, width, channels) float32

    Example
    -------
    >>> import noiselab.noise as nn, noiselab.byexample as nb
    >>> p = nb.analyse(nn.grid("fbm", 64, seed=3))
    >>> nb.synthesize(p, 48, 32, seed=2).shape
    (32, 48, 1)
    """
    if not isinstance(params, Params):
        raise TypeError(f"params: expected noiselab.byexample.Params, got {type(params).__name__}")
    height = width if height is None else height
    for name, v in (("width", width), ("height", height)):
        # the range is the library's; here only what a C int holds
        _int(name, v, -2**31, 2**31 - 1)
    seed = _int("seed", seed, 0, _SEED_MAX)
    so = _SynthOptions(_number("scale", scale), 1 if solid else 0, _number("z", z), 0)
    im, err = _IP(), Error()
    check(_synthesize(ctypes.byref(params._p), int(width), int(height), seed, ctypes.byref(so),
                      ctypes.byref(im), ctypes.byref(err)), err, _NAMES)
    try:
        return _to_numpy(im)
    finally:
        _image_free(im)


def morph(a: Params, b: Params, t: float) -> Params:
    """Params between a (t = 0) and b (t = 1): linear, the PCA rotation by
    quaternion slerp (nl_byexample_morph). t outside [0, 1] (it would
    extrapolate) or not finite is a ValueError, as `example morph --t`.

    Parameters
    ----------
    a, b : Params          the two ends, with the same channels
    t : float              in [0, 1]

    Returns
    -------
    Params

    Example
    -------
    >>> import noiselab.noise as nn, noiselab.byexample as nb
    >>> a = nb.analyse(nn.grid("fbm", 64, seed=3))
    >>> b = nb.analyse(nn.grid("turbulence", 64, seed=4))
    >>> nb.morph(a, b, 0.5).channels
    1
    """
    for name, v in (("a", a), ("b", b)):
        if not isinstance(v, Params):
            raise TypeError(f"{name}: expected noiselab.byexample.Params, got {type(v).__name__}")
    m, err = _Params(), Error()
    check(_morph(ctypes.byref(a._p), ctypes.byref(b._p), _number("t", t), ctypes.byref(m),
                 ctypes.byref(err)), err, _NAMES)
    return Params(m)
