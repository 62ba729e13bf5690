/* test_byexample_reference.c - the band powers and weights of Lagae et al.
 * 2010 eq. 12-13 against the DFT by its definition (tests/reference/
 * direct_dft.c) binned here by exact integer arithmetic: frequency (u', v')
 * (signed indices) lies in band k iff
 *   2^-(k+2) < max(|u'| / w, |v'| / h) <= 2^-(k+1),
 * i.e. 2^(k+1) M <= w h < 2^(k+2) M for M = max(|u'| h, |v'| w); DC in no
 * band, bands past nbands dropped.
 *
 * Images: 14 shapes from 4 x 4 to 32 x 16 (powers of two, odd and mixed
 * sides), three images each (uniform, with a DC offset, and a sum of
 * cosines that puts power on band edges), nbands from 1 to two past
 * nl_byexample_band_count. Tolerance 1e-12 of the image's total power
 * (Parseval: the powers of one image sum to its mean square, so each band's
 * error is the FFT's, 1e-15 (2 + factor sum) sum |x| relative to the
 * spectrum's scale: test_spectrum_reference.c); measured in the output.
 * Weights: sqrt(P_k / sigma2) from those powers: |sqrt a - sqrt b| <=
 * sqrt |a - b|, so 1e-6 of sqrt(mean square / sigma2) (a band of nearly no
 * power takes the whole of it). Measured: powers 7.8e-16, weights 4.4e-16.
 */
#include "byexample/nl_byexample.h"
#include "nl_test.h"
#include "reference/direct_dft.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

static int exact_band(long u, long v, long w, long h)
{
  long M = labs(u) * h > labs(v) * w ? labs(u) * h : labs(v) * w, wh = w * h;
  if (M == 0)
    return -1;
  int k = 0;
  while ((M << (k + 2)) <= wh)
    k++;
  return k;   /* 2^(k+1) M <= wh < 2^(k+2) M */
}

NL_TEST(band_power_matches_the_dft_binned_exactly)
{
  static const int shapes[][2] = {{4, 4}, {8, 8}, {16, 16}, {32, 16}, {64, 4}, {12, 10},
    {18, 18}, {24, 20}, {33, 7}, {9, 27}, {12, 36}, {40, 8}, {7, 5}, {10, 24}};
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 2010);
  double worst = 0, worst_w = 0;
  long bins = 0;
  for (size_t s = 0; s < sizeof shapes / sizeof *shapes; s++) {
    int w = shapes[s][0], h = shapes[s][1];
    size_t n = (size_t)w * h;
    double *img = malloc(n * sizeof *img);
    long double *F = malloc(2 * n * sizeof *F);
    for (int rep = 0; rep < 3; rep++) {
      double ms = 0;
      for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
          double v = 2 * gsl_rng_uniform(r) - 1;
          if (rep == 1) v += 3;
          if (rep == 2)   /* frequencies on band edges: w/4, w/8, h/4 */
            v = cos(2 * M_PI * x / 4.0) + 0.5 * cos(2 * M_PI * x / 8.0) + cos(2 * M_PI * y / 4.0)
              + 0.1 * v;
          img[(size_t)y * w + x] = v;
          ms += v * v;
        }
      ms /= (double)n;
      direct_dft2(img, w, h, F);
      int top = nl_byexample_band_count(w, h) + 2;
      long double want[20] = {0};
      for (int v = 0; v < h; v++)
        for (int u = 0; u < w; u++) {
          long su = 2 * u < w ? u : u - w, sv = 2 * v < h ? v : v - h;
          int k = exact_band(su, sv, w, h);
          size_t q = (size_t)v * w + u;
          if (k >= 0 && k < top)
            want[k] += (F[2 * q] * F[2 * q] + F[2 * q + 1] * F[2 * q + 1]) / ((long double)n * n);
        }
      for (int nb = 1; nb <= top; nb++) {
        double power[20], wts[20], sigma2 = 0.275;
        NL_CHECK(nl_byexample_band_power(img, w, h, nb, power, NULL) == NL_OK);
        NL_CHECK(nl_byexample_weights(img, w, h, nb, sigma2, wts, NULL) == NL_OK);
        for (int k = 0; k < nb; k++) {
          worst = fmax(worst, fabs((double)(power[k] - want[k])) / ms);
          double ww = sqrt((double)want[k] / sigma2);
          worst_w = fmax(worst_w, fabs(wts[k] - ww) / sqrt(ms / sigma2));
          bins++;
        }
      }
    }
    free(img);
    free(F);
  }
  printf("  %ld band powers: max |ours - DFT| / mean square %.3g; weights %.3g\n", bins, worst,
         worst_w);
  NL_CHECK(worst <= 1e-12);
  NL_CHECK(worst_w <= 1e-6);
  gsl_rng_free(r);
}

int main(void) { return nl_test_run(); }
