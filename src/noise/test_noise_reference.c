/* test_noise_reference.c - every kernel of the improved noise against Ken
 * Perlin's published code (tests/reference/perlin_improved_noise.c, which
 * has its own copy of his table), with nl_noise_perm3_reference's table.
 *
 * Kernels: nl_noise_perm3_eval, and at the scalar level and each SIMD level
 * this CPU runs, nl_noise_perm3_row, nl_noise_perm3_points,
 * nl_noise_perm3_points_sum, nl_noise_perm3_points_bounded and
 * nl_noise_fractal_row (one octave of weight 1). Points: NL_REF_POINTS
 * (2^20) a run, each coordinate uniform in [-300, 300] or, one time in two,
 * an awkward one - a lattice point, a half-integer, an integer plus or
 * minus an ulp, a tiny double of either sign (those in [-2^-54, 0), whose
 * x - floor(x) rounds to 1, included), or near a multiple of 256 (where
 * the table wraps). Rows: random ones, and rows that cross 0 in steps of
 * 2^-56 and -256 in steps of its ulp, 2^-44.
 *
 * Tolerance: 1e-15 absolute, 4.5 ulps of 1 (|noise| <= 1.23), not 0. The
 * library blends along y and z before x (nl_noise.h), Perlin blends x
 * first: the same trilinear blend of the same corner values g . d (each at
 * most 2 in magnitude) in another order, about ten roundings on either
 * side, each within an ulp of a value below 2. Measured: 6.7e-16 (3 ulps
 * of 1) at 2^20 points. Each kernel must also give nl_noise_perm3_eval's
 * bits (the sums its value: 0 + -0 is +0).
 */
#include "noise/nl_noise.h"
#include "nl_test.h"
#include "reference/perlin_improved_noise.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NL_REF_POINTS (1 << 20)
#define NL_REF_TOL 1e-15

/* One coordinate: uniform, or (half the time) one of the awkward kinds. */
static double ref_coord(gsl_rng *r)
{
  double u = gsl_rng_uniform(r);
  if (u < 0.5) return 600 * gsl_rng_uniform(r) - 300;
  long n = (long)gsl_rng_uniform_int(r, 601) - 300;
  double s = gsl_rng_uniform(r) < 0.5 ? -1.0 : 1.0;
  if (u < 0.6) return (double)n;                             /* lattice point */
  if (u < 0.65) return (double)n + 0.5;                      /* half-integer */
  if (u < 0.75) return nextafter((double)n, s * INFINITY);   /* an ulp off a lattice point */
  if (u < 0.85) {   /* tiny, 2^-1074 .. 2^-1, a third of them in [-2^-54, 0) */
    if (gsl_rng_uniform(r) < 1.0 / 3)
      return -ldexp(1 + gsl_rng_uniform(r), -55 - (int)gsl_rng_uniform_int(r, 960));
    return s * ldexp(1.0, -1 - (int)gsl_rng_uniform_int(r, 1074));
  }
  double m = 256.0 * (double)(n % 3);                        /* -512 .. 512 */
  double off[] = {0.0, -0.0, 1e-9, 0.5, 1.0, gsl_rng_uniform(r), 0x1p-30};
  double o = off[gsl_rng_uniform_int(r, sizeof off / sizeof *off)];
  return gsl_rng_uniform(r) < 0.2 ? nextafter(m, s * INFINITY) : m + s * o;
}

typedef struct { double worst, x, y, z, got, want; long n; } ref_stat;

static void ref_note(ref_stat *s, double x, double y, double z, double got)
{
  double want = perlin_improved_noise(x, y, z), d = fabs(got - want);
  s->n++;
  if (!(d <= s->worst))
    *s = (ref_stat){d, x, y, z, got, want, s->n};
}

static void ref_report(const char *kernel, const char *level, const ref_stat *s)
{
  printf("  %-15s %-7s %8ld values, max |ours - Perlin| %.3g", kernel, level, s->n, s->worst);
  if (s->worst > 0)
    printf(" at (%.17g, %.17g, %.17g): %.17g, Perlin %.17g", s->x, s->y, s->z, s->got, s->want);
  printf("\n");
  NL_CHECK(s->worst <= NL_REF_TOL);
}

/* The bits of nl_noise_perm3_eval, or (sums, where 0 + -0 = +0) its value. */
static long ref_differs(const double *a, const double *b, size_t n, int by_value)
{
  long d = 0;
  for (size_t k = 0; k < n; k++)
    d += by_value ? !(a[k] == b[k]) : memcmp(a + k, b + k, sizeof *a) != 0;
  return d;
}

static double *px, *py, *pz, *pv;   /* the points and nl_noise_perm3_eval at them */

static void make_points(const nl_noise_perm3 *p)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 2002);
  size_t n = NL_REF_POINTS + NL_NOISE_PACK_PAD;
  px = malloc(n * sizeof *px);
  py = malloc(n * sizeof *py);
  pz = malloc(n * sizeof *pz);
  pv = malloc(n * sizeof *pv);
  for (size_t k = 0; k < NL_REF_POINTS; k++) {
    px[k] = ref_coord(r);
    py[k] = ref_coord(r);
    pz[k] = ref_coord(r);
    pv[k] = nl_noise_perm3_eval(p, px[k], py[k], pz[k]);
  }
  gsl_rng_free(r);
}

NL_TEST(reference_table_is_perlins)
{
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  int wrong = 0, seen[256] = {0};
  for (int k = 0; k < 512; k++) wrong += p.p[k] != perlin_improved_permutation(k & 255);
  for (int k = 0; k < 256; k++) seen[p.p[k]]++;
  for (int k = 0; k < 256; k++) wrong += seen[k] != 1;
  NL_CHECK(wrong == 0);
  /* the value quoted for Perlin's Java code (Rosetta Code, "Perlin noise") */
  NL_CHECK_NEAR(perlin_improved_noise(3.14, 42, 7), 0.13691995878400012, 0);
}

NL_TEST(point_kernel_matches_perlin)
{
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  if (!px) make_points(&p);
  ref_stat s = {0};
  for (size_t k = 0; k < NL_REF_POINTS; k++) ref_note(&s, px[k], py[k], pz[k], pv[k]);
  ref_report("eval", "-", &s);
  /* a point whose hashes read the table's last entry, 180 */
  double got = nl_noise_perm3_eval(&p, -0.5, 0.5, 0.5);
  NL_CHECK_NEAR(got, perlin_improved_noise(-0.5, 0.5, 0.5), NL_REF_TOL);
}

/* The batch kernels at one level over all the points. */
static void batches_at_level(const nl_noise_perm3 *p, const char *name)
{
  size_t n = NL_REF_POINTS;
  double *out = malloc((n + NL_NOISE_PACK_PAD) * sizeof *out);
  ref_stat s = {0};
  nl_noise_perm3_points(p, px, py, pz, n, out);
  for (size_t k = 0; k < n; k++) ref_note(&s, px[k], py[k], pz[k], out[k]);
  ref_report("points", name, &s);
  NL_CHECK(ref_differs(out, pv, n, 0) == 0);

  /* points_sum and points_bounded, f = 1, amp = 1, from sums of 0: v */
  memset(out, 0, n * sizeof *out);
  double top = nl_noise_perm3_points_sum(p, 1.0, px, py, pz, n, 1.0, out);
  s = (ref_stat){0};
  for (size_t k = 0; k < n; k++) ref_note(&s, px[k], py[k], pz[k], out[k]);
  ref_report("points_sum", name, &s);
  NL_CHECK(ref_differs(out, pv, n, 1) == 0 && top <= NL_NOISE3_BOUND);

  size_t m = n + NL_NOISE_PACK_PAD;
  nl_noise_pack pk = {malloc(m * sizeof(double)), malloc(m * sizeof(double)),
                      malloc(m * sizeof(double)), calloc(m, sizeof(double)),
                      calloc(m, sizeof(double)), malloc(m * sizeof(int)), n};
  int *hi = malloc(n * sizeof *hi);
  memcpy(pk.x, px, n * sizeof *px);
  memcpy(pk.y, py, n * sizeof *py);
  memcpy(pk.z, pz, n * sizeof *pz);
  for (size_t k = 0; k < n; k++)
    pk.id[k] = (int)k;
  top = 0;
  /* r = inf: no point is decided, every sum stays in its place */
  size_t nhi = nl_noise_perm3_points_bounded(p, 1.0, 1.0, INFINITY, &pk, hi, &top);
  NL_CHECK(nhi == 0 && pk.n == n);
  s = (ref_stat){0};
  for (size_t k = 0; k < n; k++) ref_note(&s, px[k], py[k], pz[k], pk.sum[k]);
  ref_report("points_bounded", name, &s);
  NL_CHECK(ref_differs(pk.sum, pv, n, 1) == 0);
  void *blocks[] = {pk.x, pk.y, pk.z, pk.base, pk.sum, pk.id, hi, out};
  for (size_t k = 0; k < sizeof blocks / sizeof *blocks; k++)
    free(blocks[k]);
}

/* Rows from the points (origin, y, z) with steps dense to sparse (to 3.7
 * cells a sample: both windows of the columns, columns lane by lane, and
 * the points path), and rows across the lattice planes 0 and -256 in steps
 * of 2^-56 (through [-2^-54, 0)): as nl_noise_perm3_row and as a one-octave
 * fractal row. */
static void rows_at_level(const nl_noise_perm3 *p, const char *name)
{
  static const double steps[] = {1.0 / 64, 0.0137, -0.29, 3.7, 1e-4, -1.0 / 64, 0.75, 0x1p-56,
                                 0.7, -1.3, 13.0 / 7, -1.95};
  enum { NSTEPS = sizeof steps / sizeof *steps };
  enum { ROW = 256 };
  double out[ROW], frac[ROW], one[ROW], scratch[ROW];
  nl_noise_basis b = nl_noise_basis_perm3(p);
  nl_noise_octaves o = nl_noise_octaves_fbm(1, 1.0, 1.0);
  ref_stat s = {0}, sf = {0};
  long differ = 0;
  size_t nrows = NL_REF_POINTS / ROW;
  for (size_t r = 0; r < nrows + 8; r++) {
    double y = py[r], z = pz[r];
    double dx = r < nrows ? steps[r % NSTEPS] : r % 2 ? 0x1p-44 : 0x1p-56;   /* ulp of 256, 2^-56 */
    double x0 = r < nrows ? px[r] : r % 2 ? -256.0 - 100 * dx : -100 * dx;
    nl_noise_perm3_row(p, x0, dx, y, z, ROW, out);
    nl_noise_fractal_row(&b, &o, x0, dx, y, z, ROW, frac, scratch);
    for (int k = 0; k < ROW; k++) {
      double x = x0 + (double)k * dx;
      ref_note(&s, x, y, z, out[k]);
      ref_note(&sf, x, y, z, frac[k]);
      one[k] = nl_noise_perm3_eval(p, x, y, z);
    }
    differ += ref_differs(out, one, ROW, 0) + ref_differs(frac, one, ROW, 1);
  }
  ref_report("row", name, &s);
  ref_report("fractal_row", name, &sf);
  NL_CHECK(differ == 0);
}

NL_TEST(every_level_matches_perlin)
{
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  if (!px) make_points(&p);
  for (int l = NL_SIMD_SCALAR; l <= NL_SIMD_AVX512; l++) {
    if (!nl_noise_simd_supported(l)) {
      nl_test_skip("the %s level: not compared, this CPU cannot run it", nl_noise_simd_name(l));
      continue;
    }
    nl_noise_simd_set(l);
    batches_at_level(&p, nl_noise_simd_name(l));
    rows_at_level(&p, nl_noise_simd_name(l));
  }
  nl_noise_simd_set(nl_noise_simd_best());
}

/* The noise at s on axis 0, 1 or 2, the other two coordinates y, z. */
static double perm3_on(const nl_noise_perm3 *p, int axis, double s, double y, double z)
{
  if (axis == 0)
    return nl_noise_perm3_eval(p, s, y, z);
  return axis == 1 ? nl_noise_perm3_eval(p, y, s, z) : nl_noise_perm3_eval(p, y, z, s);
}

/* Where x - floor(x) rounds to 1 (x in [-2^-54, 0)) the noise is its value
 * at x = 0 up to rounding, in 2D and 3D, not its value one cell down. */
NL_TEST(noise_is_continuous_below_zero)
{
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 7);
  nl_noise_grad2 *t = nl_noise_grad2_alloc(512);
  nl_noise_grad2_seed(t, 7);
  static const double xs[] = {-0x1p-54, -0x1.8p-55, -0x1p-60, -1e-20, -0x1p-1074};
  double worst = 0;
  for (int k = 0; k < 100; k++) {
    double y = 0.37 + 1.37 * k, z = -2.11 * k;
    for (size_t a = 0; a < sizeof xs / sizeof *xs; a++) {
      double x = xs[a];
      for (int axis = 0; axis < 3; axis++)
        worst = fmax(worst, fabs(perm3_on(&p, axis, x, y, z) - perm3_on(&p, axis, 0, y, z)));
      worst = fmax(worst, fabs(nl_noise_grad2_eval(t, x, y) - nl_noise_grad2_eval(t, 0, y)));
      worst = fmax(worst, fabs(nl_noise_grad2_eval(t, y, x) - nl_noise_grad2_eval(t, y, 0)));
    }
  }
  printf("  max |noise(x) - noise(0)| for x in [-2^-54, 0): %.3g\n", worst);
  NL_CHECK(worst <= NL_REF_TOL);
  nl_noise_grad2_free(t);
}

int main(void)
{
  int rc = nl_test_run();
  free(px);
  free(py);
  free(pz);
  free(pv);
  return rc;
}
