#include "wavelet/nl_wavelet.h"
#include "noise/nl_noise_lattice.h"   /* nl_noise_lmod: tile indices wrap into [0, n) */
#include "simd/nl_simd.h"
#include "wavelet/nl_wavelet_simd.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Cook & DeRose's analysis (downsampling) filter, appendix: 16 printed
 * values, mirrored. Centred so that tap j in [-16, 15] is A[j + 16]. */
static const double A_HALF[16] = {
  0.000334, -0.001528, 0.000410, 0.003545, -0.000938, -0.008233, 0.002172, 0.019120,
  -0.005040, -0.044412, 0.011655, 0.103311, -0.025936, -0.243780, 0.033979, 0.655340};
#define ARAD 16

static double afilter(int j)   /* j in [-ARAD, ARAD) */
{
  int k = j + ARAD;
  return k < ARAD ? A_HALF[k] : A_HALF[2 * ARAD - 1 - k];
}

nl_wavelet_tile *nl_wavelet_tile_alloc(int dim, int n)
{
  if ((dim != 2 && dim != 3) || n < 8 || n % 2 || n > (dim == 2 ? 8192 : 512)) return NULL;
  nl_wavelet_tile *t = nl_xmalloc(sizeof *t);
  t->dim = dim;
  t->n = n;
  size_t total = (size_t)n * n * (dim == 3 ? (size_t)n : 1);
  t->data = nl_xcalloc(total, sizeof *t->data);
  return t;
}

void nl_wavelet_tile_free(nl_wavelet_tile *t)
{
  if (!t) return;
  free(t->data);
  free(t);
}

void nl_wavelet_coarse_line(const float *line, size_t stride, int n, double *coarse)
{
  /* Downsample: the appendix's loop is k <= 2i + ARAD, one tap too many;
   * the filter has taps -ARAD .. ARAD-1. */
  int h = n / 2;
  double down[4096];
  for (int i = 0; i < h; i++) {
    double s = 0;
    for (int k = 2 * i - ARAD; k < 2 * i + ARAD; k++)
      s += afilter(k - 2 * i) * line[(size_t)nl_noise_lmod(k, n) * stride];
    down[i] = s;
  }
  /* Upsample with {1/4, 3/4, 3/4, 1/4} centred at 2: p[i - 2k]. */
  static const double P[4] = {0.25, 0.75, 0.75, 0.25};
  for (int i = 0; i < n; i++) {
    double s = 0;
    for (int k = i / 2; k <= i / 2 + 1; k++) s += P[i - 2 * k + 2] * down[nl_noise_lmod(k, h)];
    coarse[i] = s;
  }
}

/* Replaces every line along one axis of `a` by its coarse part. */
static void coarse_axis(float *a, int n, int dim, int axis)
{
  size_t stride = axis == 0 ? 1 : axis == 1 ? (size_t)n : (size_t)n * n;
  size_t lines = dim == 2 ? (size_t)n : (size_t)n * n;
  double *c = nl_xmalloc((size_t)n * sizeof *c);
  for (size_t l = 0; l < lines; l++) {
    /* Line l starts at the l-th index with the axis coordinate zero. */
    size_t lo = l % stride, hi = l / stride;
    float *line = a + lo + hi * stride * n;
    nl_wavelet_coarse_line(line, stride, n, c);
    for (int i = 0; i < n; i++) line[(size_t)i * stride] = (float)c[i];
  }
  free(c);
}

/* Steps 1-4; `transposed` copies the appendix's odd-shift loop literally
 * (temp[ix n^2 + iy n + iz] = noise[(ix+o) + (iy+o) n + (iz+o) n^2]: the copy
 * is the shifted tile with x and z exchanged). */
static void tile_seed(nl_wavelet_tile *t, unsigned long seed, int transposed)
{
  int n = t->n, d = t->dim;
  size_t total = (size_t)n * n * (d == 3 ? (size_t)n : 1);
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(seed, "wavelet.tile", 0));
  for (size_t i = 0; i < total; i++) t->data[i] = (float)gsl_ran_gaussian_ziggurat(rng, 1.0);
  gsl_rng_free(rng);

  /* Steps 2-3: coarse = (UD)_z (UD)_y (UD)_x noise; keep noise - coarse. */
  float *coarse = nl_xmalloc(total * sizeof *coarse);
  memcpy(coarse, t->data, total * sizeof *coarse);
  for (int axis = 0; axis < d; axis++) coarse_axis(coarse, n, d, axis);
  for (size_t i = 0; i < total; i++) t->data[i] -= coarse[i];

  /* Step 4: add the copy shifted by an odd offset along every axis. */
  long off = n / 2;
  if (off % 2 == 0) off++;
  float *shifted = coarse;
  for (size_t i = 0; i < total; i++) {
    long x = (long)(i % n), y = (long)((i / n) % n), z = d == 3 ? (long)(i / ((size_t)n * n)) : 0;
    if (transposed) { long tmp = x; x = d == 3 ? z : y; if (d == 3) z = tmp; else y = tmp; }
    size_t j = (size_t)nl_noise_lmod(x + off, n) + (size_t)nl_noise_lmod(y + off, n) * n
             + (d == 3 ? (size_t)nl_noise_lmod(z + off, n) * n * n : 0);
    shifted[i] = t->data[j];
  }
  for (size_t i = 0; i < total; i++) t->data[i] += shifted[i];
  free(coarse);
}

void nl_wavelet_tile_seed(nl_wavelet_tile *t, unsigned long seed) { tile_seed(t, seed, 0); }
void nl_wavelet_tile_seed_transposed(nl_wavelet_tile *t, unsigned long seed) { tile_seed(t, seed, 1); }

/* Quadratic B-spline weights and first lattice index along one axis. */
static long bspline(double p, double w[3])
{
  double mid = ceil(p - 0.5), t = mid - (p - 0.5);
  w[0] = t * t / 2;
  w[2] = (1 - t) * (1 - t) / 2;
  w[1] = 1 - w[0] - w[2];
  /* A long holds mid only below 2^63: wrap beyond 2^62 (no undefined
   * conversion; the taps there are meaningless anyway), 0 for NaN/inf. */
  long m = fabs(mid) < 0x1p62 ? (long)mid : isfinite(mid) ? (long)fmod(mid, 0x1p62) : 0;
  return m - 1;
}

/* The tile collapsed across y (and z) at a fixed point: column c of the
 * result is sum_z wz sum_y wy tile[z][y][c]. Point and row evaluation both
 * go through it, so they agree bit for bit. */
typedef struct { const float *rows[9]; double wt[9]; int nrows; } collapse;

static void collapse_init(const nl_wavelet_tile *t, double y, double z, collapse *c)
{
  int n = t->n;
  double wy[3], wz[3] = {1, 0, 0};
  long y0 = bspline(y, wy), z0 = t->dim == 3 ? bspline(z, wz) : 0;
  c->nrows = 0;
  for (int jz = 0; jz < (t->dim == 3 ? 3 : 1); jz++)
    for (int jy = 0; jy < 3; jy++) {
      size_t base = (size_t)nl_noise_lmod(y0 + jy, n) * n
                  + (t->dim == 3 ? (size_t)nl_noise_lmod(z0 + jz, n) * n * n : 0);
      c->rows[c->nrows] = t->data + base;
      c->wt[c->nrows++] = t->dim == 3 ? wz[jz] * wy[jy] : wy[jy];
    }
}

static double collapse_column(const collapse *c, long col)
{
  double s = 0;
  for (int r = 0; r < c->nrows; r++) s += c->wt[r] * c->rows[r][col];
  return s;
}

static double eval_point(const nl_wavelet_tile *t, double x, double y, double z)
{
  collapse c;
  collapse_init(t, y, z, &c);
  double wx[3];
  long x0 = bspline(x, wx);
  double s = 0;
  for (int j = 0; j < 3; j++) s += wx[j] * collapse_column(&c, nl_noise_lmod(x0 + j, t->n));
  return s;
}

double nl_wavelet_eval2(const nl_wavelet_tile *t, double x, double y) { return eval_point(t, x, y, 0); }
double nl_wavelet_eval3(const nl_wavelet_tile *t, double x, double y, double z) { return eval_point(t, x, y, z); }

void nl_wavelet_points(const nl_wavelet_tile *t, const double *x, const double *y, const double *z,
                       size_t n, double *out)
{
  for (size_t k = 0; k < n; k++) out[k] = eval_point(t, x[k], y[k], t->dim == 3 ? z[k] : 0);
}

/* nl_wavelet_row's sample loop on the dispatched level (nl_wavelet_simd.h)
 * over the period line[0 .. n - 1] repeated: GSL_SUCCESS, or GSL_CONTINUE
 * (nothing done) on the scalar level, for sparse rows (more than two
 * columns a sample) and beyond |x| < 2^51: then the caller's loop runs. */
#define SIMD_STACK_COLS 1056   /* doubles; a multiple of 8 */
#define SIMD_MAX_N ((size_t)1 << 29)   /* column indices stay ints */
static int simd_row(const double *line, long n, double x0, double dx, size_t count, double weight,
                    double *out)
{
  nl_wavelet_simd_row_fn row;
  switch (nl_simd_get()) {
#if NL_SIMD_X86
  case NL_SIMD_SSE2: row = nl_wavelet_simd_sse2; break;
  case NL_SIMD_AVX2: row = nl_wavelet_simd_avx2; break;
  case NL_SIMD_AVX512: row = nl_wavelet_simd_avx512; break;
#endif
  default: return GSL_CONTINUE;
  }
  if (count == 0 || count > SIMD_MAX_N || n < 1) return GSL_CONTINUE;
  double xl = x0 + (double)(count - 1) * dx;
  if (!(fabs(x0) < 0x1p51 && fabs(xl) < 0x1p51)) return GSL_CONTINUE;
  /* the first taps (bspline's mid - 1) of the lowest and the highest sample */
  double lo = dx >= 0 ? x0 : xl, hi = dx >= 0 ? xl : x0;
  long a = (long)ceil(lo - 0.5) - 1, b = (long)ceil(hi - 0.5) - 1;
  size_t ncol = (size_t)(b - a) + 3;
  if (ncol > 2 * count + 8) return GSL_CONTINUE;   /* sparse: the caller's loop */
  size_t len = (ncol + 7) / 8 * 8 + NL_WAVELET_SIMD_PAD;
  double sL[SIMD_STACK_COLS];
  double *L = len <= SIMD_STACK_COLS ? sL : nl_xmalloc(len * sizeof *L);
  memset(L + ncol, 0, (len - ncol) * sizeof *L);
  for (size_t c = 0; c < ncol; c++) L[c] = line[nl_noise_lmod(a + (long)c, n)];
  row(L, a, x0, dx, count, weight, out);
  if (L != sL) free(L);
  return GSL_SUCCESS;
}

void nl_wavelet_row(const nl_wavelet_tile *t, double x0, double dx, double y, double z,
                    size_t count, double weight, double *out)
{
  int n = t->n;
  collapse c;
  collapse_init(t, y, z, &c);
  /* Collapse the whole period once, plus two wrapped columns so that the
   * three taps at i, i+1, i+2 never need a modulo. */
  double *line = nl_xmalloc((size_t)(n + 2) * sizeof *line);
  for (int i = 0; i < n; i++) line[i] = collapse_column(&c, i);
  line[n] = line[0];
  line[n + 1] = line[1];
  /* The sample loop on the library's vector level, same bits; else below. */
  if (simd_row(line, n, x0, dx, count, weight, out) == GSL_SUCCESS) {
    free(line);
    return;
  }
  for (size_t k = 0; k < count; k++) {
    double wx[3];
    long i = nl_noise_lmod(bspline(x0 + (double)k * dx, wx), n);
    out[k] += weight * (wx[0] * line[i] + wx[1] * line[i + 1] + wx[2] * line[i + 2]);
  }
  free(line);
}

double nl_wavelet_tile_variance(const nl_wavelet_tile *t, int per_unit)
{
  int m = t->n * per_unit;
  double d = 1.0 / per_unit, sum = 0;
  double *row = nl_xmalloc((size_t)m * sizeof *row);
  int planes = t->dim == 3 ? m : 1;
  for (int iz = 0; iz < planes; iz++)
    for (int iy = 0; iy < m; iy++) {
      memset(row, 0, (size_t)m * sizeof *row);
      nl_wavelet_row(t, 0.5 * d, d, (iy + 0.5) * d, (iz + 0.5) * d, (size_t)m, 1.0, row);
      for (int ix = 0; ix < m; ix++) sum += row[ix] * row[ix];
    }
  free(row);
  return sum / ((double)m * m * planes);
}

double nl_wavelet_slice_variance(const nl_wavelet_tile *t, double z, int per_unit, double *mean)
{
  int m = t->n * per_unit;
  double d = 1.0 / per_unit, sum = 0, s1 = 0;
  double *row = nl_xmalloc((size_t)m * sizeof *row);
  for (int iy = 0; iy < m; iy++) {
    memset(row, 0, (size_t)m * sizeof *row);
    nl_wavelet_row(t, 0.5 * d, d, (iy + 0.5) * d, z, (size_t)m, 1.0, row);
    for (int ix = 0; ix < m; ix++) { sum += row[ix] * row[ix]; s1 += row[ix]; }
  }
  free(row);
  if (mean) *mean = s1 / ((double)m * m);
  return sum / ((double)m * m);
}

double nl_wavelet_point_variance(const nl_wavelet_tile *t, size_t count, unsigned long seed)
{
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(seed, "wavelet.points", 0));
  double sum = 0;
  for (size_t k = 0; k < count; k++) {
    double x = t->n * gsl_rng_uniform(rng), y = t->n * gsl_rng_uniform(rng), z = t->n * gsl_rng_uniform(rng);
    double v = eval_point(t, x, y, t->dim == 3 ? z : 0);
    sum += v * v;
  }
  gsl_rng_free(rng);
  return sum / (double)count;
}

double nl_wavelet_multiband_variance(const nl_wavelet_tile *t, int nbands, double z, int per_unit)
{
  /* Cook & DeRose's WMultibandNoise with w = 1: sum_b N(2^-b p), one tile, no offsets. */
  int m = t->n * per_unit;
  double d = 1.0 / per_unit, sum = 0;
  double *row = nl_xmalloc((size_t)m * sizeof *row);
  for (int iy = 0; iy < m; iy++) {
    memset(row, 0, (size_t)m * sizeof *row);
    for (int b = 0; b < nbands; b++) {
      double s = ldexp(1.0, -b);
      nl_wavelet_row(t, 0.5 * d * s, d * s, (iy + 0.5) * d * s, z * s, (size_t)m, 1.0, row);
    }
    for (int ix = 0; ix < m; ix++) sum += row[ix] * row[ix];
  }
  free(row);
  return sum / ((double)m * m * nbands);
}

double nl_wavelet_lattice_variance(const nl_wavelet_tile *t, double frac)
{
  int n = t->n, planes = t->dim == 3 ? n : 1;
  double *row = nl_xmalloc((size_t)n * sizeof *row), sum = 0;
  for (int iz = 0; iz < planes; iz++)
    for (int iy = 0; iy < n; iy++) {
      memset(row, 0, (size_t)n * sizeof *row);
      nl_wavelet_row(t, frac, 1.0, iy + frac, iz + frac, (size_t)n, 1.0, row);
      for (int ix = 0; ix < n; ix++) sum += row[ix] * row[ix];
    }
  free(row);
  return sum / ((double)n * n * planes);
}

nl_status nl_wavelet_bands_init(nl_wavelet_bands *b, int nbands, const double *w,
                                int n, unsigned long seed, nl_error *err)
{
  if (nbands < 1 || nbands > NL_WAVELET_MAX_BANDS)
    return nl_fail(err, NL_EINVAL, "band count %d outside 1..%d", nbands, NL_WAVELET_MAX_BANDS);
  memset(b, 0, sizeof *b);
  b->nbands = nbands;
  /* A stream of its own, so that offsets do not repeat the tile's values. */
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(seed, "wavelet.offsets", 0));
  for (int k = 0; k < nbands; k++) {
    b->w[k] = w ? w[k] : 1.0;
    for (int a = 0; a < 3; a++) b->off[k][a] = n * gsl_rng_uniform(rng);
  }
  gsl_rng_free(rng);
  return NL_OK;
}

void nl_wavelet_bands_grid(const nl_wavelet_tile *t, const nl_wavelet_bands *b, int w, int h,
                           double z, double scale, double *out)
{
  memset(out, 0, (size_t)w * h * sizeof *out);
  for (int y = 0; y < h; y++)
    for (int k = 0; k < b->nbands; k++) {
      if (b->w[k] == 0) continue;
      double s = scale * ldexp(1.0, -k);
      nl_wavelet_row(t, 0.5 * s + b->off[k][0], s, (y + 0.5) * s + b->off[k][1],
                     z * s + b->off[k][2], (size_t)w, b->w[k], out + (size_t)y * w);
    }
}

static void wavelet_basis_row(const void *ctx, double x0, double dx, double y, double z,
                              size_t n, double *out)
{
  for (size_t k = 0; k < n; k++) out[k] = 0;
  nl_wavelet_row(ctx, x0, dx, y, z, n, 1.0, out);
}

nl_noise_basis nl_wavelet_basis(const nl_wavelet_tile *t)
{
  size_t n = (size_t)t->n * t->n * (t->dim == 3 ? (size_t)t->n : 1);
  double m = 0;
  /* fmax's value (a NaN is skipped) written as a comparison: aarch64 gcc 12
   * stops with an internal error vectorizing the fmax reduction. */
  for (size_t k = 0; k < n; k++) {
    double a = fabs(t->data[k]);
    if (a > m) m = a;
  }
  nl_noise_basis b = {wavelet_basis_row, t, m};
  return b;
}
