/* test_noise_grad2_reference.c - the 2D gradient-table noise against
 * Cheng's definition (tests/reference/cheng_gradient_noise.c), and sums of
 * octaves (fractal sum, fBm, Cheng's eq. 3.10 octaves, turbulence) of both
 * noises against the same sums of the oracles (that one and Perlin's code,
 * tests/reference/perlin_improved_noise.c).
 *
 * Tables: m = 512 (indices by mask) and m = 500 (by division), the angles
 * and permutation the library drew. Points: 2^17 a table through
 * nl_noise_grad2_eval and, at every SIMD level, nl_noise_grad2_points;
 * 1024 rows of 256 through nl_noise_grad2_row at every level. Coordinates
 * uniform in [-300, 300] or, one time in two, a lattice point, a
 * half-integer, an ulp off an integer, a tiny value of either sign (those
 * in [-2^-54, 0) included), or near a multiple of m (where the table
 * wraps).
 *
 * Tolerance 5e-15 absolute (|noise| <= 0.71): the same four corner terms,
 * blended by fade(t) along y then x there, weighted by 1 - fade(|t|) and
 * summed corner by corner here. fade's Horner form passes through
 * 6t - 15, so each evaluation rounds at ~2^-49 (1.8e-15) absolute, and
 * the two sides evaluate it at t and at 1 - t: measured 2.1e-15 (with the
 * expanded 6t^5 - 15t^4 + 10t^3 here, 5.4e-15). Sums: 5e-15 sum_l |amp_l|
 * (8.5e-16 measured; the oracles evaluated at the row's own octave
 * coordinates x0 f + k (dx f), so only the noise and the sum are
 * compared, not the rounding of f x).
 */
#include "noise/nl_noise.h"
#include "nl_test.h"
#include "reference/cheng_gradient_noise.h"
#include "reference/perlin_improved_noise.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

#define NPOINTS (1 << 17)
#define TOL 5e-15

static double coord(gsl_rng *r, double m)
{
  double u = gsl_rng_uniform(r);
  if (u < 0.5) return 600 * gsl_rng_uniform(r) - 300;
  double n = (double)((long)gsl_rng_uniform_int(r, 601) - 300);
  double s = gsl_rng_uniform(r) < 0.5 ? -1.0 : 1.0;
  if (u < 0.6) return n;
  if (u < 0.65) return n + 0.5;
  if (u < 0.75) return nextafter(n, s * INFINITY);
  if (u < 0.85) {
    if (gsl_rng_uniform(r) < 1.0 / 3)
      return -ldexp(1 + gsl_rng_uniform(r), -55 - (int)gsl_rng_uniform_int(r, 960));
    return s * ldexp(1.0, -1 - (int)gsl_rng_uniform_int(r, 1074));
  }
  double w = m * (double)((long)gsl_rng_uniform_int(r, 3) - 1);
  return gsl_rng_uniform(r) < 0.3 ? nextafter(w, s * INFINITY) : w + s * gsl_rng_uniform(r);
}

static double ref2(const nl_noise_grad2 *t, double x, double y)
{
  return cheng_gradient_noise(t->angle, t->perm, t->m, x, y);
}

NL_TEST(grad2_matches_cheng_eq_3_2)
{
  static const size_t sizes[] = {512, 500};
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 2009);
  double *x = malloc(NPOINTS * sizeof *x), *y = malloc(NPOINTS * sizeof *y);
  double *out = malloc(NPOINTS * sizeof *out);
  for (int s = 0; s < 2; s++) {
    nl_noise_grad2 *t = nl_noise_grad2_alloc(sizes[s]);
    nl_noise_grad2_seed(t, 41 + (unsigned long)s);
    double worst = 0;
    for (size_t k = 0; k < NPOINTS; k++) {
      x[k] = coord(r, (double)t->m);
      y[k] = coord(r, (double)t->m);
      worst = fmax(worst, fabs(nl_noise_grad2_eval(t, x[k], y[k]) - ref2(t, x[k], y[k])));
    }
    printf("  m = %zu eval   %d points, max |ours - eq. 3.2| %.3g\n", t->m, NPOINTS, worst);
    NL_CHECK(worst <= TOL);
    for (int l = NL_SIMD_SCALAR; l <= NL_SIMD_AVX512; l++) {
      if (!nl_simd_supported(l))
        continue;
      nl_simd_set(l);
      double wp = 0, wr = 0;
      nl_noise_grad2_points(t, x, y, NPOINTS, out);
      for (size_t k = 0; k < NPOINTS; k++)
        wp = fmax(wp, fabs(out[k] - ref2(t, x[k], y[k])));
      static const double steps[] = {1.0 / 64, 0.0137, -0.29, 3.7, 1e-4, 0.5, 1.0, 0x1p-56};
      for (int row = 0; row < 1024; row++) {
        double x0 = x[row], yy = y[row], dx = steps[row % 8], v[256];
        nl_noise_grad2_row(t, x0, dx, yy, 256, v);
        for (int k = 0; k < 256; k++)
          wr = fmax(wr, fabs(v[k] - ref2(t, x0 + (double)k * dx, yy)));
      }
      printf("  m = %zu %-6s points %.3g, rows %.3g\n", t->m, nl_simd_name(l), wp, wr);
      NL_CHECK(wp <= TOL && wr <= TOL);
    }
    nl_simd_set(nl_simd_best());
    nl_noise_grad2_free(t);
  }
  free(x); free(y); free(out);
  gsl_rng_free(r);
}

NL_TEST(octave_sums_match_the_oracles_sums)
{
  nl_noise_grad2 *t = nl_noise_grad2_alloc(512);
  nl_noise_grad2_seed(t, 7);
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  nl_noise_basis bases[2] = {nl_noise_basis_grad2(t), nl_noise_basis_perm3(&p)};
  nl_noise_octaves sets[4] = {nl_noise_octaves_fractal(6), nl_noise_octaves_fbm(5, 0.6, 2.1),
                              nl_noise_octaves_cheng(4, 8, 4), nl_noise_octaves_fbm(5, 0.6, 2.1)};
  sets[3].turbulence = 1;
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 1985);
  double worst = 0;
  long values = 0;
  for (int l = NL_SIMD_SCALAR; l <= NL_SIMD_AVX512; l++) {
    if (!nl_simd_supported(l))
      continue;
    nl_simd_set(l);
    for (int row = 0; row < 256; row++) {
      int b = row % 2;
      const nl_noise_octaves *o = &sets[row / 2 % 4];
      double x0 = coord(r, 256), y = coord(r, 256), z = coord(r, 256);
      double dx = row % 3 ? 0.0137 : -0.29, out[200], scratch[200], bound = 0;
      nl_noise_fractal_row(&bases[b], o, x0, dx, y, z, 200, out, scratch);
      for (int q = 0; q < o->n; q++)
        bound += fabs(o->amp[q]);
      for (int k = 0; k < 200; k++) {
        double want = 0;
        for (int q = 0; q < o->n; q++) {
          double f = o->freq[q], px = x0 * f + (double)k * (dx * f);
          double v = b == 0 ? ref2(t, px, y * f) : perlin_improved_noise(px, y * f, z * f);
          want += o->amp[q] * (o->turbulence ? fabs(v) : v);
        }
        worst = fmax(worst, fabs(out[k] - want) / bound);
        values++;
      }
    }
  }
  nl_simd_set(nl_simd_best());
  printf("  %ld values of sums over both noises and every level, max |ours - oracle| / sum |amp|"
         " %.3g\n", values, worst);
  NL_CHECK(worst <= TOL);
  gsl_rng_free(r);
  nl_noise_grad2_free(t);
}

int main(void) { return nl_test_run(); }
