#include "spectrum/nl_spectrum.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_fft_complex.h>
#include <gsl/gsl_fft_real.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

double nl_spectrum_freq(int u, int n) { return (double)(2 * u < n ? u : u - n) / n; }

/* Transforms every line of a complex w x h array along one axis, in place.
 * stride/dist in complex elements: rows (1, w), columns (w, 1). */
static void fft_lines(double *F, int len, int count, size_t stride, size_t dist, gsl_fft_direction dir)
{
  gsl_fft_complex_wavetable *wt = gsl_fft_complex_wavetable_alloc((size_t)len);
  gsl_fft_complex_workspace *ws = gsl_fft_complex_workspace_alloc((size_t)len);
  for (int k = 0; k < count; k++)
    gsl_fft_complex_transform(F + 2 * dist * k, stride, (size_t)len, wt, ws, dir);
  gsl_fft_complex_workspace_free(ws);
  gsl_fft_complex_wavetable_free(wt);
}

static void fft2_inplace(double *F, int w, int h, gsl_fft_direction dir)
{
  fft_lines(F, w, h, 1, (size_t)w, dir);
  fft_lines(F, h, w, (size_t)w, 1, dir);
}

void nl_spectrum_fft2(const double *img, int w, int h, double *F)
{
  for (size_t k = 0; k < (size_t)w * h; k++) { F[2 * k] = img[k]; F[2 * k + 1] = 0; }
  fft2_inplace(F, w, h, gsl_fft_forward);
}

void nl_spectrum_fft2_inverse(const double *F, int w, int h, double *img)
{
  size_t n = (size_t)w * h;
  double *G = nl_xmalloc(2 * n * sizeof *G);
  memcpy(G, F, 2 * n * sizeof *G);
  fft2_inplace(G, w, h, gsl_fft_backward);
  for (size_t k = 0; k < n; k++) img[k] = G[2 * k] / (double)n;
  free(G);
}

void nl_spectrum_power2(const double *img, int w, int h, double *P)
{
  size_t n = (size_t)w * h;
  double *F = nl_xmalloc(2 * n * sizeof *F);
  nl_spectrum_fft2(img, w, h, F);
  double s = 1.0 / ((double)n * (double)n);
  for (size_t k = 0; k < n; k++) P[k] = (F[2 * k] * F[2 * k] + F[2 * k + 1] * F[2 * k + 1]) * s;
  free(F);
}

void nl_spectrum_radial(const double *img, int w, int h, int nbins, double *f, double *p)
{
  size_t n = (size_t)w * h;
  double *P = nl_xmalloc(n * sizeof *P);
  size_t *count = nl_xcalloc((size_t)nbins, sizeof *count);
  nl_spectrum_power2(img, w, h, P);
  for (int b = 0; b < nbins; b++) { p[b] = 0; f[b] = (b + 0.5) * 0.5 / nbins; }
  for (int v = 0; v < h; v++)
    for (int u = 0; u < w; u++) {
      double fu = nl_spectrum_freq(u, w), fv = nl_spectrum_freq(v, h);
      int b = (int)(sqrt(fu * fu + fv * fv) / 0.5 * nbins);
      if (b >= nbins) continue;
      p[b] += P[(size_t)v * w + u];
      count[b]++;
    }
  for (int b = 0; b < nbins; b++) if (count[b]) p[b] /= (double)count[b];
  free(P); free(count);
}

/* Tukey window of n samples, taper fraction frac: sin^2 over the outer frac/2 of each side. */
static double taper(int x, int n, double frac)
{
  double u = (x + 0.5) / n, e = frac / 2;   /* position in (0, 1), edge width */
  if (u > e && u < 1 - e) return 1;
  double s = sin(NL_PI * fmin(u, 1 - u) / (2 * e));
  return s * s;
}

void nl_spectrum_taper2(const double *img, int w, int h, double frac, double *out)
{
  size_t n = (size_t)w * h;
  double *hx = nl_xmalloc((size_t)w * sizeof *hx), *hy = nl_xmalloc((size_t)h * sizeof *hy);
  double mean = 0, sx = 0, sy = 0;
  for (size_t k = 0; k < n; k++) mean += img[k];
  mean /= (double)n;
  for (int x = 0; x < w; x++) { hx[x] = taper(x, w, frac); sx += hx[x] * hx[x]; }
  for (int y = 0; y < h; y++) { hy[y] = taper(y, h, frac); sy += hy[y] * hy[y]; }
  double norm = 1.0 / sqrt(sx / w * sy / h);   /* the window's power, measured (not 9/64) */
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      size_t k = (size_t)y * w + x;
      out[k] = (img[k] - mean) * hx[x] * hy[y] * norm;
    }
  free(hx);
  free(hy);
}

void nl_spectrum_hann2(const double *img, int w, int h, double *out) { nl_spectrum_taper2(img, w, h, 1.0, out); }

/* ---- 1D --------------------------------------------------------------- */

nl_status nl_spectrum_psd1(const double *x, size_t n, double rate, double *f, double *P, nl_error *err)
{
  if (n < 2 || !(rate > 0.0)) return nl_fail(err, NL_EINVAL, "psd1: need n >= 2 and rate > 0");
  double *d = nl_xmalloc(n * sizeof *d);
  memcpy(d, x, n * sizeof *d);
  gsl_fft_real_wavetable *wt = gsl_fft_real_wavetable_alloc(n);
  gsl_fft_real_workspace *ws = gsl_fft_real_workspace_alloc(n);
  int gs = gsl_fft_real_transform(d, 1, n, wt, ws);
  gsl_fft_real_workspace_free(ws);
  gsl_fft_real_wavetable_free(wt);
  if (gs) { free(d); return nl_fail(err, NL_ENUM, "psd1: %s", gsl_strerror(gs)); }
  /* Half-complex layout: d[0] = X_0, (d[2k-1], d[2k]) = X_k, d[n-1] = X_{n/2}
   * for even n. |X_k|^2 / n^2 per two-sided bin (Parseval, eq. 4.4, over
   * n^2 so that the sum is the mean square); folded to one side. */
  double nn = (double)n * (double)n;
  size_t m = n / 2 + 1;
  for (size_t k = 0; k < m; k++) {
    double re, im = 0.0;
    if (k == 0) re = d[0];
    else if (2 * k == n) re = d[n - 1];
    else { re = d[2 * k - 1]; im = d[2 * k]; }
    double two_sided = (re * re + im * im) / nn;
    P[k] = (k == 0 || 2 * k == n) ? two_sided : 2.0 * two_sided;
    f[k] = (double)k * rate / (double)n;
  }
  free(d);
  return NL_OK;
}

nl_status nl_spectrum_psd1_window(const double *x, size_t n, double rate, int window, double *f, double *P,
                                  nl_error *err)
{
  if (window == NL_SPECTRUM_RECT) return nl_spectrum_psd1(x, n, rate, f, P, err);
  if (window != NL_SPECTRUM_HANN) return nl_fail(err, NL_EINVAL, "psd1: unknown window %d", window);
  if (n < 2) return nl_fail(err, NL_EINVAL, "psd1: need n >= 2 and rate > 0");
  double *w = nl_xmalloc(n * sizeof *w), pi2 = 2.0 * acos(-1.0);
  for (size_t j = 0; j < n; j++) w[j] = x[j] * 0.5 * (1.0 - cos(pi2 * (double)j / (double)n));
  nl_status rc = nl_spectrum_psd1(w, n, rate, f, P, err);
  free(w);
  if (!rc)   /* the periodic Hann window's mean square is exactly 3/8 */
    for (size_t k = 0; k < n / 2 + 1; k++) P[k] /= 0.375;
  return rc;
}
