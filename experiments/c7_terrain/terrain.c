/* C7's terrain (Cheng 2009 sec. 4.5): height maps and patterns as matrix
 * tables for gnuplot, and the height shaded as relief. */
#include "c7.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

nl_table *c7_matrix_table(const double *v, int w, int h)
{
  char (*names)[16] = nl_xmalloc((size_t)w * sizeof *names);
  const char **cols = nl_xmalloc((size_t)w * sizeof *cols);
  for (int x = 0; x < w; x++) {
    snprintf(names[x], sizeof names[x], "c%d", x);
    cols[x] = names[x];
  }
  nl_table *t = nl_table_alloc((size_t)w, cols);
  for (int y = 0; y < h; y++) nl_table_append_doubles(t, v + (size_t)y * w);
  free(cols);
  free(names);
  return t;
}

nl_table *c7_pattern_table(const nl_cheng_pattern *p)
{
  size_t n = (size_t)p->grid * (size_t)p->grid;
  double *v = nl_xmalloc(n * sizeof *v);
  for (size_t i = 0; i < n; i++) v[i] = -1;
  for (size_t i = 0; i < p->n; i++) v[p->cell[i]] = p->d[i];
  nl_table *t = c7_matrix_table(v, p->grid, p->grid);
  free(v);
  return t;
}

nl_image *c7_relief_image(const double *z, int w, int h, double zscale)
{
  /* Light direction (towards the light): from the north-west (x -1, y -1 in
   * image rows growing down), 45 degrees above the horizon. */
  const double lx = -0.5, ly = -0.5, lz = sqrt(0.5);
  nl_image *im = nl_image_alloc(w, h, 3);
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      /* central differences, one-sided at the border */
      int x0 = x > 0 ? x - 1 : x;
      int x1 = x + 1 < w ? x + 1 : x;
      int y0 = y > 0 ? y - 1 : y;
      int y1 = y + 1 < h ? y + 1 : y;
      /* slopes per unit length of the unit square */
      double dzdx = zscale * (z[(size_t)y * w + x1] - z[(size_t)y * w + x0]) * w / (x1 - x0);
      double dzdy = zscale * (z[(size_t)y1 * w + x] - z[(size_t)y0 * w + x]) * h / (y1 - y0);
      double nn = sqrt(dzdx * dzdx + dzdy * dzdy + 1);
      double shade = (-dzdx * lx - dzdy * ly + lz) / nn;
      shade = shade < 0 ? 0 : shade;
      /* hypsometric tint by height (0..1), times the shade */
      double t = z[(size_t)y * w + x];
      double r = 0.25 + 0.6 * t;
      double g = 0.45 + 0.3 * t;
      double b = 0.25 + 0.5 * t;
      float *px = nl_image_pixel(im, x, y);
      px[0] = (float)fmin(1, r * (0.25 + 0.85 * shade));
      px[1] = (float)fmin(1, g * (0.25 + 0.85 * shade));
      px[2] = (float)fmin(1, b * (0.25 + 0.85 * shade));
    }
  return im;
}
