/* Control patterns (sec. 3.4.1, Fig 3.7): black = 0, red = 1 from the red
 * channel, alpha 0 = no control. Reading PNGs and the built-in shapes are on
 * the harness side (src/study/nl_study_cheng_image.c): this module sees pixels only. */
#include "cheng/nl_cheng_internal.h"

#include <stdlib.h>

/* A borrowed interleaved float raster, row 0 at the top (nl_image's layout). */
typedef struct { const float *data; int width, height, channels; } nl_pixels;

/* Red and alpha of a pixel for 1 (grey), 2 (grey+alpha), 3 (RGB), 4 (RGBA) channels. */
static void red_alpha(const nl_pixels *im, int x, int y, double *red, double *alpha)
{
  const float *px = im->data + ((size_t)y * im->width + x) * im->channels;
  *red = px[0];
  *alpha = im->channels == 2 ? px[1] : im->channels == 4 ? px[3] : 1.0;
}

/* Mean alpha and alpha-weighted mean red of the pixels of cell (r, c); at
 * least the pixel under the cell centre when the image is smaller than the grid. */
static void cell_mean(const nl_pixels *im, int grid, int r, int c, double *d, double *alpha)
{
  int W = im->width, H = im->height;
  int x0 = c * W / grid, x1 = ((c + 1) * W + grid - 1) / grid;
  int y0 = r * H / grid, y1 = ((r + 1) * H + grid - 1) / grid;
  if (x1 <= x0) x1 = x0 + 1;
  if (y1 <= y0) y1 = y0 + 1;
  double sa = 0, sr = 0;
  for (int y = y0; y < y1 && y < H; y++)
    for (int x = x0; x < x1 && x < W; x++) {
      double red, a;
      red_alpha(im, x, y, &red, &a);
      sa += a;
      sr += a * red;
    }
  double npx = (double)(x1 - x0) * (y1 - y0);
  *alpha = sa / npx;
  *d = sa > 0 ? sr / sa : 0.0;
  if (*d < 0) *d = 0;
  if (*d > 1) *d = 1;
}

nl_status nl_cheng_pattern_from_pixels(const float *data, int width, int height, int channels,
                                       int grid, nl_cheng_pattern **out, nl_error *err)
{
  *out = NULL;
  if (width < 1 || height < 1 || channels < 1 || channels > 4)
    return nl_fail(err, NL_EINVAL, "pattern image %d x %d x %d: not a grey, grey+alpha, RGB or RGBA image",
                   width, height, channels);
  const nl_pixels px = {data, width, height, channels}, *im = &px;
  if (grid < 1 || grid > 4096) return nl_fail(err, NL_EINVAL, "control grid %d out of range 1..4096", grid);
  /* D is a fraction of the way from black to red (Fig 3.7) and alpha a
   * weight: a float file's 1.5 or -0.2 is neither, and the cell mean would
   * clamp it away unseen. */
  for (int y = 0; y < height; y++)
    for (int x = 0; x < width; x++) {
      double v[2];
      red_alpha(im, x, y, &v[0], &v[1]);
      for (int k = 0; k < 2; k++)
        if (!(v[k] >= 0 && v[k] <= 1))
          return nl_fail(err, NL_EINVAL, "pixel (%d, %d): %s %g is outside [0, 1]", x, y,
                         k ? "alpha" : channels < 3 ? "grey" : "red", v[k]);
    }
  size_t cap = (size_t)grid * grid;
  nl_cheng_pattern *p = nl_xcalloc(1, sizeof *p);
  p->grid = grid;
  p->x = nl_xmalloc(cap * sizeof *p->x);
  p->y = nl_xmalloc(cap * sizeof *p->y);
  p->d = nl_xmalloc(cap * sizeof *p->d);
  p->cell = nl_xmalloc(cap * sizeof *p->cell);
  for (int r = 0; r < grid; r++)
    for (int c = 0; c < grid; c++) {
      double d, a;
      cell_mean(im, grid, r, c, &d, &a);
      if (a < 0.5) continue;
      p->x[p->n] = (c + 0.5) / grid;
      p->y[p->n] = (r + 0.5) / grid;
      p->d[p->n] = d;
      p->cell[p->n++] = r * grid + c;
    }
  if (p->n == 0) {
    nl_cheng_pattern_free(p);
    return nl_fail(err, NL_EINVAL, "pattern has no control pixels (all transparent)");
  }
  *out = p;
  return NL_OK;
}

void nl_cheng_pattern_free(nl_cheng_pattern *p)
{
  if (!p) return;
  free(p->x); free(p->y); free(p->d); free(p->cell); free(p);
}

