#include "wavelet/nl_wavelet.h"
#include "nl_test.h"

#include <stdlib.h>
#include <string.h>

NL_TEST(coarse_line_keeps_constants)
{
  /* The analysis filter sums to 1 and each upsampled value takes 1/4 + 3/4
   * of two coarse values, so a constant line is its own coarse part. The
   * printed coefficients have 6 decimals: tolerance 1e-5. */
  float line[64];
  double c[64];
  for (int i = 0; i < 64; i++) line[i] = 2.0f;
  nl_wavelet_coarse_line(line, 1, 64, c);
  for (int i = 0; i < 64; i++) NL_CHECK_NEAR(c[i], 2.0, 1e-5 * 2);
}

NL_TEST(tile_is_periodic_and_deterministic)
{
  nl_wavelet_tile *a = nl_wavelet_tile_alloc(2, 64), *b = nl_wavelet_tile_alloc(2, 64);
  nl_wavelet_tile_seed(a, 5);
  nl_wavelet_tile_seed(b, 5);
  NL_CHECK(memcmp(a->data, b->data, 64 * 64 * sizeof(float)) == 0);
  NL_CHECK_NEAR(nl_wavelet_eval2(a, 3.3, 7.9), nl_wavelet_eval2(a, 3.3 + 64, 7.9 - 128), 1e-12);
  nl_wavelet_tile_seed(b, 6);
  NL_CHECK(nl_wavelet_eval2(a, 3.3, 7.9) != nl_wavelet_eval2(b, 3.3, 7.9));
  nl_wavelet_tile_free(a);
  nl_wavelet_tile_free(b);
  NL_CHECK(nl_wavelet_tile_alloc(2, 31) == NULL);
  NL_CHECK(nl_wavelet_tile_alloc(4, 32) == NULL);
}

NL_TEST(row_equals_points_bit_for_bit)
{
  for (int dim = 2; dim <= 3; dim++) {
    nl_wavelet_tile *t = nl_wavelet_tile_alloc(dim, 32);
    nl_wavelet_tile_seed(t, 9);
    double row[300] = {0};
    nl_wavelet_row(t, -7.25, 0.37, 4.1, -2.6, 300, 1.0, row);
    int same = 1;
    for (int k = 0; k < 300; k++) {
      double p = dim == 2 ? nl_wavelet_eval2(t, -7.25 + k * 0.37, 4.1)
                          : nl_wavelet_eval3(t, -7.25 + k * 0.37, 4.1, -2.6);
      same &= p == row[k];
    }
    NL_CHECK(same);
    nl_wavelet_tile_free(t);
  }
}

/* nl_wavelet_points gives nl_wavelet_eval2/3's bits at scattered points,
 * negative and far from the origin among them. */
NL_TEST(points_equal_eval_bit_for_bit)
{
  enum { N = 500 };
  double x[N], y[N], z[N], got[N];
  unsigned long s = 12345;
  for (int k = 0; k < N; k++) {   /* a small LCG: the points need no statistics */
    s = s * 6364136223846793005UL + 1442695040888963407UL;
    x[k] = ((double)(s >> 11) / 0x1p53 - 0.5) * (k % 7 ? 200 : 2e9);
    y[k] = -x[k] * 0.37 + (k % 5) - 2.5;
    z[k] = x[k] * 0.11 - 40;
  }
  for (int dim = 2; dim <= 3; dim++) {
    nl_wavelet_tile *t = nl_wavelet_tile_alloc(dim, 16);
    nl_wavelet_tile_seed(t, 4);
    nl_wavelet_points(t, x, y, dim == 3 ? z : NULL, N, got);
    int same = 1;
    for (int k = 0; k < N; k++) {
      double p = dim == 2 ? nl_wavelet_eval2(t, x[k], y[k]) : nl_wavelet_eval3(t, x[k], y[k], z[k]);
      same &= memcmp(&p, &got[k], sizeof p) == 0;
    }
    NL_CHECK(same);
    nl_wavelet_tile_free(t);
  }
}

NL_TEST(bspline_interpolates_a_constant_tile)
{
  /* Quadratic B-spline weights sum to 1: a tile of ones evaluates to 1. */
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(3, 16);
  for (int i = 0; i < 16 * 16 * 16; i++) t->data[i] = 1.0f;
  NL_CHECK_NEAR(nl_wavelet_eval3(t, 0.3, 5.77, -1.2), 1.0, 1e-15);
  nl_wavelet_tile_free(t);
}

NL_TEST(noise_has_zero_mean_and_is_band_limited)
{
  /* The finest-octave residual has no coarse part: a tile's mean over one
   * period is ~0 (sum of n^2 values of unit-ish variance: |mean| < 0.02 for
   * n = 128 is > 5 sigma), and the variance sits near the literature's
   * 0.2-0.3 range (Lagae quotes 0.265). */
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(2, 128);
  nl_wavelet_tile_seed(t, 3);
  double m = 0;
  for (int i = 0; i < 128 * 128; i++) m += t->data[i];
  m /= 128 * 128;
  NL_CHECK(fabs(m) < 0.02);
  double v = nl_wavelet_tile_variance(t, 2);
  printf("  2D variance %.4f\n", v);
  NL_CHECK(v > 0.15 && v < 0.4);
  nl_wavelet_tile_free(t);
}

NL_TEST(bands_sum_weights)
{
  /* A grid of one band with weight 2 is twice the grid with weight 1. */
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(2, 32);
  nl_wavelet_tile_seed(t, 1);
  nl_wavelet_bands b;
  double w1[2] = {1, 0}, w2[2] = {2, 0};
  NL_CHECK(nl_wavelet_bands_init(&b, 2, w1, 32, 4, NULL) == NL_OK);
  double g1[64], g2[64];
  nl_wavelet_bands_grid(t, &b, 8, 8, 0, 1, g1);
  NL_CHECK(nl_wavelet_bands_init(&b, 2, w2, 32, 4, NULL) == NL_OK);
  nl_wavelet_bands_grid(t, &b, 8, 8, 0, 1, g2);
  for (int i = 0; i < 64; i++) NL_CHECK_NEAR(g2[i], 2 * g1[i], 1e-12);
  NL_CHECK(nl_wavelet_bands_init(&b, 0, w1, 32, 4, NULL) == NL_EINVAL);
  nl_wavelet_tile_free(t);
}

int main(void) { return nl_test_run(); }
