/* L1's figure: one band of 2D wavelet noise and a slice of 3D noise beside
 * their power spectra, with the radial power profiles and the band's edges
 * that the figure's caption reads. */
#include "report.h"
#include "study/nl_study.h"
#include "variance.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int l1_band_figure(nl_harness *r, nl_wavelet_tile *t2, nl_wavelet_tile *t3,
                   const l1_setting *c, int band)
{
  int size = c->size, tile3 = c->tile3;
  unsigned long seed0 = c->seed0;
  nl_wavelet_tile_seed(t2, seed0);
  nl_wavelet_tile_seed(t3, seed0);
  double w[NL_WAVELET_MAX_BANDS] = { 0 };
  w[band] = 1;
  nl_wavelet_bands b;
  nl_wavelet_bands_init(&b, band + 1, w, c->tile, seed0, NULL);
  double *img2 = malloc((size_t)size * size * sizeof *img2);
  double *img3 = malloc((size_t)size * size * sizeof *img3);
  nl_wavelet_bands_grid(t2, &b, size, size, 0, 1, img2);
  nl_wavelet_bands_init(&b, band + 1, w, tile3, seed0, NULL);
  nl_wavelet_bands_grid(t3, &b, size, size, 3.3, 1, img3);
  /* (b) and (d) show one period of the 3D tile at most: a wider window repeats it */
  int w3 = size < (tile3 << band) ? size : tile3 << band;
  double *win3 = l1_window(img3, size, w3);
  nl_error err;
  nl_image *im[4] = { nl_image_from_values(img2, size, size, -1.5, 1.5),
                      nl_image_from_values(win3, w3, w3, -1.5, 1.5),
                      nl_byexample_spectrum_image(img2, size, size, c->decades, &err), NULL };
  if (im[2]) im[3] = nl_byexample_spectrum_image(win3, w3, w3, c->decades, &err);
  if (!im[2] || !im[3]) nl_harness_die(r, 1, "spectrum figure: %s", err.msg);
  free(win3);
  char lb[64];
  snprintf(lb, sizeof lb, w3 == tile3 << band ? "(b) 3D slice, one period" : "(b) 3D slice, %d px",
           w3);
  const char *labels[] = { "(a) 2D wavelet noise", lb, "(c) power spectrum of (a)",
                           "(d) power spectrum of (b)" };
  char title[96];
  snprintf(title, sizeof title, "One band (k = %d: 1/%d..1/%d cycles per pixel)", band, 4 << band,
           2 << band);
  nl_study_montage(r, (const nl_image *const *)im, labels, 4, 2, title, "noise.png");
  const double *imgs[2] = { img2, img3 };
  nl_table *rt = nl_study_radial_table(imgs, (const char *[]){ "power2d", "power3d" }, 2, size, 0);
  nl_harness_write_table(r, rt, "radial.tsv");
  const char *ecols[] = { "lo", "hi" };
  nl_table *et = nl_table_alloc(2, ecols);
  nl_table_append(et, "dd", ldexp(1.0, -(band + 2)), ldexp(1.0, -(band + 1)));
  nl_harness_write_table(r, et, "edges.tsv");
  nl_table_free(et);
  for (int i = 0; i < 4; i++) nl_image_free(im[i]);
  nl_table_free(rt);
  free(img2);
  free(img3);
  return w3;
}
