#include "spectrum/nl_spectrum.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_fft_complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

double nl_fft_freq(int u, int n) { return (double)(2 * u < n ? u : u - n) / n; }

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

void nl_fft2(const double *img, int w, int h, double *F)
{
  for (size_t k = 0; k < (size_t)w * h; k++) { F[2 * k] = img[k]; F[2 * k + 1] = 0; }
  fft2_inplace(F, w, h, gsl_fft_forward);
}

void nl_fft2_inverse(const double *F, int w, int h, double *img)
{
  size_t n = (size_t)w * h;
  double *G = nl_xmalloc(2 * n * sizeof *G);
  memcpy(G, F, 2 * n * sizeof *G);
  fft2_inplace(G, w, h, gsl_fft_backward);
  for (size_t k = 0; k < n; k++) img[k] = G[2 * k] / (double)n;
  free(G);
}

void nl_power2(const double *img, int w, int h, double *P)
{
  size_t n = (size_t)w * h;
  double *F = nl_xmalloc(2 * n * sizeof *F);
  nl_fft2(img, w, h, F);
  double s = 1.0 / ((double)n * (double)n);
  for (size_t k = 0; k < n; k++) P[k] = (F[2 * k] * F[2 * k] + F[2 * k + 1] * F[2 * k + 1]) * s;
  free(F);
}

void nl_radial_power(const double *img, int w, int h, int nbins, double *f, double *p)
{
  size_t n = (size_t)w * h;
  double *P = nl_xmalloc(n * sizeof *P);
  size_t *count = nl_xcalloc((size_t)nbins, sizeof *count);
  nl_power2(img, w, h, P);
  for (int b = 0; b < nbins; b++) { p[b] = 0; f[b] = (b + 0.5) * 0.5 / nbins; }
  for (int v = 0; v < h; v++)
    for (int u = 0; u < w; u++) {
      double fu = nl_fft_freq(u, w), fv = nl_fft_freq(v, h);
      int b = (int)(sqrt(fu * fu + fv * fv) / 0.5 * nbins);
      if (b >= nbins) continue;
      p[b] += P[(size_t)v * w + u];
      count[b]++;
    }
  for (int b = 0; b < nbins; b++) if (count[b]) p[b] /= (double)count[b];
  free(P); free(count);
}
