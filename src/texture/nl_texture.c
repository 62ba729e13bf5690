#include "texture/nl_texture.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

nl_texture_ramp nl_texture_ramp_linear(int n, const double *pos, const float (*rgb)[3])
{
  nl_texture_ramp r = {.n = n < 1 ? 1 : n > NL_RAMP_MAX ? NL_RAMP_MAX : n, .kind = NL_RAMP_LINEAR};
  for (int k = 0; k < r.n; k++) { r.pos[k] = pos[k]; memcpy(r.rgb[k], rgb[k], sizeof r.rgb[k]); }
  return r;
}

nl_texture_ramp nl_texture_ramp_spline(int n, const float (*rgb)[3])
{
  nl_texture_ramp r = {.n = n < 4 ? 4 : n > NL_RAMP_MAX ? NL_RAMP_MAX : n, .kind = NL_RAMP_SPLINE};
  for (int k = 0; k < r.n; k++) {
    r.pos[k] = (double)k / (r.n - 1);
    memcpy(r.rgb[k], rgb[k < n ? k : n - 1], sizeof r.rgb[k]);
  }
  return r;
}

static void eval_linear(const nl_texture_ramp *r, double u, float *rgb)
{
  if (u <= r->pos[0] || r->n == 1) { memcpy(rgb, r->rgb[0], 3 * sizeof *rgb); return; }
  if (u >= r->pos[r->n - 1]) { memcpy(rgb, r->rgb[r->n - 1], 3 * sizeof *rgb); return; }
  int k = 0;
  while (k + 2 < r->n && u >= r->pos[k + 1]) k++;
  double t = (u - r->pos[k]) / (r->pos[k + 1] - r->pos[k]);
  for (int c = 0; c < 3; c++) rgb[c] = (float)(r->rgb[k][c] + t * (r->rgb[k + 1][c] - r->rgb[k][c]));
}

/* Ebert et al., "Texturing & Modeling", spline(): Catmull-Rom basis over
 * the span of four knots that contains u. */
static void eval_spline(const nl_texture_ramp *r, double u, float *rgb)
{
  int nspans = r->n - 3;
  double x = (u < 0 ? 0 : u > 1 ? 1 : u) * nspans;
  int span = (int)x;
  if (span >= nspans) span = nspans - 1;
  x -= span;
  const float (*k)[3] = r->rgb + span;
  for (int c = 0; c < 3; c++) {
    double c3 = -0.5 * k[0][c] + 1.5 * k[1][c] - 1.5 * k[2][c] + 0.5 * k[3][c];
    double c2 = 1.0 * k[0][c] - 2.5 * k[1][c] + 2.0 * k[2][c] - 0.5 * k[3][c];
    double c1 = -0.5 * k[0][c] + 0.5 * k[2][c];
    double c0 = k[1][c];
    rgb[c] = (float)(((c3 * x + c2) * x + c1) * x + c0);
  }
}

void nl_texture_ramp_eval(const nl_texture_ramp *r, double u, float *rgb)
{
  if (r->kind == NL_RAMP_SPLINE) eval_spline(r, u, rgb);
  else eval_linear(r, u, rgb);
}

nl_image *nl_texture_ramp_image(const nl_texture_ramp *r, const double *values, int w, int h, double lo, double hi)
{
  nl_image *im = nl_image_alloc(w, h, 3);
  double s = hi > lo ? 1.0 / (hi - lo) : 0.0;
  for (size_t i = 0; i < (size_t)w * h; i++) nl_texture_ramp_eval(r, (values[i] - lo) * s, im->data + 3 * i);
  return im;
}

nl_texture_ramp nl_texture_ramp_grey(void)
{
  const double pos[] = {0, 1};
  const float rgb[][3] = {{0, 0, 0}, {1, 1, 1}};
  return nl_texture_ramp_linear(2, pos, rgb);
}

nl_texture_ramp nl_texture_ramp_marble(void)
{
  /* White veins into grey-blue stone, the slides' marble palette. */
  const double pos[] = {0.0, 0.35, 0.6, 0.8, 1.0};
  const float rgb[][3] = {{0.95f, 0.95f, 0.93f}, {0.85f, 0.85f, 0.86f}, {0.55f, 0.58f, 0.66f},
                          {0.28f, 0.30f, 0.42f}, {0.12f, 0.12f, 0.22f}};
  return nl_texture_ramp_linear(5, pos, rgb);
}

void nl_texture_marble_grid(const nl_noise_basis *b, const nl_noise_octaves *o, const nl_noise_window *win,
                            double omega, double a, double *u)
{
  nl_noise_fractal_grid(b, o, win, u);
  double dy = win->size / win->h;
  for (int r = 0; r < win->h; r++) {
    double y = win->y0 + (r + 0.5) * dy;
    double *row = u + (size_t)r * win->w;
    for (int c = 0; c < win->w; c++) row[c] = nl_texture_marble(omega * y, omega * a, row[c]);
  }
}

/* ---- Qin & Yang sec. 4 ------------------------------------------------- */

nl_texture_ramp nl_texture_ramp_cellular_marble(void)
{
  static const float k[13][3] = {
    {0.25f, 0.25f, 0.35f}, {0.25f, 0.25f, 0.35f}, {0.10f, 0.10f, 0.30f}, {0.10f, 0.10f, 0.30f},
    {0.10f, 0.10f, 0.30f}, {0.25f, 0.25f, 0.35f}, {0.25f, 0.25f, 0.35f}, {0.05f, 0.05f, 0.26f},
    {0.05f, 0.05f, 0.26f}, {0.03f, 0.03f, 0.20f}, {0.03f, 0.03f, 0.20f}, {0.25f, 0.25f, 0.35f},
    {0.03f, 0.03f, 0.20f}};
  return nl_texture_ramp_spline(13, k);
}

static double smoothstep01(double t)
{
  t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
  return t * t * (3.0 - 2.0 * t);   /* RenderMan's Hermite smoothstep */
}

nl_image *nl_texture_cloud_colour(const double *v, int w, int h)
{
  static const float sky[3] = {0.15f, 0.15f, 0.60f}, cloud[3] = {1.0f, 1.0f, 1.0f};
  nl_image *im = nl_image_alloc(w, h, 3);
  for (size_t k = 0; k < (size_t)w * h; k++) {
    float t = (float)smoothstep01(v[k]);
    for (int a = 0; a < 3; a++) im->data[3 * k + a] = (1.0f - t) * sky[a] + t * cloud[a];
  }
  return im;
}

/* ---- wood ------------------------------------------------------------ */

static double smoothstep(double a, double b, double x)
{
  double t = (x - a) / (b - a);
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  return t * t * (3 - 2 * t);
}

double nl_texture_wood_radius(const nl_texture_wood *w, const double p[3])
{
  double d[3], n = 0, along = 0, r2 = 0;
  for (int a = 0; a < 3; a++) n += w->axis_d[a] * w->axis_d[a];
  n = sqrt(n);
  for (int a = 0; a < 3; a++) { d[a] = p[a] - w->axis_p[a]; along += d[a] * w->axis_d[a] / n; }
  for (int a = 0; a < 3; a++) { double e = d[a] - along * w->axis_d[a] / n; r2 += e * e; }
  return sqrt(r2);
}

double nl_texture_wood_ring(const nl_texture_wood *w, const double p[3], double g)
{
  double u = w->ring_freq * nl_texture_wood_radius(w, p) + w->turb * g;
  u -= floor(u);
  /* the RenderMan Companion's ring profile: dark wood builds up over the ring, ends sharply */
  return smoothstep(0.0, 0.8, u) - smoothstep(0.83, 1.0, u);
}

void nl_texture_wood_grid(const nl_texture_wood *w, const nl_noise_window *win, const double *g, double *t)
{
  double dx = win->size / win->w, dy = win->size / win->h;
  for (int j = 0; j < win->h; j++)
    for (int i = 0; i < win->w; i++) {
      double p[3] = {win->x0 + (i + 0.5) * dx, win->y0 + (j + 0.5) * dy, win->z};
      size_t k = (size_t)j * win->w + i;
      t[k] = nl_texture_wood_ring(w, p, g ? g[k] : 0.0);
    }
}

nl_image *nl_texture_wood_image(const nl_texture_wood *w, const double *t, int width, int height)
{
  nl_image *im = nl_image_alloc(width, height, 3);
  for (size_t k = 0; k < (size_t)width * height; k++)
    for (int c = 0; c < 3; c++) im->data[3 * k + c] = (float)(w->light[c] + t[k] * (w->dark[c] - w->light[c]));
  return im;
}

int nl_texture_band_count(const nl_image *im, int vertical, int index)
{
  int len = vertical ? im->height : im->width;
  double *l = nl_xmalloc((size_t)len * sizeof *l), lo = INFINITY, hi = -INFINITY, mean = 0;
  for (int i = 0; i < len; i++) {
    size_t k = vertical ? (size_t)i * im->width + index : (size_t)index * im->width + i;
    const float *px = im->data + (size_t)im->channels * k;
    l[i] = im->channels >= 3 ? 0.2126 * px[0] + 0.7152 * px[1] + 0.0722 * px[2] : px[0];
    lo = fmin(lo, l[i]); hi = fmax(hi, l[i]); mean += l[i] / len;
  }
  /* dark bands: down-crossings of the line's mean, with a hysteresis of a
   * tenth of its range so that pixel noise does not count twice */
  double h = 0.1 * (hi - lo);
  int state = 0, count = 0;   /* 0 unknown, 1 above, -1 below */
  for (int i = 0; i < len; i++) {
    if (l[i] > mean + h) state = 1;
    else if (l[i] < mean - h) { if (state == 1) count++; state = -1; }
  }
  free(l);
  return count;
}
