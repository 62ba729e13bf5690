/* The threaded grids and checked batches (nl_noise.h, "threads") give the
 * bytes of one thread for 1, 2 and 3 threads: fBm and turbulence grids
 * over both noises, batches of points, sums over them, and batches with a
 * refused point in a later chunk, whose return value and out layout
 * (values before it, out[k1 ..) untouched) must be one thread's. Sizes are
 * above the threshold where the calls start threads. */
#include "noise/nl_noise.h"
#include "nl_test.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const int THREADS[] = {1, 2, 3};

/* 600 x 700 pixels, 6 octaves: 2.5 M samples, well above the threshold. */
static void grid_same(const nl_noise_basis *b, const nl_noise_octaves *o)
{
  nl_noise_window win = {-3.25, 1.5, 0.5, 8.0, 600, 700};
  size_t n = (size_t)win.w * (size_t)win.h;
  double *one = malloc(n * sizeof *one), *v = malloc(n * sizeof *v);
  nl_noise_fractal_grid(b, o, &win, one);
  for (size_t i = 0; i < sizeof THREADS / sizeof *THREADS; i++) {
    memset(v, 0xff, n * sizeof *v);
    nl_noise_fractal_grid_threads(b, o, &win, THREADS[i], v);
    NL_CHECK(memcmp(one, v, n * sizeof *v) == 0);
  }
  free(one);
  free(v);
}

NL_TEST(grid_threads_same_bytes)
{
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  nl_noise_grad2 *t = nl_noise_grad2_alloc(512);
  nl_noise_grad2_seed(t, 3);
  nl_noise_basis b3 = nl_noise_basis_perm3(&p), b2 = nl_noise_basis_grad2(t);
  nl_noise_octaves fbm = nl_noise_octaves_fbm(6, 0.5, 2.0), turb = nl_noise_octaves_fractal(6);
  turb.turbulence = 1;
  grid_same(&b3, &fbm);
  grid_same(&b2, &fbm);
  grid_same(&b3, &turb);
  nl_noise_grad2_free(t);
}

enum { NPTS = 300007 };   /* above the threshold; not a multiple of a block: a short last chunk */

static double *coords(gsl_rng *r, size_t n)
{
  double *c = malloc(n * sizeof *c);
  for (size_t k = 0; k < n; k++) c[k] = 600 * gsl_rng_uniform(r) - 300;
  return c;
}

/* One thread's call and the threaded one on the same input, from outputs
 * filled with the same pattern: the same return and the same bytes,
 * untouched ones included. */
static void checked_same(const nl_noise_perm3 *p, const nl_noise_grad2 *t,
                         const nl_noise_octaves *o, const double *x, const double *y,
                         const double *z, size_t n, size_t want)
{
  double *one = malloc(n * sizeof *one), *v = malloc(n * sizeof *v);
  memset(one, 0x5a, n * sizeof *one);
  size_t k1 = t ? nl_noise_grad2_points_checked(t, x, y, n, one)
                : nl_noise_perm3_points_checked(p, o, x, y, z, n, one);
  NL_CHECK(k1 == want);
  for (size_t i = 0; i < sizeof THREADS / sizeof *THREADS; i++) {
    memset(v, 0x5a, n * sizeof *v);
    size_t k = t ? nl_noise_grad2_points_checked_threads(t, x, y, n, v, THREADS[i])
                 : nl_noise_perm3_points_checked_threads(p, o, x, y, z, n, v, THREADS[i]);
    NL_CHECK(k == want);
    /* out[k .. k1) holds values of no meaning: compared around them */
    size_t end = want == n ? n : (want / NL_NOISE_CHECK_BLOCK + 1) * NL_NOISE_CHECK_BLOCK;
    if (end > n) end = n;
    NL_CHECK(memcmp(one, v, want * sizeof *v) == 0);
    NL_CHECK(memcmp(one + end, v + end, (n - end) * sizeof *v) == 0);
    if (end < n) {   /* untouched: still the fill pattern */
      unsigned char fill[sizeof(double)];
      memset(fill, 0x5a, sizeof fill);
      NL_CHECK(memcmp(v + end, fill, sizeof fill) == 0 && memcmp(v + n - 1, fill, sizeof fill) == 0);
    }
  }
  free(one);
  free(v);
}

NL_TEST(checked_threads_same_bytes)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 50);
  double *x = coords(r, NPTS), *y = coords(r, NPTS), *z = coords(r, NPTS);
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 9);
  nl_noise_grad2 *t = nl_noise_grad2_alloc(256);
  nl_noise_grad2_seed(t, 4);
  nl_noise_octaves fbm = nl_noise_octaves_fbm(4, 0.5, 2.0);
  checked_same(&p, NULL, NULL, x, y, z, NPTS, NPTS);
  checked_same(&p, NULL, &fbm, x, y, z, NPTS, NPTS);
  checked_same(NULL, t, NULL, x, y, NULL, NPTS, NPTS);
  /* a refused point deep in the batch (a later chunk), then an earlier one
   * as well: the first counts, the later chunks write nothing */
  size_t late = 250001, early = 9000;
  double keep = y[late];
  y[late] = NAN;
  checked_same(&p, NULL, NULL, x, y, z, NPTS, late);
  checked_same(&p, NULL, &fbm, x, y, z, NPTS, late);
  checked_same(NULL, t, NULL, x, y, NULL, NPTS, late);
  z[early] = 0x1p53;   /* beyond 2^52: refused by the 3D batches only */
  checked_same(&p, NULL, NULL, x, y, z, NPTS, early);
  checked_same(NULL, t, NULL, x, y, NULL, NPTS, late);
  /* a point refused by the finest octave only (f |c| >= 2^52) */
  z[early] = 0x1p52 / 4;
  checked_same(&p, NULL, NULL, x, y, z, NPTS, late);
  checked_same(&p, NULL, &fbm, x, y, z, NPTS, early);
  y[late] = keep;
  free(x);
  free(y);
  free(z);
  nl_noise_grad2_free(t);
  gsl_rng_free(r);
}

int main(void) { return nl_test_run(); }
