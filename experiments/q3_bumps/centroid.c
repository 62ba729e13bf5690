/* centroid.c - Q3: where a bump height's power lies, and eq. 6 without
 * its frequency doubling. */
#include "q3.h"

#include "spectrum/nl_spectrum.h"

#include <math.h>
#include <stdlib.h>

double q3_centroid(const double *h, int w, double extent)
{
  size_t n = (size_t)w * w;
  int nb = w / 2;
  double *c = nl_xmalloc(n * sizeof *c), *f = nl_xmalloc(2 * (size_t)nb * sizeof *f), *p = f + nb;
  double m = 0;
  for (size_t q = 0; q < n; q++) m += h[q] / n;
  for (size_t q = 0; q < n; q++) c[q] = h[q] - m;
  if (nl_spectrum_radial(c, w, w, nb, f, p, NULL)) {   /* w passed nl_harness_param_fft_size */
    free(c);
    free(f);
    return NAN;
  }
  double sp = 0, sfp = 0;
  for (int b = 0; b < nb; b++) {
    sp += p[b];
    sfp += f[b] * p[b];
  }
  free(c);
  free(f);
  return sp > 0 ? sfp / sp * w / extent : 0;
}

void q3_bump_one_scale(const nl_cellular_gctbf_basis *b, int octaves, double k,
                       const nl_noise_window *win, double *out)
{
  nl_noise_basis nb = nl_cellular_basis_gctbf(b);
  nl_noise_octaves o = nl_noise_octaves_fbm(1, 1.0, 1.0);
  o.freq[0] = k;
  size_t n = (size_t)win->w * win->h;
  nl_noise_fractal_grid(&nb, &o, win, out);
  for (size_t q = 0; q < n; q++) {
    double t = fabs(0.5 - out[q]), s = 0;
    for (int i = 0; i <= octaves; i++) s += t / ldexp(1.0, i);
    out[q] = s * s * s;
  }
}
