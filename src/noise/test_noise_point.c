/* The inline point calls of nl_noise.h against the library's out-of-line
 * formula (nl_noise_*_eval_general: the scalar kernel with
 * nl_noise_lattice.h's floor and fraction), bit for bit, at 2^17 points a
 * test whose coordinates are random in [-300, 300], lattice points,
 * half-integers, an ulp either side of an integer, tiny of either sign,
 * near a multiple of 256, at the 2^31 edge of the inline path, or not
 * finite. */
#include "noise/nl_noise.h"
#include "nl_test.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

enum { NPOINTS = 1 << 17 };

static double coordinate(gsl_rng *r)
{
  double u = 600 * gsl_rng_uniform(r) - 300, n = floor(u);
  switch (gsl_rng_uniform_int(r, 12)) {
  case 0: return n;
  case 1: return n + 0.5;
  case 2: return nextafter(n, INFINITY);
  case 3: return nextafter(n, -INFINITY);
  case 4: return ldexp(gsl_rng_uniform(r) - 0.5, -60);
  case 5: return 256 * floor(u / 64) + (gsl_rng_uniform(r) - 0.5) * 1e-9;
  case 6: {   /* either side of the inline path's edge, +-2^31 */
    double e = gsl_rng_uniform_int(r, 2) ? 0x1p31 : -0x1p31;
    return e + (double)((long)gsl_rng_uniform_int(r, 5) - 2) * 0.25;
  }
  case 7: {
    const double odd[] = {NAN, INFINITY, -INFINITY, 0x1p62, -0x1p70, -0.0};
    return odd[gsl_rng_uniform_int(r, 6)];
  }
  default: return u;
  }
}

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

NL_TEST(perm3_point_is_the_general_formula)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 34);
  nl_noise_perm3 p[2];
  nl_noise_perm3_reference(&p[0]);
  nl_noise_perm3_seed(&p[1], 5);
  long bad = 0;
  for (int k = 0; k < NPOINTS; k++) {
    const nl_noise_perm3 *pp = &p[k & 1];
    double x = coordinate(r), y = coordinate(r), z = coordinate(r);
    if (!same_bits(nl_noise_perm3_eval(pp, x, y, z), nl_noise_perm3_eval_general(pp, x, y, z)))
      bad++;
  }
  NL_CHECK(bad == 0);
  gsl_rng_free(r);
}

NL_TEST(grad2_point_is_the_general_formula)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 35);
  nl_noise_grad2 *t[3] = {nl_noise_grad2_alloc(512), nl_noise_grad2_alloc(64),
                          nl_noise_grad2_alloc(300)};
  for (int a = 0; a < 3; a++) nl_noise_grad2_seed(t[a], 7 + (unsigned long)a);
  long bad = 0;
  for (int k = 0; k < NPOINTS; k++) {
    const nl_noise_grad2 *tt = t[k % 3];
    double x = coordinate(r), y = coordinate(r);
    if (!same_bits(nl_noise_grad2_eval(tt, x, y), nl_noise_grad2_eval_general(tt, x, y))) bad++;
  }
  NL_CHECK(bad == 0);
  for (int a = 0; a < 3; a++) nl_noise_grad2_free(t[a]);
  gsl_rng_free(r);
}

/* The point sum of octaves gives the bits of a one-sample fractal row, for
 * fBm, Shaffer's sum and turbulence. */
NL_TEST(perm3_fractal_point_is_the_row)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 36);
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  nl_noise_basis b = nl_noise_basis_perm3(&p);
  nl_noise_octaves o[3] = {nl_noise_octaves_fbm(4, 0.5, 2.0), nl_noise_octaves_fractal(7),
                           nl_noise_octaves_fbm(5, 0.6, 2.1)};
  o[2].turbulence = 1;
  long bad = 0;
  for (int k = 0; k < NPOINTS / 8; k++) {
    const nl_noise_octaves *oo = &o[k % 3];
    double x = coordinate(r), y = coordinate(r), z = coordinate(r), row, scratch;
    if (!isfinite(x) || !isfinite(y) || !isfinite(z)) continue;
    nl_noise_fractal_row(&b, oo, x, 0.25, y, z, 1, &row, &scratch);
    if (!same_bits(nl_noise_perm3_fractal_eval(&p, oo, x, y, z), row)) bad++;
  }
  NL_CHECK(bad == 0);
  gsl_rng_free(r);
}

#ifndef NL_NOISE_NO_INLINE
/* The pair table holds Perlin's 16 gradients (his grad(hash, x, y, z)). */
NL_TEST(perm3_gradient_pairs)
{
  for (int a = 0; a < 16; a++) {
    for (int b = 0; b < 16; b++) {
      const nl_noise_perm3_gradpairs_table *g = &nl_noise_perm3_gradpairs;
      int q = 16 * a + b;
      int h[2] = {a, b};
      for (int l = 0; l < 2; l++) {
        double x = 1, y = 10, z = 100;   /* grad(h, x, y, z) = gx x + gy y + gz z */
        double u = h[l] < 8 ? x : y, v = h[l] < 4 ? y : h[l] == 12 || h[l] == 14 ? x : z;
        double perlin = ((h[l] & 1) == 0 ? u : -u) + ((h[l] & 2) == 0 ? v : -v);
        NL_CHECK(g->gx[q][l] * x + g->gy[q][l] * y + g->gz[q][l] * z == perlin);
      }
    }
  }
}

#endif

int main(void) { return nl_test_run(); }
