#include "spectrum/nl_spectrum.h"
#include "nl_test.h"

#include <stdlib.h>

NL_TEST(parseval_and_round_trip_odd_size)
{
  int w = 30, h = 17;   /* not powers of two */
  size_t n = (size_t)w * h;
  double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *P = malloc(n * sizeof *P);
  double *F = malloc(2 * n * sizeof *F), ms = 0, sp = 0;
  srand(3);
  for (size_t k = 0; k < n; k++) { x[k] = rand() / (double)RAND_MAX - 0.3; ms += x[k] * x[k] / n; }
  nl_spectrum_power2(x, w, h, P);
  for (size_t k = 0; k < n; k++) sp += P[k];
  NL_CHECK_NEAR(sp, ms, 1e-12);
  nl_spectrum_fft2(x, w, h, F);
  nl_spectrum_fft2_inverse(F, w, h, y);
  double worst = 0;
  for (size_t k = 0; k < n; k++) worst = fmax(worst, fabs(x[k] - y[k]));
  NL_CHECK(worst < 1e-13);
  free(x); free(y); free(P); free(F);
}

NL_TEST(cosine_lands_in_its_bin)
{
  /* cos(2 pi 8 x / 64) along x: all power at |k| = 8/64 = 0.125 c/px. */
  int w = 64, h = 64, nb = 32;
  double *x = malloc(sizeof(double) * w * h), f[32], p[32];
  for (int r = 0; r < h; r++)
    for (int c = 0; c < w; c++) x[r * w + c] = cos(NL_TWO_PI * 8 * c / w);
  nl_spectrum_radial(x, w, h, nb, f, p);
  int best = 0;
  for (int b = 1; b < nb; b++) if (p[b] > p[best]) best = b;
  NL_CHECK(best == 8);    /* 0.125 / 0.5 * 32 */
  NL_CHECK_NEAR(f[8], 8.5 / 64, 1e-15);
  NL_CHECK_NEAR(nl_spectrum_freq(63, 64), -1.0 / 64, 0);
  free(x);
}

int main(void) { return nl_test_run(); }

NL_TEST(psd1_hann_window)
{
  /* Rectangular = psd1 bit for bit; Hann keeps the power of a sine that
   * falls on a bin (3/8 normalisation) in its three-bin main lobe, and
   * unknown windows are refused. */
  enum { N = 256 };
  double x[N], f[N / 2 + 1], P[N / 2 + 1], f2[N / 2 + 1], P2[N / 2 + 1];
  for (int j = 0; j < N; j++) x[j] = 0.3 + sin(2 * M_PI * 10.0 * j / N) + 0.01 * ((j * 37) % 11);
  NL_CHECK(nl_spectrum_psd1(x, N, 8.0, f, P, NULL) == NL_OK);
  NL_CHECK(nl_spectrum_psd1_window(x, N, 8.0, NL_SPECTRUM_RECT, f2, P2, NULL) == NL_OK);
  NL_CHECK(memcmp(P, P2, sizeof P) == 0 && memcmp(f, f2, sizeof f) == 0);
  for (int j = 0; j < N; j++) x[j] = sin(2 * M_PI * 10.0 * j / N);
  NL_CHECK(nl_spectrum_psd1_window(x, N, 8.0, NL_SPECTRUM_HANN, f2, P2, NULL) == NL_OK);
  NL_CHECK_NEAR(P2[9] + P2[10] + P2[11], 0.5, 1e-12);
  NL_CHECK_NEAR(P2[10] / (P2[9] + P2[10] + P2[11]), 2.0 / 3.0, 1e-12);
  NL_CHECK(nl_spectrum_psd1_window(x, N, 8.0, 7, f2, P2, NULL) == NL_EINVAL);
}
