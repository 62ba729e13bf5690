/* noiselab._ext: the noise calls of noiselab.noise as a CPython extension.
 *
 * Why an extension and not ctypes: a ctypes call costs ~0.4 us of argument
 * conversion before the C code runs, and a point of improved noise costs
 * ~20 ns, so a loop of scalar calls from Python was 40x slower than
 * python3-noise's pnoise3. Why a hand-written callable and not a numpy
 * ufunc: a ufunc call on three Python floats goes through numpy's dispatch
 * (type resolution, 0-d arrays, the scalar result), which alone costs more
 * than the 1.5x pnoise3 target (docs/python.md, "The extension", gives the
 * measurement); the array path keeps numpy's broadcasting by broadcasting
 * in noise.py and handing this module contiguous float64 arrays.
 *
 * NoiseFunction: a built noise (the tables of a noiselab.noise._Noise,
 * which it keeps alive) called as f(x, y[, z]). Python floats and ints take
 * the fast path: PyFloat_AS_DOUBLE, the library's range check and point
 * call, a numpy float64 back - no array is made. Anything else (arrays,
 * keywords, a refused point, which needs its one-line error) goes to the
 * Python fallback the object was made with.
 *
 * points(): the batch over contiguous arrays, run a block at a time with
 * the GIL released; between blocks the GIL is taken back to check for
 * signals (PyErr_CheckSignals needs it), so Ctrl-C raises
 * KeyboardInterrupt within a block's time (a few ms) instead of at the
 * end of a long call.
 *
 * grid(): nl_noise_fractal_grid's raster (and nl_texture_marble_grid's), the
 * same row calls in the same order, a block of rows at a time with the same
 * signal checks between blocks. */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <structmember.h>
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>
#include <numpy/arrayscalars.h>

#include "basis/nl_basis.h"
#include "base/nl_parallel.h"
#include "texture/nl_texture.h"

#include <math.h>

/* How a built noise evaluates points (noise.py chooses, by what the
 * library has kernels for). */
enum {
  K_PERM3,     /* improved noise, alone or fractal/fbm sums (batch SIMD, checked) */
  K_GRAD2,     /* noise2 alone (batch SIMD, checked) */
  K_WAVELET,   /* wavelet alone (nl_wavelet_points) */
  K_GCTBF,     /* gctbf alone (nl_cellular_gctbf_points) */
  K_SUM,       /* any other sum: nl_noise_fractal_points over the basis */
  K_COUNT
};

typedef struct {
  PyObject_HEAD
  vectorcallfunc vectorcall;
  PyObject *owner;      /* what owns the tables below (kept alive) */
  PyObject *fallback;   /* called with the arguments the fast path declines */
  int kind, planar, has_sum;
  const nl_basis *b;    /* K_PERM3, K_WAVELET, K_GCTBF */
  const nl_noise_grad2 *grad2;
  nl_noise_basis basis; /* K_SUM */
  nl_noise_octaves oct;
  double fmax;
} NoiseFunction;

/* Points per block between two checks for signals: a block of the slowest
 * kernel stays within a few ms (10^6 points of 6-octave fbm: ~60 ms in all;
 * gctbf ~1 us a point), and 16 GIL round trips in 10^6 points cost
 * nothing measurable. */
/* A threaded call's blocks are this many times the one-thread block: each
 * nl_parallel_for starts its threads (about 0.1 ms), and the one-thread
 * blocks, sized for Ctrl-C, are too small to pay for that. */
#define THREADED_BLOCKS 16

static size_t block_points(const NoiseFunction *f)
{
  size_t per = (f->kind == K_PERM3 || f->kind == K_GRAD2) ? 65536 : 4096;
  size_t oct = f->oct.n > 1 ? (size_t)f->oct.n : 1;
  per /= oct;
  return per < 64 ? 64 : per;
}

/* The first refused point of x[0..n) (n if none); out[0..k) written. No GIL. */
static size_t run(const NoiseFunction *f, const double *x, const double *y, const double *z,
                  size_t n, double *out, int nthreads)
{
  size_t k;
  switch (f->kind) {
  case K_PERM3:   /* the same bytes for any nthreads (nl_noise.h, "threads") */
    return nl_noise_perm3_points_checked_threads(&f->b->perm3, f->has_sum ? &f->oct : NULL, x, y,
                                                 z, n, out, nthreads);
  case K_GRAD2:
    return nl_noise_grad2_points_checked_threads(f->grad2, x, y, n, out, nthreads);
  default:
    break;
  }
  k = nl_noise_points_refused(x, y, z, n, f->fmax);
  if (f->kind == K_WAVELET)
    nl_wavelet_points(f->b->tile, x, y, z, k, out);
  else if (f->kind == K_GCTBF)
    nl_cellular_gctbf_points(f->b->gctbf.cell, &f->b->gctbf.g, x, y, z, k, out);
  else
    nl_noise_fractal_points(&f->basis, &f->oct, x, y, z, k, out);
  return k;
}

static int scalar(PyObject *o, double *v)
{
  if (PyFloat_Check(o)) {             /* float and numpy.float64 */
    *v = PyFloat_AS_DOUBLE(o);
    return 1;
  }
  if (PyLong_CheckExact(o)) {         /* not bool: a bool is no coordinate */
    *v = PyLong_AsDouble(o);
    if (*v == -1.0 && PyErr_Occurred()) {
      PyErr_Clear();
      return 0;
    }
    return 1;
  }
  return 0;
}

static PyObject *nf_vectorcall(PyObject *self, PyObject *const *args, size_t nargsf,
                               PyObject *kwnames)
{
  NoiseFunction *f = (NoiseFunction *)self;
  Py_ssize_t nargs = PyVectorcall_NARGS(nargsf);
  double c[3] = {0.0, 0.0, 0.5}, v;
  PyObject *r;

  if (kwnames || nargs < 2 || nargs > (f->planar ? 2 : 3))
    goto slow;
  for (Py_ssize_t i = 0; i < nargs; i++)
    if (!scalar(args[i], &c[i]))
      goto slow;
  if (f->kind == K_PERM3 && !f->has_sum) {
    /* the batch kernel's bits (nl_noise.h: out[k] = nl_noise_perm3_eval) */
    if (nl_noise_points_refused(&c[0], &c[1], &c[2], 1, f->fmax) != 1)
      goto slow;
    v = nl_noise_perm3_eval(&f->b->perm3, c[0], c[1], c[2]);
  } else if (f->kind == K_GRAD2) {
    if (nl_noise_points_refused(&c[0], &c[1], NULL, 1, f->fmax) != 1)
      goto slow;
    v = nl_noise_grad2_eval(f->grad2, c[0], c[1]);
  } else if (run(f, &c[0], &c[1], f->planar ? NULL : &c[2], 1, &v, 1) != 1) {
    goto slow;
  }
  r = PyArrayScalar_New(Double);
  if (r)
    PyArrayScalar_ASSIGN(r, Double, v);
  return r;
slow:
  if (!f->fallback || f->fallback == Py_None) {
    PyErr_SetString(PyExc_TypeError, "noise function without a fallback");
    return NULL;
  }
  return PyObject_Vectorcall(f->fallback, args, nargsf, kwnames);
}

static int nf_traverse(NoiseFunction *f, visitproc visit, void *arg)
{
  Py_VISIT(f->owner);
  Py_VISIT(f->fallback);
  return 0;
}

static int nf_clear(NoiseFunction *f)
{
  Py_CLEAR(f->owner);
  Py_CLEAR(f->fallback);
  return 0;
}

static void nf_dealloc(NoiseFunction *f)
{
  PyObject_GC_UnTrack(f);
  nf_clear(f);
  Py_TYPE(f)->tp_free((PyObject *)f);
}

static void *address(PyObject *o)
{
  return o == Py_None ? NULL : PyLong_AsVoidPtr(o);
}

/* NoiseFunction(owner, fallback, kind, planar, basis, noise_basis, octaves,
 * grad2, has_sum): the addresses (ints, or None) of the owner's nl_basis,
 * its nl_noise_basis and nl_noise_octaves (both copied) and grad2 table. */
static PyObject *nf_new(PyTypeObject *type, PyObject *args, PyObject *kw)
{
  PyObject *owner, *fallback, *pb, *pnb, *po, *pg;
  int kind, planar, has_sum;
  NoiseFunction *f;

  if (kw && PyDict_GET_SIZE(kw)) {
    PyErr_SetString(PyExc_TypeError, "NoiseFunction takes no keywords");
    return NULL;
  }
  if (!PyArg_ParseTuple(args, "OOiiOOOOi", &owner, &fallback, &kind, &planar, &pb, &pnb, &po,
                        &pg, &has_sum))
    return NULL;
  if (kind < 0 || kind >= K_COUNT) {
    PyErr_Format(PyExc_ValueError, "NoiseFunction: kind %d", kind);
    return NULL;
  }
  f = (NoiseFunction *)type->tp_alloc(type, 0);
  if (!f)
    return NULL;
  f->vectorcall = nf_vectorcall;
  f->kind = kind;
  f->planar = planar;
  f->has_sum = has_sum;
  f->b = address(pb);
  f->grad2 = address(pg);
  const nl_noise_basis *nb = address(pnb);
  const nl_noise_octaves *o = address(po);
  if (PyErr_Occurred() || !o || (kind == K_GRAD2 && !f->grad2) ||
      ((kind == K_PERM3 || kind == K_WAVELET || kind == K_GCTBF) && !f->b) ||
      (kind == K_SUM && !nb)) {
    if (!PyErr_Occurred())
      PyErr_SetString(PyExc_ValueError, "NoiseFunction: missing table");
    Py_DECREF(f);
    return NULL;
  }
  if (nb)
    f->basis = *nb;
  f->oct = *o;
  f->fmax = nl_noise_octaves_fmax(&f->oct);
  Py_INCREF(owner);
  f->owner = owner;
  Py_INCREF(fallback);
  f->fallback = fallback;
  return (PyObject *)f;
}

static PyMemberDef nf_members[] = {
  {"_noise", T_OBJECT, offsetof(NoiseFunction, owner), READONLY, "the built noise"},
  {"_kind", T_INT, offsetof(NoiseFunction, kind), READONLY, "how its points are evaluated"},
  {NULL, 0, 0, 0, NULL}
};

static PyTypeObject NoiseFunctionType = {
  PyVarObject_HEAD_INIT(NULL, 0)
  .tp_name = "noiselab.noise.NoiseFunction",
  .tp_basicsize = sizeof(NoiseFunction),
  .tp_flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_HAVE_GC | Py_TPFLAGS_HAVE_VECTORCALL,
  .tp_doc = "A built noise, f(x, y[, z], *, out=None): noiselab.noise.function's result.\n\n"
            "Python floats and ints take a fast path (a numpy.float64 back);\n"
            "arrays, out= and refused points go through noiselab.noise.points.\n\n"
            "Parameters\n----------\n"
            "x, y, z : float or array_like\n    the point(s); z defaults to 0.5, 2D noises take none.\n"
            "out : numpy.ndarray, optional\n    as points' out=.\n\n"
            "Returns\n-------\n"
            "numpy.float64, or an array of the broadcast shape\n\n"
            "Example\n-------\n"
            ">>> import noiselab.noise as nn\n"
            ">>> f = nn.function(\"fbm\", octaves=3)\n"
            ">>> isinstance(f, nn.NoiseFunction), f(0.5, 0.25) == nn.points(0.5, 0.25, noise=\"fbm\", octaves=3)\n"
            "(True, True)\n",
  .tp_new = nf_new,
  .tp_dealloc = (destructor)nf_dealloc,
  .tp_traverse = (traverseproc)nf_traverse,
  .tp_clear = (inquiry)nf_clear,
  .tp_call = PyVectorcall_Call,
  .tp_vectorcall_offset = offsetof(NoiseFunction, vectorcall),
  .tp_members = nf_members,
};

/* The data of a C-contiguous numpy array of n entries of type (NPY_DOUBLE
 * or NPY_FLOAT), or NULL with a ValueError naming it. */
static void *array_of(PyObject *a, size_t n, const char *name, int writeable, int type)
{
  if (!PyArray_Check(a) || PyArray_TYPE((PyArrayObject *)a) != type ||
      !PyArray_IS_C_CONTIGUOUS((PyArrayObject *)a) || (size_t)PyArray_SIZE((PyArrayObject *)a) != n ||
      (writeable && !PyArray_ISWRITEABLE((PyArrayObject *)a))) {
    PyErr_Format(PyExc_ValueError, "%s: expected a C-contiguous %s array of %zu entries", name,
                 type == NPY_FLOAT ? "float32" : "float64", n);
    return NULL;
  }
  return PyArray_DATA((PyArrayObject *)a);
}

static const double *data_of(PyObject *a, size_t n, const char *name, int writeable)
{
  return array_of(a, n, name, writeable, NPY_DOUBLE);
}

/* The float32 path (nl_noise.h, "float32 path"): improved noise alone or
 * its fBm and fractal sums, and the 2D table noise, computed in float. */
static int has_f32(const NoiseFunction *f) { return f->kind == K_PERM3 || f->kind == K_GRAD2; }

/* The first point of a float32 block the double path would refuse (n if
 * none): a coordinate that is not finite, or f |c| >= 2^52 - the same rule
 * as nl_noise_points_refused, so both dtypes refuse the same points. */
static size_t refused_f32(const float *x, const float *y, const float *z, size_t n, double f)
{
  const double lim = 4503599627370496.0;   /* 2^52 */
  for (size_t k = 0; k < n; k++) {
    double a = x[k], b = y[k], c = z ? z[k] : 0.0;
    if (!(fabs(a) * f < lim && fabs(b) * f < lim && fabs(c) * f < lim)) return k;
  }
  return n;
}

static size_t run_f32(const NoiseFunction *f, const float *x, const float *y, const float *z,
                      size_t n, float *out)
{
  size_t k = refused_f32(x, y, z, n, f->fmax);
  if (f->kind == K_GRAD2)
    nl_noise_grad2_points_f32(f->grad2, x, y, k, out);
  else if (f->has_sum)
    nl_noise_perm3_fractal_points_f32(&f->b->perm3, &f->oct, x, y, z, k, out);
  else
    nl_noise_perm3_points_f32(&f->b->perm3, x, y, z, k, out);
  return k;
}

/* points(f, x, y, z, out[, threads]): f's noise at the points of the
 * contiguous float64 arrays x, y, z (None for planar noises) into out,
 * which overlaps none of them (noise.py buffers an overlap). Returns the
 * flat index of the first refused point (out.size if none); out[0 .. k)
 * holds values. points_f32(f, x, y, z, out): the same over float32 arrays
 * through the float32 kernels (f must have them: has_f32). */
static PyObject *points_call(PyObject *const *args, Py_ssize_t nargs, int f32)
{
  if ((nargs != 5 && (f32 || nargs != 6)) || !PyObject_TypeCheck(args[0], &NoiseFunctionType)) {
    PyErr_SetString(PyExc_TypeError, f32 ? "points_f32(f, x, y, z, out)"
                                         : "points(f, x, y, z, out[, threads])");
    return NULL;
  }
  int nthreads = 1;
  if (nargs == 6 && (nthreads = _PyLong_AsInt(args[5])) == -1 && PyErr_Occurred())
    return NULL;
  const NoiseFunction *f = (const NoiseFunction *)args[0];
  if (f32 && !has_f32(f)) {
    PyErr_SetString(PyExc_ValueError, "points_f32: this noise has no float32 kernel");
    return NULL;
  }
  if (!PyArray_Check(args[4])) {
    PyErr_SetString(PyExc_ValueError, "out: expected a numpy array");
    return NULL;
  }
  int type = f32 ? NPY_FLOAT : NPY_DOUBLE;
  size_t n = (size_t)PyArray_SIZE((PyArrayObject *)args[4]);
  char *out = array_of(args[4], n, "out", 1, type);
  const char *x = out ? array_of(args[1], n, "x", 0, type) : NULL;
  const char *y = x ? array_of(args[2], n, "y", 0, type) : NULL;
  const char *z = NULL;
  if (!y)
    return NULL;
  if (!f->planar && !(z = array_of(args[3], n, "z", 0, type)))
    return NULL;
  /* threads split a block when it is above the library's size threshold
   * (2^17 samples): a threaded call's blocks are THREADED_BLOCKS times as
   * large (each nl_parallel_for starts its threads), still a few
   * milliseconds between checks for signals */
  size_t block = block_points(f), done = 0, sz = f32 ? sizeof(float) : sizeof(double);
  if (nthreads > 1 && (f->kind == K_PERM3 || f->kind == K_GRAD2))
    block *= THREADED_BLOCKS;
  while (done < n) {
    size_t m = n - done < block ? n - done : block, k, at = done * sz;
    Py_BEGIN_ALLOW_THREADS
    if (f32)
      k = run_f32(f, (const float *)(x + at), (const float *)(y + at),
                  z ? (const float *)(z + at) : NULL, m, (float *)(out + at));
    else
      k = run(f, (const double *)(x + at), (const double *)(y + at),
              z ? (const double *)(z + at) : NULL, m, (double *)(out + at), nthreads);
    Py_END_ALLOW_THREADS
    done += k;
    if (k < m)
      break;
    if (done < n && PyErr_CheckSignals())
      return NULL;
  }
  return PyLong_FromSize_t(done);
}

static PyObject *ext_points(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
  (void)mod;
  return points_call(args, nargs, 0);
}

static PyObject *ext_points_f32(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
  (void)mod;
  return points_call(args, nargs, 1);
}

/* grid(noise_basis, octaves, x0, y0, z, size, w, h, marble, omega, a, block, out):
 * the window {x0, y0, z, size, w, h} of nl_noise_fractal_grid over the basis
 * and octaves at those addresses (the caller keeps them alive) into the
 * C-contiguous float64 out of h x w; marble: then nl_texture_marble_grid's
 * stripes, omega and a as its. The bits of those calls: the same rows, each
 * nl_noise_fractal_row at x0 + dx/2, y0 + (r + 1/2) dy. A block is as many
 * rows as hold about block samples times octaves (at least one row). */
/* A block of rows runs on threads when it holds at least twice the
 * one-thread block's samples (pixels x octaves): for the SIMD bases 2^17,
 * the library's own threshold for its threaded calls (nl_noise.h,
 * "threads"); the slower bases' blocks are smaller in proportion. */
typedef struct {
  const nl_noise_basis *b;
  const nl_noise_octaves *o;
  const nl_noise_window *win;
  double dx, dy;
  int marble;
  double omega, a;
  double *out, *scratch;
  size_t w, r0;
} grid_job;

/* Row r0 + i of the window, with thread t's scratch (no GIL). */
static void grid_row(void *ctx, size_t i, int t)
{
  const grid_job *j = ctx;
  size_t r = j->r0 + i;
  double y = j->win->y0 + ((int)r + 0.5) * j->dy, *row = j->out + r * j->w;
  nl_noise_fractal_row(j->b, j->o, j->win->x0 + 0.5 * j->dx, j->dx, y, j->win->z, j->w, row,
                       j->scratch + (size_t)t * j->w);
  if (j->marble)
    for (size_t c = 0; c < j->w; c++)
      row[c] = nl_texture_marble(j->omega * y, j->omega * j->a, row[c]);
}

static PyObject *ext_grid(PyObject *mod, PyObject *args)
{
  (void)mod;
  PyObject *pb, *po, *pout;
  nl_noise_window win;
  int marble, nthreads = 1;
  double omega, a;
  Py_ssize_t block;
  if (!PyArg_ParseTuple(args, "OOddddiipddnO|i", &pb, &po, &win.x0, &win.y0, &win.z, &win.size,
                        &win.w, &win.h, &marble, &omega, &a, &block, &pout, &nthreads))
    return NULL;
  const nl_noise_basis *b = address(pb);
  const nl_noise_octaves *o = address(po);
  if (PyErr_Occurred())
    return NULL;
  if (!b || !o || win.w < 1 || win.h < 1) {
    PyErr_SetString(PyExc_ValueError, "grid: no basis, no octaves or an empty window");
    return NULL;
  }
  size_t w = (size_t)win.w, h = (size_t)win.h;
  double *out = (double *)data_of(pout, w * h, "out", 1);
  if (!out)
    return NULL;
  if (nthreads < 1)
    nthreads = 1;
  int nt = nl_parallel_threads((size_t)-1, nthreads);
  double *scratch = malloc((size_t)nt * w * sizeof *scratch);
  if (!scratch)
    return PyErr_NoMemory();
  size_t oct = o->n > 1 ? (size_t)o->n : 1, work = w * oct;
  /* a block's rows are the items of one nl_parallel_for: each row is made
   * as on one thread (its own slot, its thread's scratch), so the bytes do
   * not depend on the thread count */
  size_t rows = block < 1 || work >= (size_t)block ? 1 : (size_t)block / work;
  if (nt > 1 && block > 0 && rows * work < THREADED_BLOCKS * (size_t)block)
    rows = (THREADED_BLOCKS * (size_t)block + work - 1) / work;
  grid_job j = {b, o, &win, win.size / win.w, win.size / win.h, marble, omega, a, out, scratch, w, 0};
  for (size_t r0 = 0; r0 < h; r0 += rows) {
    size_t r1 = r0 + rows < h ? r0 + rows : h;
    j.r0 = r0;
    Py_BEGIN_ALLOW_THREADS
    nl_parallel_for(r1 - r0, r1 - r0 > 1 && work * (r1 - r0) >= 2 * (size_t)block ? nthreads : 1,
                    grid_row, &j);
    Py_END_ALLOW_THREADS
    if (r1 < h && PyErr_CheckSignals()) {
      free(scratch);
      return NULL;
    }
  }
  free(scratch);
  Py_RETURN_NONE;
}

/* has_f32(f): whether points_f32 takes f. */
static PyObject *ext_has_f32(PyObject *mod, PyObject *arg)
{
  (void)mod;
  if (!PyObject_TypeCheck(arg, &NoiseFunctionType)) {
    PyErr_SetString(PyExc_TypeError, "has_f32(f): f must be a NoiseFunction");
    return NULL;
  }
  return PyBool_FromLong(has_f32((const NoiseFunction *)arg));
}

/* bases(): the library's registry of bases (nl_basis_kinds), as
 * (name, name under a sum, planar) triples, so that noise.py lists none. */
static PyObject *ext_bases(PyObject *mod, PyObject *unused)
{
  (void)mod;
  (void)unused;
  size_t n;
  const nl_basis_kind *k = nl_basis_kinds(&n);
  PyObject *t = PyTuple_New((Py_ssize_t)n);
  for (size_t i = 0; t && i < n; i++) {
    PyObject *e = Py_BuildValue("(ssO)", k[i].name, k[i].under,
                                (k[i].reads & NL_BASIS_PLANAR) ? Py_True : Py_False);
    if (!e) {
      Py_CLEAR(t);
      break;
    }
    PyTuple_SET_ITEM(t, (Py_ssize_t)i, e);
  }
  return t;
}

static PyMethodDef ext_methods[] = {
  {"points", (PyCFunction)(void (*)(void))ext_points, METH_FASTCALL,
   "points(f, x, y, z, out[, threads]) -> index of the first refused point (out.size if none)"},
  {"points_f32", (PyCFunction)(void (*)(void))ext_points_f32, METH_FASTCALL,
   "points_f32(f, x, y, z, out) -> as points, over float32 arrays (float32 kernels)"},
  {"has_f32", ext_has_f32, METH_O, "has_f32(f) -> whether f has float32 kernels"},
  {"bases", ext_bases, METH_NOARGS, "bases() -> ((name, under, planar), ...)"},
  {"grid", ext_grid, METH_VARARGS,
   "grid(noise_basis, octaves, x0, y0, z, size, w, h, marble, omega, a, block, out[, threads])"},
  {NULL, NULL, 0, NULL}
};

static struct PyModuleDef ext_module = {
  PyModuleDef_HEAD_INIT, "_ext", "noiselab's noise calls as a CPython extension (_ext.c)", -1,
  ext_methods, NULL, NULL, NULL, NULL
};

PyMODINIT_FUNC PyInit__ext(void)
{
  PyObject *m;
  import_array();
  if (PyType_Ready(&NoiseFunctionType) < 0)
    return NULL;
  m = PyModule_Create(&ext_module);
  if (!m)
    return NULL;
  Py_INCREF(&NoiseFunctionType);
  if (PyModule_AddObject(m, "NoiseFunction", (PyObject *)&NoiseFunctionType) < 0) {
    Py_DECREF(&NoiseFunctionType);
    Py_DECREF(m);
    return NULL;
  }
  return m;
}
