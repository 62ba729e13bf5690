/* The image side of the Cheng module (sec. 3.4.1, 4.1): control patterns
 * read from PNGs and the built-in shapes that make them, the textures and
 * panels experiments show. The optimiser (src/cheng) sees pixels and values
 * only; everything that makes or reads an nl_image is here. */
#include "study/nl_study_cheng.h"
#include "stats/nl_stats.h"
#include "texture/nl_texture.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* ---- patterns from images ----------------------------------------------- */

nl_status nl_study_cheng_pattern_from_image(const nl_image *im, int grid, nl_cheng_pattern **out,
                                            nl_error *err)
{
  return nl_cheng_pattern_from_pixels(im->data, im->width, im->height, im->channels, grid, out,
                                      err);
}

/* PATH read as a pattern at `grid` (nl_study_cheng_pattern_from_image); the
 * error names the file. */
static nl_status pattern_read(const char *path, int grid, nl_cheng_pattern **out, nl_error *err)
{
  nl_image *im;
  *out = NULL;
  nl_status s = nl_image_read(path, &im, err);
  if (s) return s;
  s = nl_study_cheng_pattern_from_image(im, grid, out, err);
  nl_image_free(im);
  if (s) {
    char msg[NL_ERROR_LEN];
    snprintf(msg, sizeof msg, "%s", err ? err->msg : "");
    return nl_fail(err, s, "%s: %s", path, msg);
  }
  return NL_OK;
}

/* The pattern as an RGB image (grid x grid): red = D, no-control cells grey. */
static nl_image *pattern_image(const nl_cheng_pattern *p)
{
  nl_image *im = nl_image_alloc(p->grid, p->grid, 3);
  for (size_t q = 0; q < (size_t)p->grid * p->grid * 3; q++) im->data[q] = 0.5f;
  for (size_t i = 0; i < p->n; i++) {
    float *px = im->data + (size_t)p->cell[i] * 3;
    px[0] = (float)p->d[i];
    px[1] = 0;
    px[2] = 0;
  }
  return im;
}

/* ---- shapes: red = f(u, v) on [-1, 1]^2, v down the image ---------------- */

static double shape_flower(double u, double v)
{
  double r = hypot(u, v), phi = atan2(v, u);
  return r < 0.3 + 0.55 * fabs(cos(2.5 * phi));   /* 5 round petals */
}

static double shape_x(double u, double v)
{
  if (fabs(u) > 0.8 || fabs(v) > 0.8) return 0;
  return fabs(u - v) < 0.22 || fabs(u + v) < 0.22;
}

static double shape_star(double u, double v)
{
  double r = hypot(u, v), phi = atan2(u, -v);        /* a point straight up */
  double t = fmod(phi / NL_TWO_PI * 5 + 10.0, 1.0);  /* 0 at a tip, 1/2 between */
  double tri = fabs(1 - 2 * t);                      /* 1 at tips, 0 between */
  return r < 0.34 + 0.58 * tri * tri;   /* concave sides: pointed tips */
}

static double shape_rings(double u, double v)
{
  double r = hypot(u, v);
  return r < 0.95 && ((int)floor(r / 0.19) % 2 == 0);
}

static double shape_disc(double u, double v) { return hypot(u, v) < 0.6; }

static double shape_letter(double u, double v)   /* "N" */
{
  if (fabs(v) > 0.8) return 0;
  return fabs(u + 0.55) < 0.14 || fabs(u - 0.55) < 0.14 ||
         (fabs(u - 0.6875 * v) < 0.17 && fabs(u) < 0.6);
}

static double shape_gradient(double u, double v) { (void)v; return 0.5 * (u + 1); }

static double shape_spiral(double u, double v)
{
  double r = hypot(u, v), phi = atan2(v, u);
  return r < 0.95 && fmod(phi / NL_TWO_PI + 2.5 * r + 10.0, 1.0) < 0.45;
}

const char *const nl_study_cheng_shape_names[] = {"flower", "x", "star", "rings", "disc", "letter",
                                            "gradient", "spiral", NULL};
static double (*const shape_fns[])(double, double) = {
  shape_flower, shape_x,      shape_star,     shape_rings,
  shape_disc,   shape_letter, shape_gradient, shape_spiral};

nl_image *nl_study_cheng_shape(const char *name, int size)
{
  int idx = -1;
  for (int k = 0; nl_study_cheng_shape_names[k]; k++)
    if (!strcmp(name, nl_study_cheng_shape_names[k])) idx = k;
  if (idx < 0 || size < 1) return NULL;
  nl_image *im = nl_image_alloc(size, size, 4);
  for (int y = 0; y < size; y++)
    for (int x = 0; x < size; x++) {
      double red = 0;   /* 2 x 2 supersampling for smooth edges */
      for (int s = 0; s < 4; s++) {
        double u = 2 * (x + 0.25 + 0.5 * (s & 1)) / size - 1;
        double v = 2 * (y + 0.25 + 0.5 * (s >> 1)) / size - 1;
        red += 0.25 * shape_fns[idx](u, v);
      }
      double u = 2 * (x + 0.5) / size - 1, v = 2 * (y + 0.5) / size - 1;
      float *px = nl_image_pixel(im, x, y);
      px[0] = (float)red; px[1] = 0; px[2] = 0;
      px[3] = !strcmp(name, "disc") && hypot(u, v) > 1.0 ? 0.0f : 1.0f;
    }
  return im;
}

/* ---- the experiments' pattern folder ------------------------------------ */

nl_status nl_study_cheng_patterns_parse(int *argc, char **argv, const char **dir, nl_error *err)
{
  int w = 1;
  *dir = "data/patterns";
  for (int i = 1; i < *argc; i++) {
    if (!strcmp(argv[i], "--patterns")) {
      if (i + 1 >= *argc) return nl_fail(err, NL_EINVAL, "--patterns: missing value");
      if (!argv[i + 1][0]) return nl_fail(err, NL_EINVAL, "--patterns: empty folder name");
      *dir = argv[++i];
      continue;
    }
    argv[w++] = argv[i];
  }
  *argc = w;
  argv[w] = NULL;
  return NL_OK;
}

nl_status nl_study_cheng_patterns_check(const char *dir, int grid, nl_error *err)
{
  struct stat st;
  if (stat(dir, &st)) return nl_fail(err, NL_EIO, "--patterns %s: %s", dir, strerror(errno));
  if (!S_ISDIR(st.st_mode)) return nl_fail(err, NL_EIO, "--patterns %s: not a folder", dir);
  for (int k = 0; nl_study_cheng_shape_names[k]; k++) {
    char file[64];
    snprintf(file, sizeof file, "%s.png", nl_study_cheng_shape_names[k]);
    char *path = nl_path_join(dir, file);
    nl_cheng_pattern *p;
    nl_status s = pattern_read(path, grid, &p, err);
    free(path);
    if (s) return s;
    nl_cheng_pattern_free(p);
  }
  return NL_OK;
}

nl_cheng_pattern *nl_study_cheng_pattern_load_or_die(const char *prog, const char *dir,
                                                     const char *name, int grid)
{
  char file[256];
  snprintf(file, sizeof file, "%s.png", name);
  char *path = nl_path_join(dir, file);
  nl_cheng_pattern *p;
  nl_error err;
  if (pattern_read(path, grid, &p, &err)) {
    fprintf(stderr, "%s: control pattern: %s (make them with build/tools/noiselab-patterns "
                    "data/patterns, or pass --patterns DIR)\n", prog, err.msg);
    exit(2);
  }
  free(path);
  return p;
}

/* ---- textures and panels (sec. 4.1) ------------------------------------- */

/* The 1st and 99th percentiles of v: the display range of a texture. */
static void display_range(const double *v, size_t n, double *lo, double *hi)
{
  double *c = nl_xmalloc(n * sizeof *c);
  memcpy(c, v, n * sizeof *c);
  nl_stats_sort(c, n);
  *lo = c[n / 100];
  *hi = c[n - 1 - n / 100];
  if (!(*hi > *lo)) { *lo -= 0.5; *hi += 0.5; }
  free(c);
}

/* Sec. 4.1: cloud / erosion / fire alpha-blend two colours with the value as
 * alpha; marble maps the value through the marble ramp. The optimised value
 * spans only part of [0, 1] (nl_cheng.h, READINGS), so alpha 0..1 is the
 * value's own 1st..99th percentile: a display stretch, not part of the
 * optimisation. */
static nl_image *texture(nl_cheng_con kind, const double *v, int w, int h)
{
  /* Two colours per texture, blended with the value as alpha (sec. 4.1). */
  static const float pair[4][2][3] = {
    {{0.20f, 0.40f, 0.85f}, {1.00f, 1.00f, 1.00f}},   /* cloud: sky to white */
    {{0.00f, 0.00f, 0.00f}, {0.00f, 0.00f, 0.00f}},   /* marble: ramp below */
    {{0.22f, 0.13f, 0.07f}, {0.92f, 0.82f, 0.62f}},   /* erosion: soil to sand */
    {{0.25f, 0.00f, 0.00f}, {1.00f, 0.85f, 0.15f}},   /* fire: ember to flame */
  };
  size_t n = (size_t)w * h;
  double lo, hi;
  display_range(v, n, &lo, &hi);
  if (kind == NL_CHENG_CON_SIN) {
    nl_texture_ramp r = nl_texture_ramp_marble();
    return nl_texture_ramp_image(&r, v, w, h, lo, hi);
  }
  nl_image *im = nl_image_alloc(w, h, 3);
  for (size_t q = 0; q < n; q++) {
    double a = (v[q] - lo) / (hi - lo);
    a = a < 0 ? 0 : a > 1 ? 1 : a;
    for (int ch = 0; ch < 3; ch++)
      im->data[3 * q + ch] = (float)((1 - a) * pair[kind][0][ch] + a * pair[kind][1][ch]);
  }
  return im;
}

nl_image *nl_study_cheng_grey_image(const double *v, int w, int h)
{
  double lo, hi;
  display_range(v, (size_t)w * h, &lo, &hi);
  return nl_image_from_values(v, w, h, lo, hi);
}

nl_image *nl_study_cheng_value_image(const nl_noise_grad2 *g, const nl_cheng_config *c, int size)
{
  double *v = nl_xmalloc((size_t)size * size * sizeof *v);
  nl_cheng_value_grid(g, c, size, size, v);
  nl_image *im = nl_study_cheng_grey_image(v, size, size);
  free(v);
  return im;
}

nl_image *nl_study_cheng_value_image_raw(const nl_noise_grad2 *g, const nl_cheng_config *c,
                                         int size)
{
  double *v = nl_xmalloc((size_t)size * size * sizeof *v);
  nl_cheng_value_grid(g, c, size, size, v);
  /* The value's own scale: [0, 1] for the rescaled control values and the
   * literal |V|, sum |Noise| / a; [-1, 1] for the literal signed V and sin V. */
  int signed_v = c->literal && (c->con == NL_CHENG_CON_PLAIN || c->con == NL_CHENG_CON_SIN);
  nl_image *im = nl_image_from_values(v, size, size, signed_v ? -1 : 0, 1);
  free(v);
  return im;
}

nl_image *nl_study_cheng_texture_image(const nl_noise_grad2 *g, const nl_cheng_config *c, int size)
{
  double *v = nl_xmalloc((size_t)size * size * sizeof *v);
  nl_cheng_value_grid(g, c, size, size, v);
  nl_image *im = texture(c->con, v, size, size);
  free(v);
  return im;
}

nl_image *nl_study_cheng_pattern_panel(const nl_cheng_pattern *p, int size)
{
  nl_image *small = pattern_image(p);
  nl_image *im = nl_image_alloc(size, size, 3);
  for (int y = 0; y < size; y++)
    for (int x = 0; x < size; x++) {
      const float *src = nl_image_pixel(small, x * p->grid / size, y * p->grid / size);
      memcpy(nl_image_pixel(im, x, y), src, 3 * sizeof(float));
    }
  nl_image_free(small);
  return im;
}
