/* Control patterns (sec. 3.4.1, Fig 3.7): black = 0, red = 1 from the red
 * channel, alpha 0 = no control; built-in shapes for the shipped PNGs. */
#include "cheng/nl_cheng_internal.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Red and alpha of a pixel for 1 (grey), 2 (grey+alpha), 3 (RGB), 4 (RGBA) channels. */
static void red_alpha(const nl_image *im, int x, int y, double *red, double *alpha)
{
  const float *px = nl_image_pixel(im, x, y);
  *red = px[0];
  *alpha = im->channels == 2 ? px[1] : im->channels == 4 ? px[3] : 1.0;
}

/* Mean alpha and alpha-weighted mean red of the pixels of cell (r, c); at
 * least the pixel under the cell centre when the image is smaller than the grid. */
static void cell_mean(const nl_image *im, int grid, int r, int c, double *d, double *alpha)
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

nl_status nl_cheng_pattern_from_image(const nl_image *im, int grid, nl_cheng_pattern **out,
                                      nl_error *err)
{
  *out = NULL;
  if (grid < 1 || grid > 4096) return nl_fail(err, NL_EINVAL, "control grid %d out of range 1..4096", grid);
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

nl_status nl_cheng_pattern_read(const char *path, int grid, nl_cheng_pattern **out, nl_error *err)
{
  nl_image *im;
  *out = NULL;
  nl_status s = nl_image_read(path, &im, err);
  if (s) return s;
  s = nl_cheng_pattern_from_image(im, grid, out, err);
  nl_image_free(im);
  if (s) {
    char msg[NL_ERROR_LEN];
    snprintf(msg, sizeof msg, "%s", err ? err->msg : "");
    return nl_fail(err, s, "%s: %s", path, msg);
  }
  return NL_OK;
}

void nl_cheng_pattern_free(nl_cheng_pattern *p)
{
  if (!p) return;
  free(p->x); free(p->y); free(p->d); free(p->cell); free(p);
}

nl_image *nl_cheng_pattern_image(const nl_cheng_pattern *p)
{
  nl_image *im = nl_image_alloc(p->grid, p->grid, 3);
  for (size_t q = 0; q < (size_t)p->grid * p->grid * 3; q++) im->data[q] = 0.5f;
  for (size_t i = 0; i < p->n; i++) {
    float *px = im->data + (size_t)p->cell[i] * 3;
    px[0] = (float)p->d[i]; px[1] = 0; px[2] = 0;
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
  return fabs(u + 0.55) < 0.14 || fabs(u - 0.55) < 0.14 || (fabs(u - 0.6875 * v) < 0.17 && fabs(u) < 0.6);
}

static double shape_gradient(double u, double v) { (void)v; return 0.5 * (u + 1); }

static double shape_spiral(double u, double v)
{
  double r = hypot(u, v), phi = atan2(v, u);
  return r < 0.95 && fmod(phi / NL_TWO_PI + 2.5 * r + 10.0, 1.0) < 0.45;
}

const char *const nl_cheng_shape_names[] = {"flower", "x", "star", "rings", "disc", "letter",
                                            "gradient", "spiral", NULL};
static double (*const shape_fns[])(double, double) = {
  shape_flower, shape_x, shape_star, shape_rings, shape_disc, shape_letter, shape_gradient, shape_spiral};

nl_image *nl_cheng_shape(const char *name, int size)
{
  int idx = -1;
  for (int k = 0; nl_cheng_shape_names[k]; k++) if (!strcmp(name, nl_cheng_shape_names[k])) idx = k;
  if (idx < 0 || size < 1) return NULL;
  nl_image *im = nl_image_alloc(size, size, 4);
  for (int y = 0; y < size; y++)
    for (int x = 0; x < size; x++) {
      double red = 0;   /* 2 x 2 supersampling for smooth edges */
      for (int s = 0; s < 4; s++) {
        double u = 2 * (x + 0.25 + 0.5 * (s & 1)) / size - 1, v = 2 * (y + 0.25 + 0.5 * (s >> 1)) / size - 1;
        red += 0.25 * shape_fns[idx](u, v);
      }
      double u = 2 * (x + 0.5) / size - 1, v = 2 * (y + 0.5) / size - 1;
      float *px = nl_image_pixel(im, x, y);
      px[0] = (float)red; px[1] = 0; px[2] = 0;
      px[3] = !strcmp(name, "disc") && hypot(u, v) > 1.0 ? 0.0f : 1.0f;
    }
  return im;
}

/* ---- experiments' pattern folder ---------------------------------------- */

nl_status nl_cheng_patterns_parse(int *argc, char **argv, const char **dir, nl_error *err)
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

const char *nl_cheng_patterns_option(int *argc, char **argv)
{
  const char *dir;
  nl_error err;
  if (nl_cheng_patterns_parse(argc, argv, &dir, &err)) {
    fprintf(stderr, "%s: %s\n", argv[0], err.msg);
    exit(2);
  }
  return dir;
}

nl_status nl_cheng_patterns_check(const char *dir, int grid, nl_error *err)
{
  struct stat st;
  if (stat(dir, &st)) return nl_fail(err, NL_EIO, "--patterns %s: %s", dir, strerror(errno));
  if (!S_ISDIR(st.st_mode)) return nl_fail(err, NL_EIO, "--patterns %s: not a folder", dir);
  for (int k = 0; nl_cheng_shape_names[k]; k++) {
    char file[64];
    snprintf(file, sizeof file, "%s.png", nl_cheng_shape_names[k]);
    char *path = nl_path_join(dir, file);
    nl_cheng_pattern *p;
    nl_status s = nl_cheng_pattern_read(path, grid, &p, err);
    free(path);
    if (s) return s;
    nl_cheng_pattern_free(p);
  }
  return NL_OK;
}

nl_cheng_pattern *nl_cheng_pattern_load_or_die(const char *prog, const char *dir,
                                               const char *name, int grid)
{
  char file[256];
  snprintf(file, sizeof file, "%s.png", name);
  char *path = nl_path_join(dir, file);
  nl_cheng_pattern *p;
  nl_error err;
  if (nl_cheng_pattern_read(path, grid, &p, &err)) {
    fprintf(stderr, "%s: control pattern: %s (make them with build/tools/noiselab-patterns "
                    "data/patterns, or pass --patterns DIR)\n", prog, err.msg);
    exit(2);
  }
  free(path);
  return p;
}
