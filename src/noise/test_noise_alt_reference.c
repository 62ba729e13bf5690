/* test_noise_alt_reference.c - A3's simplex noises (nl_noise_alt_simplex
 * with r2 = 0.6 and 0.5, nl_noise_alt_simplex2) against a transcription of
 * Gustavson's published code (tests/reference/gustavson_simplex.c), and
 * the classic 1985 lattice noise against its definition written here.
 *
 * Points: 2^17 per noise and table (three permutations), coordinates uniform
 * in [-300, 300] or, one time in two, a lattice point, a half-integer, an
 * ulp off an integer, a tiny value of either sign, or a point whose skewed
 * coordinate x + s is an integer (a simplex face). Tolerance 1e-15: the
 * same kernels and corners; the library sums them in a loop in the same
 * order, so agreement is expected to the rounding of a sum of four terms;
 * measured: bit-identical. The 1985 noise: gradients g[p[p[p[X] + Y] + Z]]
 * from the library's table (data), cubic fade 3t^2 - 2t^3, the trilinear
 * blend of the corner dot products ((1 - u) a + u b here, a + u (b - a)
 * there), within 1e-15 (|noise| <= ~1); measured 2.8e-16.
 */
#include "noise/nl_noise_alt.h"
#include "nl_test.h"
#include "reference/gustavson_simplex.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

#define NPOINTS (1 << 17)

static double coord(gsl_rng *r)
{
  double u = gsl_rng_uniform(r);
  if (u < 0.5) return 600 * gsl_rng_uniform(r) - 300;
  double n = (double)((long)gsl_rng_uniform_int(r, 601) - 300);
  double s = gsl_rng_uniform(r) < 0.5 ? -1.0 : 1.0;
  if (u < 0.6) return n;
  if (u < 0.7) return n + 0.5;
  if (u < 0.8) return nextafter(n, s * INFINITY);
  return s * ldexp(1.0, -1 - (int)gsl_rng_uniform_int(r, 1074));
}

static double fade3(double t) { return t * t * (3 - 2 * t); }

/* Perlin 1985 on the table's gradients: trilinear blend by the cubic fade. */
static double classic(const nl_noise_alt *t, double x, double y, double z)
{
  double cx = floor(x), cy = floor(y), cz = floor(z), c[2][2][2];
  int X = (int)((long)cx & 255), Y = (int)((long)cy & 255), Z = (int)((long)cz & 255);
  double fx = x - cx, fy = y - cy, fz = z - cz;
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++)
      for (int k = 0; k < 2; k++) {
        const double *g = t->g[t->p[t->p[t->p[X + i] + Y + j] + Z + k]];
        c[i][j][k] = g[0] * (fx - i) + g[1] * (fy - j) + g[2] * (fz - k);
      }
  double u = fade3(fx), v = fade3(fy), w = fade3(fz), e[2][2];
  for (int j = 0; j < 2; j++)
    for (int k = 0; k < 2; k++)
      e[j][k] = (1 - u) * c[0][j][k] + u * c[1][j][k];
  double f0 = (1 - v) * e[0][0] + v * e[1][0], f1 = (1 - v) * e[0][1] + v * e[1][1];
  return (1 - w) * f0 + w * f1;
}

NL_TEST(simplex_and_classic_match_their_references)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 2005);
  double worst[4] = {0};
  for (unsigned long seed = 1; seed <= 3; seed++) {
    nl_noise_perm3 p;
    nl_noise_perm3_seed(&p, seed);
    nl_noise_alt s6, s5, s2, cl;
    nl_noise_alt_simplex(&s6, &p, 0.6);
    nl_noise_alt_simplex(&s5, &p, 0.5);
    nl_noise_alt_simplex2(&s2, &p);
    nl_noise_alt_classic(&cl, &p, seed);
    for (int k = 0; k < NPOINTS; k++) {
      double x = coord(r), y = coord(r), z = coord(r);
      if (k % 8 == 0) {   /* on a face of the skewed lattice: x + s an integer */
        double s = (x + y + z) / 3.0;
        x = floor(x + s) - s;
      }
      worst[0] = fmax(worst[0], fabs(nl_noise_alt_eval(&s6, x, y, z)
                                     - gustavson_noise3(p.p, 0.6, x, y, z)));
      worst[1] = fmax(worst[1], fabs(nl_noise_alt_eval(&s5, x, y, z)
                                     - gustavson_noise3(p.p, 0.5, x, y, z)));
      worst[2] = fmax(worst[2], fabs(nl_noise_alt_eval(&s2, x, y, z)
                                     - gustavson_noise2(p.p, x, y)));
      worst[3] = fmax(worst[3], fabs(nl_noise_alt_eval(&cl, x, y, z) - classic(&cl, x, y, z)));
    }
  }
  printf("  3 tables x %d points: max |ours - Gustavson| 3D r2 0.6 %.3g, 0.5 %.3g, 2D %.3g;"
         " 1985 noise %.3g\n", NPOINTS, worst[0], worst[1], worst[2], worst[3]);
  for (int q = 0; q < 4; q++)
    NL_CHECK(worst[q] <= 1e-15);
  gsl_rng_free(r);
}

int main(void) { return nl_test_run(); }
