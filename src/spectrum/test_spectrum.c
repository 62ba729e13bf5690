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
