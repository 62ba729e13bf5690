/* test_noise_f32.c - the float32 path (nl_noise.h, "float32 path").
 *
 * 1. Every level gives the scalar level's bits: point batches, rows (dense,
 *    sparse, backwards, across 0 and multiples of 256, far from 0) and
 *    sums of octaves over both, of the improved noise and of the 2D noise
 *    (m = 512, 16 and 2^16), at random coordinates of which half are
 *    awkward (lattice points, ulps off them, tiny of either sign, near
 *    multiples of 256, far from 0, up to FLT_MAX), and a row gives the
 *    bits of its points. NaN compares as NaN.
 * 2. Accuracy: at F32_POINTS (2^18) random float points of [-300, 300]^3,
 *    half of them awkward, the float noise against the double noise at the
 *    same point and against Perlin's reference code; and at points spread
 *    over every magnitude up to 2^40 (the bound holds for every finite
 *    float). The tolerance F32_TOL is stated from the measured bound below.
 */
#include "noise/nl_noise.h"
#include "nl_test.h"
#include "reference/perlin_improved_noise.h"

#include <float.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define F32_POINTS (1 << 18)

/* Measured max |f32 - double| at the same point: 8.7e-7 (improved 3D)
 * and 8.4e-7 (2D, m = 512) over the 2^18 points of [-300, 300]^3 below,
 * 1.1e-6 over the 2^18 of every magnitude (9 ulps of 1), and 8.6e-7 to
 * 9.6e-7 in four runs of 2^22 uniform points: a dozen float roundings of
 * values up to about 4 (the column lines A_c and the blend's differences),
 * each within 2.4e-7, mostly cancelling. Random points do not find the
 * worst case, so the tolerance is the largest measured times 1.8. */
#define F32_TOL 2e-6

static float coord(gsl_rng *r, double span)
{
  double u = gsl_rng_uniform(r);
  if (u < 0.5) return (float)(span * (2 * gsl_rng_uniform(r) - 1));
  long n = (long)gsl_rng_uniform_int(r, 601) - 300;
  float s = gsl_rng_uniform(r) < 0.5 ? -1.0f : 1.0f;
  if (u < 0.6) return (float)n;                                  /* lattice point */
  if (u < 0.65) return (float)n + 0.5f;                          /* half-integer */
  if (u < 0.75) return nextafterf((float)n, s * INFINITY);       /* an ulp off a lattice point */
  if (u < 0.85) {   /* tiny: 2^-149 .. 2^-1, a third of them in [-2^-25, 0) */
    if (gsl_rng_uniform(r) < 1.0 / 3)
      return -ldexpf(1 + (float)gsl_rng_uniform(r), -26 - (int)gsl_rng_uniform_int(r, 100));
    return s * ldexpf(1.0f, -1 - (int)gsl_rng_uniform_int(r, 149));
  }
  float m = 256.0f * (float)(n % 3);                             /* -512 .. 512 */
  float off[] = {0.0f, -0.0f, 1e-5f, 0.5f, 1.0f, (float)gsl_rng_uniform(r), 0x1p-15f};
  float o = off[gsl_rng_uniform_int(r, sizeof off / sizeof *off)];
  return gsl_rng_uniform(r) < 0.2 ? nextafterf(m, s * INFINITY) : m + s * o;
}

/* A coordinate of any magnitude 2^-30 .. 2^40, or (rarely) beyond. */
static float coord_far(gsl_rng *r)
{
  double u = gsl_rng_uniform(r), s = gsl_rng_uniform(r) < 0.5 ? -1 : 1;
  if (u < 0.01) return (float)s * FLT_MAX;
  if (u < 0.02) return (float)s * 0x1p31f;
  if (u < 0.03) return (float)s * (0x1p31f + 256.0f);
  return (float)(s * ldexp(1 + gsl_rng_uniform(r), (int)gsl_rng_uniform_int(r, 71) - 30));
}

/* bits equal, or both NaN */
static long differ(const float *a, const float *b, size_t n)
{
  long d = 0;
  for (size_t k = 0; k < n; k++)
    d += !(isnan(a[k]) && isnan(b[k])) && memcmp(a + k, b + k, sizeof *a) != 0;
  return d;
}

static size_t NP;   /* points in the batches of test 1 */
static float *px, *py, *pz;

static void make_points(void)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 2026);
  NP = F32_POINTS + 13;   /* not a multiple of a vector */
  px = malloc(NP * sizeof *px);
  py = malloc(NP * sizeof *py);
  pz = malloc(NP * sizeof *pz);
  for (size_t k = 0; k < NP; k++) {
    int far = k % 16 == 0;
    px[k] = far ? coord_far(r) : coord(r, 300);
    py[k] = far ? coord_far(r) : coord(r, 300);
    pz[k] = far ? coord_far(r) : coord(r, 300);
  }
  px[1] = NAN;
  py[2] = INFINITY;
  pz[3] = -INFINITY;
  gsl_rng_free(r);
}

/* Rows: (x0, dx, y, z) */
typedef struct { float x0, dx, y, z; } row_spec;
static const row_spec rows[] = {
  {0.5f / 64, 1.0f / 64, 3.3f, 0.5f}, {-3.7f, 0.7f, -1.25f, 7.5f}, {300.0f, -0.29f, 0.0f, -0.0f},
  {-100 * 0x1p-20f, 0x1p-20f, 2.5f, -255.5f}, {-256.0f - 100 * 0x1p-15f, 0x1p-15f, 255.99f, 256.0f},
  {-40.0f, 3.7f, 1e-30f, -1e-30f}, {0x1p31f - 2048, 128.0f, 1.5f, 2.5f}, {-0x1p24f, 1.0f, 0.25f, 0.75f},
  {12.0f, 13.0f / 7, -9.5f, 100.25f}, {5.0f, -1.0f / 64, 511.5f, -511.5f}, {1e9f, 1e3f, 3.0f, 4.0f},
  {-0.5f, 0x1p-26f, 0.5f, 0.5f}};
enum { NROWS = sizeof rows / sizeof *rows, ROWN = 1000 };

typedef struct {
  float *pts3, *pts2, *frac3, *frac2, *row3, *row2, *frow3, *frow2;
} outputs;

static nl_noise_octaves octs(int turbulence)
{
  nl_noise_octaves o = nl_noise_octaves_fbm(5, 0.5, 2.03);
  o.turbulence = turbulence;
  return o;
}

/* Every kernel at the level in use. */
static outputs run_all(const nl_noise_perm3 *p, const nl_noise_grad2 *t)
{
  outputs o;
  size_t nr = (size_t)NROWS * ROWN;
  float **all[] = {&o.pts3, &o.pts2, &o.frac3, &o.frac2, &o.row3, &o.row2, &o.frow3, &o.frow2};
  for (size_t k = 0; k < 4; k++) *all[k] = malloc(NP * sizeof(float));
  for (size_t k = 4; k < 8; k++) *all[k] = malloc(nr * sizeof(float));
  nl_noise_octaves fbm = octs(0), turb = octs(1);
  nl_noise_perm3_points_f32(p, px, py, pz, NP, o.pts3);
  nl_noise_grad2_points_f32(t, px, py, NP, o.pts2);
  nl_noise_perm3_fractal_points_f32(p, &fbm, px, py, pz, NP, o.frac3);
  nl_noise_grad2_fractal_points_f32(t, &turb, px, py, NP, o.frac2);
  for (int r = 0; r < NROWS; r++) {
    const row_spec *s = rows + r;
    size_t off = (size_t)r * ROWN, n = ROWN - (size_t)r;   /* lengths not multiples of a vector */
    nl_noise_perm3_row_f32(p, s->x0, s->dx, s->y, s->z, n, o.row3 + off);
    nl_noise_grad2_row_f32(t, s->x0, s->dx, s->y, n, o.row2 + off);
    nl_noise_perm3_fractal_row_f32(p, r % 2 ? &turb : &fbm, s->x0, s->dx, s->y, s->z, n, o.frow3 + off);
    nl_noise_grad2_fractal_row_f32(t, r % 2 ? &fbm : &turb, s->x0, s->dx, s->y, n, o.frow2 + off);
    for (size_t k = n; k < ROWN; k++) o.row3[off + k] = o.row2[off + k] = o.frow3[off + k] = o.frow2[off + k] = 0;
  }
  return o;
}

static void free_outputs(outputs *o)
{
  float *all[] = {o->pts3, o->pts2, o->frac3, o->frac2, o->row3, o->row2, o->frow3, o->frow2};
  for (size_t k = 0; k < 8; k++) free(all[k]);
}

/* A row gives the bits of its points x_k = fmaf(k, dx, x0). */
static long rows_vs_points(const nl_noise_perm3 *p, const nl_noise_grad2 *t, const outputs *o)
{
  long d = 0;
  float x[ROWN], y[ROWN], z[ROWN], v3[ROWN], v2[ROWN], f3[ROWN], f2[ROWN];
  nl_noise_octaves fbm = octs(0), turb = octs(1);
  for (int r = 0; r < NROWS; r++) {
    const row_spec *s = rows + r;
    size_t off = (size_t)r * ROWN, n = ROWN - (size_t)r;
    for (size_t k = 0; k < n; k++) {
      x[k] = fmaf((float)k, s->dx, s->x0);
      y[k] = s->y;
      z[k] = s->z;
    }
    nl_noise_perm3_points_f32(p, x, y, z, n, v3);
    nl_noise_grad2_points_f32(t, x, y, n, v2);
    nl_noise_perm3_fractal_points_f32(p, r % 2 ? &turb : &fbm, x, y, z, n, f3);
    nl_noise_grad2_fractal_points_f32(t, r % 2 ? &fbm : &turb, x, y, n, f2);
    d += differ(v3, o->row3 + off, n) + differ(v2, o->row2 + off, n) + differ(f3, o->frow3 + off, n) +
         differ(f2, o->frow2 + off, n);
  }
  return d;
}

static void levels_for_table(size_t m)
{
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 11 + m);
  nl_noise_grad2 *t = nl_noise_grad2_alloc(m);
  nl_noise_grad2_seed(t, 5 + m);
  if (!px) make_points();
  nl_noise_simd_set(NL_SIMD_SCALAR);
  outputs ref = run_all(&p, t);
  long d = rows_vs_points(&p, t, &ref);
  printf("  m = %zu, scalar: %ld row values differ from their points'\n", m, d);
  NL_CHECK(d == 0);
  size_t nr = (size_t)NROWS * ROWN;
  for (int l = NL_SIMD_SSE2; l <= NL_SIMD_AVX512; l++) {
    if (!nl_noise_simd_supported(l)) {
      nl_test_skip("the %s level: not compared, this CPU cannot run it", nl_noise_simd_name(l));
      continue;
    }
    nl_noise_simd_set(l);
    outputs o = run_all(&p, t);
    long dp = differ(o.pts3, ref.pts3, NP) + differ(o.pts2, ref.pts2, NP) + differ(o.frac3, ref.frac3, NP) +
              differ(o.frac2, ref.frac2, NP);
    long dr = differ(o.row3, ref.row3, nr) + differ(o.row2, ref.row2, nr) + differ(o.frow3, ref.frow3, nr) +
              differ(o.frow2, ref.frow2, nr);
    long dv = rows_vs_points(&p, t, &o);
    printf("  m = %zu, %-6s: %ld point values and %ld row values differ from the scalar level's, "
           "%ld rows from their points\n", m, nl_noise_simd_name(l), dp, dr, dv);
    NL_CHECK(dp == 0 && dr == 0 && dv == 0);
    free_outputs(&o);
  }
  /* the NaN and infinite coordinates give NaN */
  NL_CHECK(isnan(ref.pts3[1]) && isnan(ref.pts3[2]) && isnan(ref.pts3[3]));
  NL_CHECK(isnan(ref.pts2[1]) && isnan(ref.pts2[2]));
  nl_noise_simd_set(nl_noise_simd_best());
  free_outputs(&ref);
  nl_noise_grad2_free(t);
}

NL_TEST(every_level_gives_the_scalar_bits_m512) { levels_for_table(512); }
NL_TEST(every_level_gives_the_scalar_bits_m16) { levels_for_table(16); }
NL_TEST(every_level_gives_the_scalar_bits_m65536) { levels_for_table(65536); }

/* Accuracy against the double path and Perlin's code at the same points. */
static void accuracy(int far)
{
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  nl_noise_grad2 *t = nl_noise_grad2_alloc(512);
  nl_noise_grad2_seed(t, 3);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, far ? 77 : 76);
  size_t n = F32_POINTS;
  float *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *z = malloc(n * sizeof *z);
  float *v3 = malloc(n * sizeof *v3), *v2 = malloc(n * sizeof *v2);
  for (size_t k = 0; k < n; k++) {
    x[k] = far ? coord_far(r) : coord(r, 300);
    y[k] = far ? coord_far(r) : coord(r, 300);
    z[k] = far ? coord_far(r) : coord(r, 300);
  }
  nl_noise_perm3_points_f32(&p, x, y, z, n, v3);
  nl_noise_grad2_points_f32(t, x, y, n, v2);
  double e3 = 0, e2 = 0, ep = 0;
  size_t w3 = 0;
  for (size_t k = 0; k < n; k++) {
    double d3 = fabs(v3[k] - nl_noise_perm3_eval(&p, x[k], y[k], z[k]));
    double d2 = fabs(v2[k] - nl_noise_grad2_eval(t, x[k], y[k]));
    if (!(d3 <= e3)) {
      e3 = d3;
      w3 = k;
    }
    if (!(d2 <= e2)) e2 = d2;
    double dp = far ? 0.0 : fabs(v3[k] - perlin_improved_noise(x[k], y[k], z[k]));
    if (!(dp <= ep)) ep = dp;
  }
  printf("  %zu points %s: max |f32 - double| %.3g (improved 3D, at %.9g %.9g %.9g), %.3g (2D, m = 512)",
         n, far ? "of every magnitude to 2^40" : "of [-300, 300]^3", e3, x[w3], y[w3], z[w3], e2);
  if (!far) printf("; max |f32 - Perlin's code| %.3g", ep);
  printf("\n");
  NL_CHECK(e3 <= F32_TOL && e2 <= F32_TOL && ep <= F32_TOL);
  gsl_rng_free(r);
  void *blocks[] = {x, y, z, v3, v2};
  for (size_t k = 0; k < 5; k++) free(blocks[k]);
  nl_noise_grad2_free(t);
}

NL_TEST(float_noise_is_the_double_noise_within_tol) { accuracy(0); }
NL_TEST(float_noise_is_accurate_at_every_magnitude) { accuracy(1); }

/* Sums of octaves: the float sum against the double sum at the same points
 * (octave l's coordinates f_l c rounded to float: with f up to 2^4 at
 * |c| <= 300 that moves a sample by up to 2^-11 of a cell, so the bound is
 * the input's resolution, not the arithmetic's). */
NL_TEST(float_sums_follow_the_double_sums)
{
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 9);
  enum { N = 4096 };
  float x[N], y[N], z[N], v[N];
  for (int k = 0; k < N; k++) {
    x[k] = (float)(8 * gsl_rng_uniform(r) - 4);
    y[k] = (float)(8 * gsl_rng_uniform(r) - 4);
    z[k] = (float)(8 * gsl_rng_uniform(r) - 4);
  }
  nl_noise_octaves o = nl_noise_octaves_fbm(5, 0.5, 2.0);   /* f = 2^l: exact in float */
  nl_noise_perm3_fractal_points_f32(&p, &o, x, y, z, N, v);
  double e = 0;
  /* maxima by comparison, not fmax (a NaN counts): aarch64 gcc 12 stops
   * with an internal error vectorizing an fmax reduction here */
  for (int k = 0; k < N; k++) {
    double d = fabs(v[k] - nl_noise_perm3_fractal_eval(&p, &o, x[k], y[k], z[k]));
    if (!(d <= e)) e = d;
  }
  printf("  fBm 5 octaves, 4096 points of [-4, 4]^3: max |f32 - double| %.3g\n", e);
  NL_CHECK(e <= 2 * F32_TOL);   /* the sum's weights add to < 2 */
  gsl_rng_free(r);
}

/* What a double caller loses by rounding coordinates to float: measured,
 * not a property of the kernels (they are exact at the float point). */
NL_TEST(rounding_the_coordinates_costs_resolution)
{
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 12);
  double near = 0, far = 0;
  for (int k = 0; k < 100000; k++) {
    double s = k % 2 ? 300 : 4096;
    double x = s * (2 * gsl_rng_uniform(r) - 1), y = s * (2 * gsl_rng_uniform(r) - 1),
           z = s * (2 * gsl_rng_uniform(r) - 1);
    float got;
    nl_noise_perm3_points_f32(&p, &(float){(float)x}, &(float){(float)y}, &(float){(float)z}, 1, &got);
    double d = fabs(got - nl_noise_perm3_eval(&p, x, y, z));
    if (k % 2) { if (!(d <= near)) near = d; }
    else if (!(d <= far)) far = d;
  }
  printf("  double points rounded to float: max |f32 - double| %.3g in [-300, 300]^3, %.3g in "
         "[-2^12, 2^12]^3\n", near, far);
  /* |c| 2^-24 of movement per coordinate, slope below 4 a cell per axis */
  NL_CHECK(near <= 3 * 4 * 300 * 0x1p-24 + F32_TOL && far <= 3 * 4 * 4096 * 0x1p-24 + F32_TOL);
  gsl_rng_free(r);
}

/* A 2D table the float path does not index: the double noise, rounded. */
NL_TEST(other_tables_round_the_double_noise)
{
  nl_noise_grad2 *t = nl_noise_grad2_alloc(500);
  nl_noise_grad2_seed(t, 1);
  float x[300], y[300], v[300], row[300];
  for (int k = 0; k < 300; k++) {
    x[k] = -7.3f + 0.173f * (float)k;
    y[k] = 2.9f - 0.011f * (float)k;
  }
  nl_noise_grad2_points_f32(t, x, y, 300, v);
  nl_noise_grad2_row_f32(t, -7.3f, 0.173f, 2.9f, 300, row);
  long wrong = 0;
  for (int k = 0; k < 300; k++) {
    wrong += v[k] != (float)nl_noise_grad2_eval(t, x[k], y[k]);
    wrong += row[k] != (float)nl_noise_grad2_eval(t, fmaf((float)k, 0.173f, -7.3f), 2.9f);
  }
  NL_CHECK(wrong == 0);
  nl_noise_grad2_free(t);
}

/* The grid is its rows (pixel centres placed in double, then rounded), and
 * the point calls are the batches' values, at every level. */
NL_TEST(grid_and_point_calls_agree_with_rows_and_batches)
{
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 3);
  nl_noise_grad2 *t = nl_noise_grad2_alloc(256);
  nl_noise_grad2_seed(t, 3);
  nl_noise_octaves o = nl_noise_octaves_fbm(4, 0.5, 2.0);
  nl_noise_window win = {-3.25, 250.5, 0.75, 9.5, 77, 31};
  float *grid = malloc(77 * 31 * sizeof *grid), row[77];
  long wrong = 0;
  for (int l = NL_SIMD_SCALAR; l <= NL_SIMD_AVX512; l++) {
    if (!nl_noise_simd_supported(l)) continue;
    nl_noise_simd_set(l);
    for (int which = 0; which < 2; which++) {
      nl_noise_fractal_grid_f32(which ? t : NULL, which ? NULL : &p, &o, &win, grid);
      double dx = win.size / win.w, dy = win.size / win.h;
      for (int r = 0; r < win.h; r++) {
        float x0 = (float)(win.x0 + 0.5 * dx), y = (float)(win.y0 + (r + 0.5) * dy);
        if (which)
          nl_noise_grad2_fractal_row_f32(t, &o, x0, (float)dx, y, 77, row);
        else
          nl_noise_perm3_fractal_row_f32(&p, &o, x0, (float)dx, y, (float)win.z, 77, row);
        wrong += differ(row, grid + (size_t)r * 77, 77);
      }
    }
    float x[40], y[40], z[40], v3[40], v2[40];
    for (int k = 0; k < 40; k++) {
      x[k] = -20.5f + 1.37f * (float)k;
      y[k] = 255.9f - 0.71f * (float)k;
      z[k] = (float)k * 0.25f;
    }
    nl_noise_perm3_points_f32(&p, x, y, z, 40, v3);
    nl_noise_grad2_points_f32(t, x, y, 40, v2);
    for (int k = 0; k < 40; k++) {
      float a = nl_noise_perm3_eval_f32(&p, x[k], y[k], z[k]), b = nl_noise_grad2_eval_f32(t, x[k], y[k]);
      wrong += memcmp(&a, v3 + k, sizeof a) != 0 || memcmp(&b, v2 + k, sizeof b) != 0;
    }
  }
  nl_noise_simd_set(nl_noise_simd_best());
  NL_CHECK(wrong == 0);
  free(grid);
  nl_noise_grad2_free(t);
}

/* An empty sum is 0 everywhere, at every level. */
NL_TEST(an_empty_sum_is_zero)
{
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 1);
  nl_noise_octaves o = nl_noise_octaves_fbm(0, 0.5, 2.0);
  float row[37], pts[37], x[37];
  for (int k = 0; k < 37; k++) x[k] = (float)k * 0.3f;
  nl_noise_perm3_fractal_row_f32(&p, &o, 0.1f, 0.3f, 0.2f, 0.7f, 37, row);
  nl_noise_perm3_fractal_points_f32(&p, &o, x, x, x, 37, pts);
  int nonzero = 0;
  for (int k = 0; k < 37; k++) nonzero += row[k] != 0 || pts[k] != 0;
  NL_CHECK(nonzero == 0);
}

int main(void)
{
  int rc = nl_test_run();
  free(px);
  free(py);
  free(pz);
  return rc;
}
