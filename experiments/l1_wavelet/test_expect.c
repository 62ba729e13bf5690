/* Unit tests of L1's exact expectation (expect.c) by means that share no
 * code with it: quadrature of the B-spline autocorrelation, a naive
 * evaluation of the noise as the sum over every coefficient of the tile, and
 * the mean over seeds of the tiles' measured variance (src/wavelet). */
#include "expect.h"
#include "nl_test.h"
#include "wavelet/nl_wavelet.h"

#include <gsl/gsl_rng.h>
#include <math.h>

NL_TEST(expect_autocorrelation)
{
  /* a(d) = int B(x) B(x - d) dx by the midpoint rule on [-2, 2] */
  for (int d = 0; d <= 2; d++) {
    double s = 0, h = 1e-4;
    for (double x = -2 + h / 2; x < 2; x += h) s += l1_bspline(x) * l1_bspline(x - d) * h;
    NL_CHECK_NEAR(l1_bspline_autocorrelation(d, 0), s, 1e-7);
  }
  /* partition of unity: sum_d a(d) = 1 on any grid */
  for (int S = 0; S <= 4; S++) {
    double s = 0;
    for (int d = -3; d <= 3; d++) s += l1_bspline_autocorrelation(d, S);
    NL_CHECK_NEAR(s, 1, 1e-12);
  }
}

/* N(p) = sum over all i of c_i prod_axis B(p_a - i_a), lags wrapped to the period */
static double naive3(const nl_wavelet_tile *t, const double p[3])
{
  int n = t->n;
  double s = 0;
  for (int z = 0; z < n; z++)
    for (int y = 0; y < n; y++)
      for (int x = 0; x < n; x++) {
        const int i[3] = { x, y, z };
        double w = 1;
        for (int a = 0; a < 3 && w != 0; a++) {
          double d = fmod(p[a] - i[a], n);
          if (d < -n / 2.0) d += n;
          if (d >= n / 2.0) d -= n;
          w *= l1_bspline(d);
        }
        if (w != 0) s += w * t->data[((size_t)z * n + y) * n + x];
      }
  return s;
}

NL_TEST(expect_naive_evaluation)
{
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(3, 16);
  nl_wavelet_tile_seed(t, 7);
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 3);
  for (int k = 0; k < 50; k++) {
    double p[3];
    for (int a = 0; a < 3; a++) p[a] = 16 * gsl_rng_uniform(rng);
    NL_CHECK_NEAR(nl_wavelet_eval3(t, p[0], p[1], p[2]), naive3(t, p), 1e-9);
  }
  gsl_rng_free(rng);
  nl_wavelet_tile_free(t);
}

NL_TEST(expect_against_tiles)
{
  /* 3D period 16, 2 samples per unit: 12 seeds' mean within 4 standard errors */
  enum { K = 12 };
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(3, 16);
  double m = 0, ss = 0, v[K];
  for (int s = 0; s < K; s++) {
    nl_wavelet_tile_seed(t, 100 + s);
    v[s] = nl_wavelet_tile_variance(t, 2);
    m += v[s] / K;
  }
  for (int s = 0; s < K; s++) ss += (v[s] - m) * (v[s] - m);
  double se = sqrt(ss / (K - 1) / K), e = l1_variance_expected(3, 16, 2);
  NL_CHECK(fabs(m - e) < 4 * se);
  /* the continuous mean at the paper-scale period: 0.1956, 7% below Cook & DeRose's 0.210 */
  NL_CHECK(fabs(l1_variance_expected(3, 64, 0) - 0.1956) < 0.0005);
  nl_wavelet_tile_free(t);
  NL_CHECK(isnan(l1_variance_expected(3, 7, 0)) && isnan(l1_variance_expected(4, 16, 0)));
}

int main(void) { return nl_test_run(); }
