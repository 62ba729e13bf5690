/* Procedural exemplars (nl_byexample_exemplar): textures the harness can make
 * itself, with known statistics (the photographs are in data/exemplars). Features are sized in pixels (one
 * noise unit = 128 pixels), so a larger exemplar shows more of the texture,
 * not a magnified one. */
#include "byexample/nl_byexample.h"
#include "noise/nl_noise.h"
#include "texture/nl_texture.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define UNIT_PIXELS 128.0

static double *fractal(int size, unsigned long seed, int turbulence)
{
  nl_noise_perm3 perm;
  nl_noise_perm3_seed(&perm, seed);
  nl_noise_basis b = nl_noise_basis_perm3(&perm);
  nl_noise_octaves o = nl_noise_octaves_fbm(6, 0.5, 2.0);
  o.turbulence = turbulence;
  for (int l = 0; l < o.n; l++) o.freq[l] *= 2;   /* lowest octave: 64-pixel features */
  nl_noise_window win = {0.0, 0.0, 0.37, size / UNIT_PIXELS, size, size};
  double *v = nl_xmalloc((size_t)size * size * sizeof *v);
  nl_noise_fractal_grid(&b, &o, &win, v);
  return v;
}

/* Sky blue to white, clipped at both ends: a skewed, two-spiked histogram. */
static nl_image *clouds(int size, unsigned long seed)
{
  double *v = fractal(size, seed, 0);
  const double pos[] = {0, 1};
  const float rgb[][3] = {{0.22f, 0.42f, 0.80f}, {0.97f, 0.97f, 1.0f}};
  nl_texture_ramp r = nl_texture_ramp_linear(2, pos, rgb);
  nl_image *im = nl_texture_ramp_image(&r, v, size, size, -0.25, 0.55);
  free(v);
  return im;
}

static nl_image *granite(int size, unsigned long seed)
{
  double *v = fractal(size, seed, 1);
  const double pos[] = {0, 0.3, 0.6, 1};
  const float rgb[][3] = {{0.10f, 0.08f, 0.08f}, {0.55f, 0.42f, 0.40f},
                          {0.80f, 0.72f, 0.68f}, {0.95f, 0.93f, 0.90f}};
  nl_texture_ramp r = nl_texture_ramp_linear(4, pos, rgb);
  nl_image *im = nl_texture_ramp_image(&r, v, size, size, 0.0, 1.0);
  free(v);
  return im;
}

static nl_image *marble(int size, unsigned long seed)
{
  nl_noise_perm3 perm;
  nl_noise_perm3_seed(&perm, seed);
  nl_noise_basis b = nl_noise_basis_perm3(&perm);
  nl_noise_octaves o = nl_noise_octaves_fbm(6, 0.5, 2.0);
  nl_noise_window win = {0.0, 0.0, 0.37, size / UNIT_PIXELS, size, size};
  double *u = nl_xmalloc((size_t)size * size * sizeof *u);
  nl_texture_marble_grid(&b, &o, &win, NL_TWO_PI, 1.5, u);
  nl_texture_ramp r = nl_texture_ramp_marble();
  nl_image *im = nl_texture_ramp_image(&r, u, size, size, 0.0, 1.0);
  free(u);
  return im;
}

/* Three multiresolution wavelet noises with different spectra, mixed by a
 * correlated colour matrix: the texture class the method models exactly. */
static nl_image *wavelet(int size, unsigned long seed)
{
  static const double mix[3][3] = {{0.11, 0.05, 0.02}, {0.09, -0.04, 0.03}, {0.06, -0.02, -0.05}};
  static const double base[3] = {0.55, 0.45, 0.32}, peak[3] = {2.5, 1.0, 4.0};
  int nb = nl_byexample_band_count(size, size);
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(2, NL_BYEXAMPLE_TILE);
  nl_wavelet_tile_seed(t, seed);
  double *ch[3];
  size_t n = (size_t)size * size;
  for (int c = 0; c < 3; c++) {
    double w[NL_WAVELET_MAX_BANDS];
    for (int k = 0; k < nb; k++) w[k] = exp(-(k - peak[c]) * (k - peak[c]) / 3.0) / 0.53;
    nl_wavelet_bands b;
    nl_wavelet_bands_init(&b, nb, w, t->n, nl_seed_stream(seed, "exemplar.channel", (unsigned long)c), NULL);
    ch[c] = nl_xmalloc(n * sizeof(double));
    nl_wavelet_bands_grid(t, &b, size, size, 0, 1, ch[c]);
  }
  nl_image *im = nl_image_alloc(size, size, 3);
  for (size_t i = 0; i < n; i++)
    for (int r = 0; r < 3; r++) {
      double s = base[r];
      for (int c = 0; c < 3; c++) s += mix[r][c] * ch[c][i];
      im->data[3 * i + r] = (float)s;
    }
  for (int c = 0; c < 3; c++) free(ch[c]);
  nl_wavelet_tile_free(t);
  return im;
}

nl_image *nl_byexample_exemplar(const char *kind, int size, unsigned long seed)
{
  if (size < 1) return NULL;
  if (!strcmp(kind, "clouds")) return clouds(size, seed);
  if (!strcmp(kind, "granite")) return granite(size, seed);
  if (!strcmp(kind, "marble")) return marble(size, seed);
  if (!strcmp(kind, "wavelet")) return wavelet(size, seed);
  return NULL;
}
