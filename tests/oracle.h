/* oracle.h - a figure's panel against what its caption says (tests only).
 *
 * A figure is tested against its caption: the test computes what a panel's
 * caption says by another path than the code that made the figure (the
 * library's point calls, a naive loop, `noiselab render`), maps it as the
 * figure does, and compares it value for value with the panel read back
 * out of the PNG:
 *
 *   int w[4] = {128, 128, 128, 128}, h[4] = {128, 128, 128, 128};
 *   const char *labels[4] = {"(a) 1 octave", ...};
 *   oracle_montage m;
 *   if (oracle_montage_read(&m, "out/fractal_panels.png", w, h, labels, 4, 4, "title")) fail;
 *   double *v = ...;                     // panel 1 by the other path, w x h
 *   oracle_result res = oracle_panel_compare(&m, 1, v, lo, hi);
 *   // res.max_diff <= ORACLE_TOL_8BIT: the panel is that image to 8 bits
 *   oracle_montage_free(&m);
 *
 * The layout is nl_image_montage_layout's for the same sizes, labels,
 * columns and title: a montage of another size is refused (it is not the
 * figure the test describes). The expected values are mapped to grey as
 * nl_image_from_values does (lo -> 0, hi -> 1, clamped) and box-filtered by
 * the montage's reduction factor before the comparison; the panel's first
 * channel is compared (grey panels are replicated to RGB). max_diff is in
 * grey levels of [0, 1]; corr is Pearson's correlation of the two panels,
 * which tells another octave or another seed (|corr| well below 1) from a
 * rounding difference.
 */
#ifndef NL_TESTS_ORACLE_H
#define NL_TESTS_ORACLE_H

#include "image/nl_image.h"
#include "table/nl_table.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* An 8-bit PNG holds a grey level to 0.5/255; the float maps of two paths
 * differ by rounding far below that. One level of slack covers a value that
 * lands on a rounding boundary. */
#define ORACLE_TOL_8BIT (1.0 / 255.0)

typedef struct {
  nl_image *im;
  nl_image_montage_geometry g;
  nl_image_rect *rect;
  int n;
  char err[1200];
} oracle_montage;

typedef struct {
  double max_diff;   /* largest |panel - expected| over the panel's pixels */
  double corr;       /* Pearson correlation of panel and expected */
  int x, y;          /* where max_diff is, in panel pixels */
} oracle_result;

static inline void oracle_montage_free(oracle_montage *m)
{
  nl_image_free(m->im);
  free(m->rect);
  m->im = NULL;
  m->rect = NULL;
}

/* Reads `path` and lays out n panels of widths[i] x heights[i] as the
 * montage did. 0 on success; else 1 and m->err says why. */
static inline int oracle_montage_read(oracle_montage *m, const char *path, const int *widths,
                                      const int *heights, const char *const *labels, int n, int cols,
                                      const char *title)
{
  nl_error err;
  m->im = NULL;
  m->rect = calloc((size_t)n, sizeof *m->rect);
  m->n = n;
  m->err[0] = 0;
  if (nl_image_read(path, &m->im, &err)) {
    snprintf(m->err, sizeof m->err, "%s", err.msg);
    return 1;
  }
  nl_image_montage_layout(widths, heights, labels, n, cols, title, &m->g, m->rect);
  if (m->im->width != m->g.width || m->im->height != m->g.height) {
    snprintf(m->err, sizeof m->err, "%s: %d x %d, the layout described is %d x %d", path, m->im->width,
             m->im->height, m->g.width, m->g.height);
    return 1;
  }
  return 0;
}

/* Panel i of the montage against v (its full-size w x h values, w and h as
 * given to oracle_montage_read), mapped by lo, hi. */
static inline oracle_result oracle_panel_compare(const oracle_montage *m, int i, const double *v, int w,
                                                 int h, double lo, double hi)
{
  nl_image *full = nl_image_from_values(v, w, h, lo, hi);
  nl_image *e = m->g.factor > 1 ? nl_image_downsample(full, m->g.factor) : full;
  const nl_image_rect *r = &m->rect[i];
  oracle_result res = {0, 0, 0, 0};
  double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
  size_t n = 0;
  for (int y = 0; y < r->h && y < e->height; y++)
    for (int x = 0; x < r->w && x < e->width; x++) {
      double a = nl_image_pixel(m->im, r->x + x, r->y + y)[0], b = nl_image_pixel(e, x, y)[0];
      double d = fabs(a - b);
      if (d > res.max_diff) {
        res.max_diff = d;
        res.x = x;
        res.y = y;
      }
      sa += a; sb += b; saa += a * a; sbb += b * b; sab += a * b;
      n++;
    }
  double ca = saa - sa * sa / n, cb = sbb - sb * sb / n;
  res.corr = ca > 0 && cb > 0 ? (sab - sa * sb / n) / sqrt(ca * cb) : (ca == cb ? 1 : 0);
  if (e != full) nl_image_free(e);
  nl_image_free(full);
  return res;
}

/* Panel i of the montage against panel j: the correlation of what two
 * panels show (two captions that differ must not show one picture). */
static inline double oracle_panels_corr(const oracle_montage *m, int i, int j)
{
  const nl_image_rect *a = &m->rect[i], *b = &m->rect[j];
  double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
  size_t n = 0;
  for (int y = 0; y < a->h && y < b->h; y++)
    for (int x = 0; x < a->w && x < b->w; x++) {
      double p = nl_image_pixel(m->im, a->x + x, a->y + y)[0], q = nl_image_pixel(m->im, b->x + x, b->y + y)[0];
      sa += p; sb += q; saa += p * p; sbb += q * q; sab += p * q;
      n++;
    }
  double ca = saa - sa * sa / n, cb = sbb - sb * sb / n;
  return ca > 0 && cb > 0 ? (sab - sa * sb / n) / sqrt(ca * cb) : 0;
}

/* The run's manifest (manifest.tsv, read with NL_TABLE_TEXT): the value of
 * `key`, or NULL. */
static inline const char *oracle_manifest_value(const nl_table *m, const char *key)
{
  for (size_t i = 0; i < m->nrows; i++)
    if (!strcmp(nl_table_text(m, i, "key"), key)) return nl_table_text(m, i, "value");
  return NULL;
}

/* A parameter from the manifest's "param NAME=VALUE" lines (round-trip
 * doubles), else def: the oracle reads what the run used. */
static inline double oracle_param(const nl_table *m, const char *name, double def)
{
  size_t len = strlen(name);
  for (size_t i = 0; i < m->nrows; i++) {
    const char *v = nl_table_text(m, i, "value");
    if (!strcmp(nl_table_text(m, i, "key"), "param") && v && !strncmp(v, name, len) && v[len] == '=')
      return strtod(v + len + 1, NULL);
  }
  return def;
}

static inline int oracle_cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* A "stretched" panel's range: the values' own 1st and 99th percentiles
 * (order statistics n/100 and n - 1 - n/100); a flat image gets +-0.5. */
static inline void oracle_stretch(const double *v, size_t n, double *lo, double *hi)
{
  double *c = malloc(n * sizeof *c);
  memcpy(c, v, n * sizeof *c);
  qsort(c, n, sizeof *c, oracle_cmp_double);
  *lo = c[n / 100];
  *hi = c[n - 1 - n / 100];
  if (!(*hi > *lo)) { *lo -= 0.5; *hi += 0.5; }
  free(c);
}

/* A run folder's table `file` (read as text), or NULL after "PROG: message"
 * on stderr: the oracles' input errors (exit 2). */
static inline nl_table *oracle_read_table(const char *prog, const char *dir, const char *file)
{
  char path[1200];
  nl_table *t = NULL;
  nl_error err;
  snprintf(path, sizeof path, "%s/%s", dir, file);
  if (nl_table_read(path, NL_TABLE_TEXT, &t, &err)) {
    fprintf(stderr, "%s: %s\n", prog, err.msg);
    return NULL;
  }
  return t;
}

#endif
