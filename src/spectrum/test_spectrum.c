#include "spectrum/nl_spectrum.h"
#include "nl_test.h"

#include <stdlib.h>
#include <string.h>

NL_TEST(parseval_and_round_trip_odd_size)
{
  int w = 30, h = 17;   /* not powers of two */
  size_t n = (size_t)w * h;
  double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *P = malloc(n * sizeof *P);
  double *F = malloc(2 * n * sizeof *F), ms = 0, sp = 0;
  srand(3);
  for (size_t k = 0; k < n; k++) { x[k] = rand() / (double)RAND_MAX - 0.3; ms += x[k] * x[k] / n; }
  NL_CHECK(nl_spectrum_power2(x, w, h, P, NULL) == NL_OK);
  for (size_t k = 0; k < n; k++) sp += P[k];
  NL_CHECK_NEAR(sp, ms, 1e-12);
  NL_CHECK(nl_spectrum_fft2(x, w, h, F, NULL) == NL_OK);
  NL_CHECK(nl_spectrum_fft2_inverse(F, w, h, y, NULL) == NL_OK);
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
  NL_CHECK(nl_spectrum_radial(x, w, h, nb, f, p, NULL) == NL_OK);
  int best = 0;
  for (int b = 1; b < nb; b++) if (p[b] > p[best]) best = b;
  NL_CHECK(best == 8);    /* 0.125 / 0.5 * 32 */
  NL_CHECK_NEAR(f[8], 8.5 / 64, 1e-15);
  NL_CHECK_NEAR(nl_spectrum_freq(63, 64), -1.0 / 64, 0);
  free(x);
}


/* The Hann taper: a checkerboard of +-1 (mean 0, variance 1) keeps mean
 * square 1 exactly (the power normalisation); a constant goes to 0; a
 * cosine of 2.5 cycles per 64 pixels (not periodic in the image) puts
 * far less of its power beyond 1/4 cycle per pixel once tapered. */
NL_TEST(hann_power_and_leakage)
{
  int w = 64, h = 48;
  size_t n = (size_t)w * h;
  double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *P = malloc(n * sizeof *P), ms = 0;
  for (int r = 0; r < h; r++)
    for (int c = 0; c < w; c++) x[r * w + c] = (r + c) % 2 ? 1.0 : -1.0;
  nl_spectrum_hann2(x, w, h, y);
  for (size_t k = 0; k < n; k++) ms += y[k] * y[k] / (double)n;
  NL_CHECK_NEAR(ms, 1.0, 1e-12);
  for (size_t k = 0; k < n; k++) x[k] = 3.5;
  nl_spectrum_hann2(x, w, h, y);
  double worst = 0;
  for (size_t k = 0; k < n; k++) worst = fmax(worst, fabs(y[k]));
  NL_CHECK(worst < 1e-12);
  double far[3] = {0, 0, 0};   /* raw, Hann, Tukey 1/4 */
  for (int t = 0; t < 3; t++) {
    for (int r = 0; r < h; r++)
      for (int c = 0; c < w; c++) x[r * w + c] = cos(NL_TWO_PI * 2.5 * c / w);
    if (t) nl_spectrum_taper2(x, w, h, t == 1 ? 1.0 : 0.25, x);
    NL_CHECK(nl_spectrum_power2(x, w, h, P, NULL) == NL_OK);
    double tot = 0;
    for (int v = 0; v < h; v++)
      for (int u = 0; u < w; u++) {
        double m = fmax(fabs(nl_spectrum_freq(u, w)), fabs(nl_spectrum_freq(v, h)));
        if (m == 0) continue;
        tot += P[v * w + u];
        if (m > 0.25) far[t] += P[v * w + u];
      }
    far[t] /= tot;
  }
  printf("  power beyond 1/4 c/px: raw %.3g, Hann %.3g, Tukey 1/4 %.3g\n", far[0], far[1], far[2]);
  /* measured 0.0191 raw, 6.2e-8 Hann, 1.9e-5 Tukey 1/4 (64 x 48) */
  NL_CHECK(far[0] > 1e-4);
  NL_CHECK(far[1] < 1e-3 * far[0]);
  NL_CHECK(far[2] < 0.1 * far[0]);
  /* Hann is the Tukey window with fraction 1; Tukey keeps the power normalisation */
  for (int r = 0; r < h; r++)
    for (int c = 0; c < w; c++) x[r * w + c] = (r + c) % 2 ? 1.0 : -1.0;
  nl_spectrum_hann2(x, w, h, y);
  nl_spectrum_taper2(x, w, h, 1.0, P);
  worst = 0;
  for (size_t k = 0; k < n; k++) worst = fmax(worst, fabs(y[k] - P[k]));
  NL_CHECK(worst == 0);
  nl_spectrum_taper2(x, w, h, 0.25, y);
  ms = 0;
  for (size_t k = 0; k < n; k++) ms += y[k] * y[k] / (double)n;
  NL_CHECK_NEAR(ms, 1.0, 1e-12);
  free(x); free(y); free(P);
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

/* The real-input radix-4 path (power-of-two sides) against the DFT summed
 * directly (long double), on shapes that exercise each stage kind: radix-4
 * only (16 x 64), a final radix-2 (32 x 8, 2 x 128), a single row (8 x 1),
 * an odd number of row pairs (4 x 2). The plan is reused across images. */
NL_TEST(real_path_matches_direct_dft)
{
  int shapes[][2] = {{16, 64}, {32, 8}, {2, 128}, {8, 1}, {4, 2}};
  srand(7);
  double worst = 0;
  for (size_t sidx = 0; sidx < sizeof shapes / sizeof shapes[0]; sidx++) {
    int w = shapes[sidx][0], h = shapes[sidx][1], m = w / 2 + 1;
    size_t n = (size_t)w * h;
    double *x = malloc(n * sizeof *x), *F = malloc(2 * n * sizeof *F), *H = malloc(2 * (size_t)m * h * sizeof *H);
    nl_spectrum_fft2_plan *p = nl_spectrum_fft2_plan_alloc(w, h, NULL);
    for (int rep = 0; rep < 2; rep++) {
      for (size_t k = 0; k < n; k++) x[k] = rand() / (double)RAND_MAX - 0.5;
      NL_CHECK(nl_spectrum_fft2(x, w, h, F, NULL) == NL_OK);
      nl_spectrum_rfft2(p, x, H);
      for (int v = 0; v < h; v++)
        for (int u = 0; u < w; u++) {
          long double re = 0, im = 0;
          for (int y = 0; y < h; y++)
            for (int c = 0; c < w; c++) {
              long double a = -2.0L * 3.14159265358979323846264338327950288L *
                              ((long double)u * c / w + (long double)v * y / h);
              re += x[(size_t)y * w + c] * cosl(a);
              im += x[(size_t)y * w + c] * sinl(a);
            }
          size_t k = (size_t)v * w + u;
          worst = fmax(worst, fmax(fabs(F[2 * k] - (double)re), fabs(F[2 * k + 1] - (double)im)));
          if (u < m) NL_CHECK(H[2 * ((size_t)v * m + u)] == F[2 * k] && H[2 * ((size_t)v * m + u) + 1] == F[2 * k + 1]);
        }
    }
    nl_spectrum_fft2_plan_free(p);
    free(x); free(F); free(H);
  }
  printf("  radix-4 real path: worst |F - direct DFT| %.3g (values of |F| up to ~sqrt(w h))\n", worst);
  NL_CHECK(worst < 1e-12);   /* measured 1.1e-14 */
}

/* Sides with a large prime factor make GSL's transform O(n^2): refused
 * above the cost limit with the side, its factor and a length to crop to;
 * smooth sizes of any size pass. */
NL_TEST(awkward_sizes_refused)
{
  nl_error err = {{0}};
  NL_CHECK(nl_spectrum_fft2_cost(16, 65536) == 16.0 * 65536 * (2 * 16 + 2 * 4));
  NL_CHECK(nl_spectrum_check_size(65521, 16, &err) == NL_EINVAL);
  NL_CHECK(strstr(err.msg, "width 65521 has the prime factor 65521") != NULL);
  NL_CHECK(strstr(err.msg, "crop it to 65520 x 16") != NULL);
  NL_CHECK(nl_spectrum_check_size(4096, 4093, &err) == NL_EINVAL && strstr(err.msg, "height 4093"));
  NL_CHECK(nl_spectrum_check_size(16, 65536, &err) == NL_OK);
  /* 776 = 8 x 97 has factors within the bound, 65474 = 2 x 19 x 1723 not:
   * only the height is cropped */
  NL_CHECK(nl_spectrum_check_size(776, 65474, &err) == NL_EINVAL);
  NL_CHECK(strstr(err.msg, "height 65474") != NULL);
  NL_CHECK(strstr(err.msg, "crop it to 776 x 65472") != NULL);
  /* The bound (nl_spectrum.h): S3's --set size=1021 (1.9 s per transform,
   * 205 times 1024's) and 509 (0.22 s) refused; a factor of 73 or 127 at
   * any size, and a cheap prime side, pass. */
  NL_CHECK(nl_spectrum_check_size(1021, 1021, &err) == NL_EINVAL &&
           strstr(err.msg, "width 1021 has the prime factor 1021 (beyond 127)"));
  NL_CHECK(nl_spectrum_check_size(509, 509, &err) == NL_EINVAL);
  NL_CHECK(nl_spectrum_check_size(1022, 1022, &err) == NL_OK);
  NL_CHECK(nl_spectrum_check_size(127 * 64, 127 * 32, &err) == NL_OK);
  NL_CHECK(nl_spectrum_check_size(257, 257, &err) == NL_OK);
  /* On a line (psd1): n times the sum of n's factors. */
  NL_CHECK(nl_spectrum_check_length(65536, &err) == NL_OK);
  NL_CHECK(nl_spectrum_check_length(10007, &err) == NL_OK);    /* prime: 1e8 operations */
  NL_CHECK(nl_spectrum_check_length(65521, &err) == NL_EINVAL && strstr(err.msg, "use 65520"));
  double x[8] = {0}, f[8], P[8];
  NL_CHECK(nl_spectrum_psd1(x, 65521, 1.0, f, P, &err) == NL_EINVAL);   /* refused before reading x */
  /* Every 2D transform refuses such a size itself, before any work (one
   * 1021 x 1021 transform is 1.9 s): no caller can skip the guard. */
  size_t n = (size_t)1021 * 1021;
  double *img = nl_xcalloc(2 * n, sizeof *img), *out = nl_xmalloc(2 * n * sizeof *out), rf[510], rp[510];
  double t0 = nl_time_now();
  NL_CHECK(nl_spectrum_fft2_plan_alloc(1021, 1021, &err) == NULL && strstr(err.msg, "prime factor 1021"));
  NL_CHECK(nl_spectrum_fft2(img, 1021, 1021, out, &err) == NL_EINVAL);
  NL_CHECK(nl_spectrum_fft2_inverse(img, 1021, 1021, out, &err) == NL_EINVAL);
  NL_CHECK(nl_spectrum_power2(img, 1021, 1021, out, &err) == NL_EINVAL);
  NL_CHECK(nl_spectrum_radial(img, 1021, 1021, 510, rf, rp, &err) == NL_EINVAL);
  NL_CHECK(strstr(err.msg, "1021 x 1021 pixels: width 1021") != NULL);
  NL_CHECK(nl_time_now() - t0 < 0.5);
  free(img);
  free(out);
  NL_CHECK(nl_spectrum_check_size(16384, 16384, &err) == NL_OK);
  NL_CHECK(nl_spectrum_check_size(15000, 15000, &err) == NL_OK);
  NL_CHECK(nl_spectrum_check_size(512, 509, &err) == NL_OK);
}
