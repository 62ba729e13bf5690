/* test_spectrum_reference.c - the 2D and 1D transforms, power spectra and
 * radial averages against the DFT by its definition (tests/reference/
 * direct_dft.c: long double, angles reduced exactly, no FFT).
 *
 * Shapes: 22, from 1 x 1 to 48 x 20: powers of two (the library's radix-4
 * real path), primes and mixed sizes (GSL's mixed-radix path), single rows
 * and columns; three images each, uniform in [-1, 1], the last offset by
 * 100 (a DC term 100 times the rest). Every output compared: nl_spectrum_fft2,
 * the half spectrum of nl_spectrum_rfft2, nl_spectrum_fft2_inverse of the
 * oracle's spectrum, nl_spectrum_power2, and nl_spectrum_radial for 1, 3, 8
 * and 13 bins, binned here by exact integer arithmetic (frequency
 * (ku / w, kv / h) is in bin b iff b <= 2 nbins |k| < b + 1, squared and
 * multiplied out). 1D: nl_spectrum_psd1 and its Hann window at n = 2..64
 * and 97, 100, 128, 255, 256, against |X_k|^2 / n^2 folded to one side.
 *
 * Tolerances, relative to the scale an FFT's error grows with:
 *  - F: 1e-15 (2 + S) sum |x|, S the sum of the prime factors of w and h
 *    (16 x 12: 8 + 7). A mixed-radix FFT makes one pass per prime factor p
 *    of each side, each output of a pass a sum of p products (a general
 *    O(p) pass for p > 7), so about S roundings, each within ~eps of
 *    ||x||_1, reach an output (a pure radix-2/4 path: 2 log2 n of them).
 *    Measured: 0.018 of the bound (0.07 for the inverse, 0.08 for psd1,
 *    whose largest errors are at prime n up to 97);
 *  - inverse: the same bound over w h on each sample;
 *  - power |F|^2 / (w h)^2: twice F's relative bound, times (sum |x| / w h)^2;
 *  - radial means: as power (a mean of values within it);
 *  - psd1 as power, Hann's window computed in double there: 4 ulps more.
 */
#include "spectrum/nl_spectrum.h"
#include "nl_test.h"
#include "reference/direct_dft.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

static const int shapes[][2] = {{1, 1}, {1, 7}, {7, 1}, {2, 3}, {3, 5}, {5, 5}, {15, 9},
  {12, 10}, {30, 6}, {6, 30}, {17, 4}, {11, 13}, {64, 2}, {16, 16}, {32, 8}, {2, 128}, {8, 1},
  {4, 2}, {48, 20}, {25, 27}, {1, 64}, {9, 49}};
#define NSHAPES (sizeof shapes / sizeof *shapes)

static double worst[6];   /* error / bound: F, rfft, inverse, power, radial, psd1 */

static void note(int which, double err, double bound)
{
  worst[which] = fmax(worst[which], err / bound);
}

/* Bin of frequency (ku / w, kv / h) among nbins, exactly; nbins if beyond. */
static int exact_bin(long ku, long kv, int w, int h, int nbins)
{
  /* |k|^2 = (ku^2 h^2 + kv^2 w^2) / (w h)^2; b <= 2 nbins |k| iff
   * b^2 (w h)^2 <= 4 nbins^2 (ku^2 h^2 + kv^2 w^2) */
  __int128 k2 = (__int128)ku * ku * h * h + (__int128)kv * kv * w * w;
  __int128 lhs1 = (__int128)4 * nbins * nbins * k2;
  __int128 wh2 = (__int128)w * h * w * h;
  int b = 0;
  while (b < nbins && (__int128)(b + 1) * (b + 1) * wh2 <= lhs1)
    b++;
  return b;
}

/* Sum of the prime factors of n, with multiplicity (12: 2 + 2 + 3). */
static double factor_sum(int n)
{
  double s = 0;
  for (int p = 2; n > 1; p++)
    while (n % p == 0) {
      s += p;
      n /= p;
    }
  return s;
}

static long signed_index(int u, int n) { return 2 * u < n ? u : u - n; }

NL_TEST(two_d_transforms_match_the_dft)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 1965);
  for (size_t s = 0; s < NSHAPES; s++) {
    int w = shapes[s][0], h = shapes[s][1], m = w / 2 + 1;
    size_t n = (size_t)w * h;
    double *x = malloc(n * sizeof *x), *F = malloc(2 * n * sizeof *F);
    double *back = malloc(n * sizeof *back);
    double *H = malloc(2 * (size_t)m * h * sizeof *H), *P = malloc(n * sizeof *P);
    double *Fd = malloc(2 * n * sizeof *Fd);
    long double *R = malloc(2 * n * sizeof *R);
    nl_spectrum_fft2_plan *plan = nl_spectrum_fft2_plan_alloc(w, h, NULL);
    for (int rep = 0; rep < 3; rep++) {
      double l1 = 0;
      for (size_t k = 0; k < n; k++) {
        x[k] = 2 * gsl_rng_uniform(r) - 1 + (rep == 2 ? 100 : 0);
        l1 += fabs(x[k]);
      }
      double bound = 1e-15 * (2 + factor_sum(w) + factor_sum(h)) * l1;
      direct_dft2(x, w, h, R);
      NL_CHECK(nl_spectrum_fft2(x, w, h, F, NULL) == NL_OK);
      nl_spectrum_rfft2(plan, x, H);
      NL_CHECK(nl_spectrum_power2(x, w, h, P, NULL) == NL_OK);
      double pscale = 2 * bound / l1 * (l1 / (double)n) * (l1 / (double)n);
      for (int v = 0; v < h; v++)
        for (int u = 0; u < w; u++) {
          size_t k = (size_t)v * w + u;
          long double re = R[2 * k], im = R[2 * k + 1];
          note(0, fmax(fabsl(F[2 * k] - re), fabsl(F[2 * k + 1] - im)), bound);
          if (u < m) {
            size_t q = (size_t)v * m + u;
            note(1, fmax(fabsl(H[2 * q] - re), fabsl(H[2 * q + 1] - im)), bound);
          }
          long double pw = (re * re + im * im) / ((long double)n * n);
          note(3, fabsl(P[k] - pw), pscale);
          Fd[2 * k] = (double)re;
          Fd[2 * k + 1] = (double)im;
        }
      NL_CHECK(nl_spectrum_fft2_inverse(Fd, w, h, back, NULL) == NL_OK);
      for (size_t k = 0; k < n; k++)
        note(2, fabs(back[k] - x[k]), bound / (double)n);
      static const int nbins[] = {1, 3, 8, 13};
      for (int b = 0; b < 4; b++) {
        int nb = nbins[b];
        double f[13], p[13];
        long double sum[13] = {0};
        long cnt[13] = {0};
        NL_CHECK(nl_spectrum_radial(x, w, h, nb, f, p, NULL) == NL_OK);
        for (int v = 0; v < h; v++)
          for (int u = 0; u < w; u++) {
            int bin = exact_bin(signed_index(u, w), signed_index(v, h), w, h, nb);
            if (bin == nb)
              continue;
            size_t k = (size_t)v * w + u;
            sum[bin] += (R[2 * k] * R[2 * k] + R[2 * k + 1] * R[2 * k + 1]) / ((long double)n * n);
            cnt[bin]++;
          }
        for (int q = 0; q < nb; q++) {
          long double want = cnt[q] ? sum[q] / cnt[q] : 0;
          note(4, fabsl(p[q] - want), pscale);
          NL_CHECK(f[q] == (q + 0.5) * 0.5 / nb);
        }
      }
    }
    nl_spectrum_fft2_plan_free(plan);
    free(x); free(F); free(back); free(H); free(P); free(Fd); free(R);
  }
  gsl_rng_free(r);
  static const char *what[] = {"fft2", "rfft2", "inverse", "power2", "radial"};
  for (int k = 0; k < 5; k++) {
    printf("  %-8s max error / bound %.3g\n", what[k], worst[k]);
    NL_CHECK(worst[k] <= 1);
  }
}

NL_TEST(psd1_matches_the_dft)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 1807);
  static const int extra[] = {97, 100, 128, 255, 256};
  const long double two_pi = 6.283185307179586476925286766559005768L;
  for (int t = 0; t < 63 + 5; t++) {
    int n = t < 63 ? 2 + t : extra[t - 63];
    size_t m = (size_t)n / 2 + 1;
    double *x = malloc((size_t)n * sizeof *x), *xw = malloc((size_t)n * sizeof *xw);
    double *f = malloc(m * sizeof *f), *P = malloc(m * sizeof *P);
    long double *R = malloc(2 * (size_t)n * sizeof *R);
    for (int win = 0; win < 2; win++) {
      double l1 = 0, rate = 0.5 + 3 * gsl_rng_uniform(r);
      for (int j = 0; j < n; j++) {
        x[j] = 2 * gsl_rng_uniform(r) - 1;
        xw[j] = win ? (double)(x[j] * (1 - cosl(two_pi * j / n)) / 2) : x[j];
        l1 += fabs(xw[j]);
      }
      NL_CHECK(nl_spectrum_psd1_window(x, (size_t)n, rate,
                                       win ? NL_SPECTRUM_HANN : NL_SPECTRUM_RECT, f, P,
                                       NULL) == NL_OK);
      direct_dft2(xw, n, 1, R);
      double bound = 1e-15 * (2 + factor_sum(n)) * l1 + 4 * 0x1p-52 * l1;
      double pscale = 2 * 2 * bound / l1 * (l1 / n) * (l1 / n) / (win ? 0.375 : 1);
      for (size_t k = 0; k < m; k++) {
        long double pw = (R[2 * k] * R[2 * k] + R[2 * k + 1] * R[2 * k + 1]) / ((long double)n * n);
        if (k > 0 && 2 * k != (size_t)n)
          pw *= 2;
        if (win)
          pw /= 0.375L;
        note(5, fabsl(P[k] - pw), pscale);
        NL_CHECK_NEAR(f[k], (double)((long double)k * rate / n), 1e-15 * f[k]);
      }
    }
    free(x); free(xw); free(f); free(P); free(R);
  }
  gsl_rng_free(r);
  printf("  psd1     max error / bound %.3g\n", worst[5]);
  NL_CHECK(worst[5] <= 1);
}

int main(void) { return nl_test_run(); }
