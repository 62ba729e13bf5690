/* oracle_sq - S4, Q1, Q2, Q3 and Q4's panels against their captions.
 *
 *   oracle_sq s4|q1|q2|q3|q4 OUTDIR
 *
 * Each caption names a function of the paper on a window of the plane, for
 * the run's first seed: S4 Shaffer's marble u = (1 + sin(2 pi s (y + a
 * fractal_sum(p)))) / 2 through the marble ramp; Q1 the distances F1..F4
 * to the feature points of the 27 cubes around x (Qin & Yang sec. 3.2);
 * Q2 eq. 4, clamp(GCTBF) through the 13-knot spline; Q3 eq. 6's bump
 * shaded under one light; Q4 eq. 7's clouds, Fig. 6's marble, sky and
 * flame, and the wood of a GCTBF through a ramp and a ring shader. This
 * computes each panel's values by another path than the programs (their
 * rows of nl_noise_fractal_grid and nl_cellular_row, SIMD where the CPU has
 * it): Perlin's noise one point at a time (nl_noise_perm3_eval_general),
 * F_i by a naive loop over every feature point of the 27 cubes
 * (nl_cellular_cube) sorted here, each GCTBF written out from the caption's
 * formula, the octave sums, the bump's cube, the Lambert shading and the
 * wood rings summed here. It maps the values as the figure does (the same
 * ramps and colour mixes: nl_texture_ramp_image, nl_texture_cloud_colour,
 * nl_texture_wood_image) and compares every channel of every panel with
 * the PNG to 8 bits. A panel that shows another seed, another combination,
 * another octave count or another table fails (grey levels and
 * correlation); panels whose captions differ must not show one picture.
 * Parameters come from the run's manifest. Exit 0 when every panel matches,
 * 1 with one line per mismatch.
 */
#include "oracle.h"

#include "base/nl_base.h"
#include "cellular/nl_cellular.h"
#include "noise/nl_noise.h"
#include "table/nl_table.h"
#include "texture/nl_texture.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SLICE_Z (64.0 / 3.0) /* the S and Perlin panels' plane (NL_STUDY_SLICE_Z) */

static unsigned long run_seed(const nl_table *m)
{
  const char *s = oracle_manifest_value(m, "seed");
  return s ? strtoul(s, NULL, 10) : 1;
}

/* ---- the values, by naive loops ----------------------------------------- */

/* F1..F4 at (x, y, z): every feature point of the 27 cubes around it, the
 * four smallest distances kept in order; NL_CELLULAR_FMAX where the cubes
 * hold fewer points (nl_cellular.h). */
static void naive_F(const nl_cellular *c, double x, double y, double z, double *F)
{
  static double xyz[3 * (NL_CELLULAR_MAX_M + 1)];
  long bx = (long)floor(x), by = (long)floor(y), bz = (long)floor(z);
  for (int i = 0; i < 4; i++) F[i] = INFINITY;
  for (long i = bx - 1; i <= bx + 1; i++)
    for (long j = by - 1; j <= by + 1; j++)
      for (long k = bz - 1; k <= bz + 1; k++) {
        int m = nl_cellular_cube(c, i, j, k, xyz);
        for (int q = 0; q < m; q++) {
          double dx = xyz[3 * q] - x, dy = xyz[3 * q + 1] - y, dz = xyz[3 * q + 2] - z;
          double d = sqrt(dx * dx + dy * dy + dz * dz);
          for (int s = 0; s < 4; s++)
            if (d < F[s]) {
              for (int t = 3; t > s; t--) F[t] = F[t - 1];
              F[s] = d;
              break;
            }
        }
      }
  for (int i = 0; i < 4; i++)
    if (F[i] == INFINITY) F[i] = NL_CELLULAR_FMAX;
}

/* The captions' combinations, written out from the paper's formulas. */
static double combo(const char *name, const double *F)
{
  double F1 = F[0], F2 = F[1], F3 = F[2];
  if (!strcmp(name, "F1")) return F1;
  if (!strcmp(name, "F2")) return F2;
  if (!strcmp(name, "F3")) return F3;
  if (!strcmp(name, "F4")) return F[3];
  if (!strcmp(name, "F2 - F1")) return F2 - F1;
  if (!strcmp(name, "F1F2")) return F1 * F2;
  if (!strcmp(name, "F2 - F1 - F1F1")) return F2 - F1 - F1 * F1;
  if (!strcmp(name, "F1F2 + F2F3")) return F1 * F2 + F2 * F3;
  if (!strcmp(name, "F1 + F1F1")) return F1 + F1 * F1;
  if (!strcmp(name, "F1 + F1F2")) return F1 + F1 * F2;
  if (!strcmp(name, "F1 - F1F1")) return F1 - F1 * F1;
  if (!strcmp(name, "F3 - F3F3")) return F3 - F3 * F3;
  if (!strcmp(name, "marble")) { /* sec. 4.3: sum (-1)^i F_i + sum (-1)^(i+j) F_i F_j */
    double s = 0;
    for (int i = 1; i <= 4; i++) {
      s += (i % 2 ? -1 : 1) * F[i - 1];
      for (int j = 1; j <= 4; j++) s += ((i + j) % 2 ? -1 : 1) * F[i - 1] * F[j - 1];
    }
    return s;
  }
  fprintf(stderr, "oracle_sq: no formula for %s\n", name);
  exit(2);
}

static double gctbf_at(const nl_cellular *c, const char *name, double x, double y, double z)
{
  double F[4];
  naive_F(c, x, y, z, F);
  return combo(name, F);
}

static nl_cellular *table(double lambda, int M, nl_cellular_count_rule rule, unsigned long seed)
{
  nl_cellular *c;
  nl_error err;
  if (nl_cellular_alloc(lambda, M, rule, seed, &c, &err)) {
    fprintf(stderr, "oracle_sq: %s\n", err.msg);
    exit(2);
  }
  return c;
}

/* pixel centre (i, j) of a w x w raster of [0, extent)^2 */
static double centre(int i, int w, double extent) { return (i + 0.5) * extent / w; }

/* ---- comparing ---------------------------------------------------------- */

typedef struct {
  const char *file;
  oracle_montage m;
  int bad;
} fig;

static int fig_open(fig *f, const char *dir, const char *file, int n, int w, const char *const *labels,
                    int cols, const char *title)
{
  int ws[8], hs[8];
  for (int i = 0; i < n; i++) ws[i] = hs[i] = w;
  char path[1024];
  snprintf(path, sizeof path, "%s/%s", dir, file);
  f->file = file;
  f->bad = 0;
  if (oracle_montage_read(&f->m, path, ws, hs, labels, n, cols, title)) {
    printf("%s: %s\n", file, f->m.err);
    oracle_montage_free(&f->m);
    return 1;
  }
  return 0;
}

/* Panel i of the figure against the colour image e (full size): every
 * channel to 8 bits, and the correlation of the channels' sums. */
static void fig_rgb(fig *f, int i, const char *label, nl_image *e)
{
  nl_image *d = f->m.g.factor > 1 ? nl_image_downsample(e, f->m.g.factor) : e;
  const nl_image_rect *r = &f->m.rect[i];
  double md = 0, sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
  int mx = 0, my = 0;
  size_t n = 0;
  for (int y = 0; y < r->h && y < d->height; y++)
    for (int x = 0; x < r->w && x < d->width; x++) {
      const float *p = nl_image_pixel(f->m.im, r->x + x, r->y + y), *q = nl_image_pixel(d, x, y);
      double a = 0, b = 0;
      for (int ch = 0; ch < 3; ch++) {
        /* an 8-bit PNG holds [0, 1]: a spline's overshoot is written clamped */
        double qc = fmin(1, fmax(0, q[d->channels >= 3 ? ch : 0])), diff = fabs(p[ch] - qc);
        if (diff > md) {
          md = diff;
          mx = x;
          my = y;
        }
        a += p[ch];
        b += qc;
      }
      sa += a; sb += b; saa += a * a; sbb += b * b; sab += a * b;
      n++;
    }
  double ca = saa - sa * sa / n, cb = sbb - sb * sb / n;
  double corr = ca > 0 && cb > 0 ? (sab - sa * sb / n) / sqrt(ca * cb) : (ca == cb ? 1 : 0);
  if (md > ORACLE_TOL_8BIT || corr < 0.999) {
    printf("%s: panel %s is not its caption: max difference %.4f at (%d, %d), correlation %.4f\n",
           f->file, label, md, mx, my, corr);
    f->bad++;
  }
  if (d != e) nl_image_free(d);
  nl_image_free(e);
}

/* Panel i against grey values v mapped from lo to hi (nl_image_from_values). */
static void fig_grey(fig *f, int i, const char *label, const double *v, int w, double lo, double hi)
{
  oracle_result res = oracle_panel_compare(&f->m, i, v, w, w, lo, hi);
  /* a flat caption (Fig. 4's original plane) has no correlation to speak of */
  int flat = 1;
  for (size_t q = 1; q < (size_t)w * w && flat; q++) flat = v[q] == v[0];
  if (res.max_diff > ORACLE_TOL_8BIT || (!flat && res.corr < 0.999)) {
    printf("%s: panel %s is not its caption: max grey difference %.4f at (%d, %d), correlation %.4f\n",
           f->file, label, res.max_diff, res.x, res.y, res.corr);
    f->bad++;
  }
}

/* Captions that differ do not show one picture; returns the failures. */
static int fig_close(fig *f, int n, const char *const *labels)
{
  for (int i = 0; i + 1 < n; i++) {
    double c = oracle_panels_corr(&f->m, i, i + 1);
    if (c > 0.9999) {
      printf("%s: panels %s and %s show one picture (correlation %.5f)\n", f->file, labels[i],
             labels[i + 1], c);
      f->bad++;
    }
  }
  oracle_montage_free(&f->m);
  return f->bad;
}

/* ---- S4: marble ---------------------------------------------------------- */

static int check_s4(const char *dir, const nl_table *man)
{
  int w = (int)oracle_param(man, "size", 128), oct = (int)oracle_param(man, "octaves", 6);
  double s = oracle_param(man, "stripes", 1), extent = oracle_param(man, "extent", 4);
  const double amps[4] = {0, 0.25, 0.5, 1.0};
  const char *labels[4] = {"(a) a = 0", "(b) a = 0.25", "(c) a = 0.5", "(d) a = 1"};
  fig f;
  if (fig_open(&f, dir, "panels.png", 4, w, labels, 4,
               "marble: u = (1 + sin(2 pi (y + a fractal_sum(p)))) / 2"))
    return 1;
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, nl_seed_replicate(run_seed(man), 0));
  nl_texture_ramp ramp = nl_texture_ramp_marble();
  double *fs = malloc((size_t)w * w * sizeof *fs), *u = malloc((size_t)w * w * sizeof *u);
  for (int j = 0; j < w; j++)
    for (int i = 0; i < w; i++) {
      double x = centre(i, w, extent), y = centre(j, w, extent), sum = 0, a = 1, fr = 1;
      for (int l = 0; l < oct; l++, a /= 2, fr *= 2)
        sum += a * nl_noise_perm3_eval_general(&p, fr * x, fr * y, fr * SLICE_Z);
      fs[(size_t)j * w + i] = sum;
    }
  for (int k = 0; k < 4; k++) {
    for (int j = 0; j < w; j++)
      for (int i = 0; i < w; i++) {
        double y = centre(j, w, extent);
        u[(size_t)j * w + i] = 0.5 * (1 + sin(2 * NL_PI * s * (y + amps[k] * fs[(size_t)j * w + i])));
      }
    fig_rgb(&f, k, labels[k], nl_texture_ramp_image(&ramp, u, w, w, 0, 1));
  }
  free(fs);
  free(u);
  return fig_close(&f, 4, labels);
}

/* ---- Q1: F1..F4 ---------------------------------------------------------- */

static int check_q1(const char *dir, const nl_table *man)
{
  int w = (int)oracle_param(man, "size", 96), M = (int)oracle_param(man, "M", 50);
  double lambda = oracle_param(man, "lambda", 4), extent = 4.0;
  const char *labels[6] = {"F1", "F2", "F3", "F4", "F2 - F1", "F1 paper rule"};
  fig f;
  if (fig_open(&f, dir, "planes.png", 6, w, labels, 3, "F_i on z = 0.5")) return 1;
  unsigned long seed = run_seed(man); /* Q1's tables are made from the run's seed itself */
  nl_cellular *ref = table(lambda, M, NL_COUNT_INVERSE_CDF, seed);
  nl_cellular *paper = table(lambda, M, NL_COUNT_CLOSEST, seed);
  double *v = malloc((size_t)w * w * sizeof *v);
  for (int k = 0; k < 6; k++) {
    double top = 0;
    for (int j = 0; j < w; j++)
      for (int i = 0; i < w; i++) {
        double x = centre(i, w, extent), y = centre(j, w, extent);
        double g = gctbf_at(k == 5 ? paper : ref, k == 5 ? "F1" : labels[k], x, y, 0.5);
        v[(size_t)j * w + i] = g;
        top = fmax(top, g);
      }
    fig_grey(&f, k, labels[k], v, w, 0, top);
  }
  free(v);
  nl_cellular_free(ref);
  nl_cellular_free(paper);
  return fig_close(&f, 6, labels);
}

/* ---- Q2: eq. 4 ----------------------------------------------------------- */

static int check_q2(const char *dir, const nl_table *man)
{
  int w = (int)oracle_param(man, "size", 96);
  double extent = oracle_param(man, "extent", 4), pf = oracle_param(man, "perlin_freq", 2);
  const char *labels[6] = {"Perlin noise", "F1", "F2 - F1", "F1F2", "F2 - F1 - F1F1", "F1F2 + F2F3"};
  fig f;
  if (fig_open(&f, dir, "colour.png", 6, w, labels, 3, "Fig. 2: spline colour map")) return 1;
  unsigned long seed = nl_seed_replicate(run_seed(man), 0);
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, seed);
  nl_cellular *c = table(4.0, 50, NL_COUNT_INVERSE_CDF, seed);
  nl_texture_ramp ramp = nl_texture_ramp_cellular_marble();
  double *v = malloc((size_t)w * w * sizeof *v);
  for (int k = 0; k < 6; k++) {
    for (int j = 0; j < w; j++)
      for (int i = 0; i < w; i++) {
        double x = centre(i, w, extent), y = centre(j, w, extent);
        /* RenderMan's noise, 0.5 + 0.5 Perlin, off the lattice planes */
        v[(size_t)j * w + i] = k == 0 ? 0.5 + 0.5 * nl_noise_perm3_eval_general(&p, pf * x, pf * y, pf * SLICE_Z)
                                      : gctbf_at(c, labels[k], x, y, 0.5);
      }
    /* eq. 4 clamps to [0, 1]; the ramp clamps the same way */
    fig_rgb(&f, k, labels[k], nl_texture_ramp_image(&ramp, v, w, w, 0, 1));
  }
  free(v);
  nl_cellular_free(c);
  return fig_close(&f, 6, labels);
}

/* ---- Q3: eq. 6 ----------------------------------------------------------- */

static int check_q3(const char *dir, const nl_table *man)
{
  int w = (int)oracle_param(man, "size", 96), top = (int)oracle_param(man, "octaves", 4);
  double extent = oracle_param(man, "extent", 2), k = oracle_param(man, "k", 3), amp = oracle_param(man, "amp", 0.05);
  const double L[3] = {-0.5, 0.5, 0.70710678118654752};
  int n = top + 2;
  if (n > 8) {
    printf("bumps.png: %d panels, the oracle reads at most 8\n", n);
    return 1;
  }
  char lab[8][32];
  const char *labels[8];
  for (int i = 0; i < n; i++) {
    snprintf(lab[i], 32, i ? "octaves = %d" : "original", i - 1);
    labels[i] = lab[i];
  }
  fig f;
  if (fig_open(&f, dir, "bumps.png", n, w, labels, 3, "Fig. 4: F2 - F1 - F1F1 wrinkles")) return 1;
  nl_cellular *c = table(4.0, 50, NL_COUNT_INVERSE_CDF, nl_seed_replicate(run_seed(man), 0));
  size_t np = (size_t)w * w;
  double *g = calloc((size_t)(top + 1) * np, sizeof *g), *h = malloc(np * sizeof *h);
  double *sh = malloc(np * sizeof *sh);
  /* each octave's |0.5 - GCTBF(2^i k x)|, once */
  for (int o = 0; o <= top; o++)
    for (int j = 0; j < w; j++)
      for (int i = 0; i < w; i++) {
        double fr = k * ldexp(1.0, o);
        double x = centre(i, w, extent), y = centre(j, w, extent);
        g[o * np + (size_t)j * w + i] = fabs(0.5 - gctbf_at(c, "F2 - F1 - F1F1", fr * x, fr * y, fr * 0.5));
      }
  double d = extent / w;
  for (int pan = 0; pan < n; pan++) {
    for (size_t q = 0; q < np; q++) {
      double s = 0;
      for (int o = 0; o < pan; o++) s += g[o * np + q] / ldexp(1.0, o);
      h[q] = amp * s * s * s; /* the plane moves by amp x bump */
    }
    /* Lambert: the surface z = -h, its normal (dh/dx, dh/dy, 1) by central
     * differences (one-sided at the borders) */
    for (int j = 0; j < w; j++)
      for (int i = 0; i < w; i++) {
        int il = i > 0 ? i - 1 : i, ir = i < w - 1 ? i + 1 : i;
        int ju = j > 0 ? j - 1 : j, jd = j < w - 1 ? j + 1 : j;
        double hx = (h[(size_t)j * w + ir] - h[(size_t)j * w + il]) / ((ir - il) * d);
        double hy = (h[(size_t)jd * w + i] - h[(size_t)ju * w + i]) / ((jd - ju) * d);
        double dot = (hx * L[0] + hy * L[1] + L[2]) / sqrt(hx * hx + hy * hy + 1);
        sh[(size_t)j * w + i] = dot > 0 ? dot : 0;
      }
    fig_grey(&f, pan, labels[pan], sh, w, 0, 1);
  }
  free(g);
  free(h);
  free(sh);
  nl_cellular_free(c);
  return fig_close(&f, n, labels);
}

/* ---- Q4: clouds, textures, wood ------------------------------------------ */

typedef struct {
  int w, oct;
  double k, extent;
  unsigned long seed;
  nl_cellular *c;
  nl_noise_perm3 p;
} q4_run;

/* eq. 7 with smoothscale 1: sum_{i<=oct} 2^-i (1 - 2 GCTBF(2^i k x)); for
 * Perlin (name NULL) 1 - 2 (0.5 + 0.5 N) = -N on the slice z = 64/3. */
static void q4_cloud(const q4_run *q, const char *name, double *v)
{
  for (int j = 0; j < q->w; j++)
    for (int i = 0; i < q->w; i++) {
      double x = centre(i, q->w, q->extent), y = centre(j, q->w, q->extent), s = 0;
      for (int o = 0; o <= q->oct; o++) {
        double fr = q->k * ldexp(1.0, o);
        s += (name ? 1 - 2 * gctbf_at(q->c, name, fr * x, fr * y, fr * 0.5)
                   : -nl_noise_perm3_eval_general(&q->p, fr * x, fr * y, fr * SLICE_Z)) /
             ldexp(1.0, o);
      }
      v[(size_t)j * q->w + i] = s;
    }
}

/* The GCTBF itself at k x (Fig. 6's marble and wood). */
static void q4_plain(const q4_run *q, const char *name, double *v)
{
  for (int j = 0; j < q->w; j++)
    for (int i = 0; i < q->w; i++) {
      double x = centre(i, q->w, q->extent), y = centre(j, q->w, q->extent);
      v[(size_t)j * q->w + i] = gctbf_at(q->c, name, q->k * x, q->k * y, q->k * 0.5);
    }
}

/* The wood shader of nl_texture.h on the GCTBF g: rings of the distance r
 * to the axis, u = frac(freq r + turb g), t = smoothstep(0, 0.8, u) -
 * smoothstep(0.83, 1, u), mixed from light to dark. */
static double step(double a, double b, double x)
{
  double t = (x - a) / (b - a);
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  return t * t * (3 - 2 * t);
}

static nl_image *q4_wood(const q4_run *q, const nl_texture_wood *wd, const double *g)
{
  double *t = malloc((size_t)q->w * q->w * sizeof *t);
  double n = sqrt(wd->axis_d[0] * wd->axis_d[0] + wd->axis_d[1] * wd->axis_d[1] + wd->axis_d[2] * wd->axis_d[2]);
  for (int j = 0; j < q->w; j++)
    for (int i = 0; i < q->w; i++) {
      double p[3] = {centre(i, q->w, q->extent), centre(j, q->w, q->extent), 0.5}, d[3], al = 0, r2 = 0;
      for (int a = 0; a < 3; a++) {
        d[a] = p[a] - wd->axis_p[a];
        al += d[a] * wd->axis_d[a] / n;
      }
      for (int a = 0; a < 3; a++) r2 += pow(d[a] - al * wd->axis_d[a] / n, 2);
      double u = wd->ring_freq * sqrt(r2) + wd->turb * g[(size_t)j * q->w + i];
      u -= floor(u);
      t[(size_t)j * q->w + i] = step(0, 0.8, u) - step(0.83, 1, u);
    }
  nl_image *im = nl_texture_wood_image(wd, t, q->w, q->w);
  free(t);
  return im;
}

static int check_q4(const char *dir, const nl_table *man)
{
  q4_run q = {(int)oracle_param(man, "size", 96), (int)oracle_param(man, "octaves", 4), oracle_param(man, "k", 2), 2.0, 0, NULL, {{0}}};
  double rings = oracle_param(man, "wood_rings", 6), turb = oracle_param(man, "wood_turb", 8);
  q.seed = nl_seed_replicate(run_seed(man), 0);
  q.c = table(4.0, 50, NL_COUNT_INVERSE_CDF, q.seed);
  nl_noise_perm3_seed(&q.p, q.seed);
  size_t np = (size_t)q.w * q.w;
  double *v = malloc(np * sizeof *v);
  int bad = 0;

  const char *cl[6] = {"Perlin", "F1", "F2", "F1 + F1F1", "F1 + F1F2", "F1F2 + F2F3"};
  fig f;
  if (fig_open(&f, dir, "clouds.png", 6, q.w, cl, 3, "Fig. 5: eq. 7 clouds")) bad++;
  else {
    for (int k = 0; k < 6; k++) {
      q4_cloud(&q, k ? cl[k] : NULL, v);
      fig_rgb(&f, k, cl[k], nl_texture_cloud_colour(v, q.w, q.w));
    }
    bad += fig_close(&f, 6, cl);
  }

  /* the wood panels (wood.png, and Fig. 6's two wood panels) */
  const float woodc[2][3] = {{0.80f, 0.58f, 0.34f}, {0.38f, 0.20f, 0.08f}};
  const double wpos[2] = {0.0, 1.0};
  nl_texture_ramp wr = nl_texture_ramp_linear(2, wpos, woodc);
  nl_texture_wood wd[2] = {{.axis_p = {1.0, 1.0, 0.25}, .axis_d = {1.0, 0.08, 0.15}, .ring_freq = rings, .turb = turb},
                           {.axis_p = {0.9, 1.1, 0.0}, .axis_d = {0.0, 0.0, 1.0}, .ring_freq = rings, .turb = turb}};
  const char *wexpr[2] = {"F1 - F1F1", "F3 - F3F3"};
  nl_image *ramped[2], *ringed[2];
  for (int i = 0; i < 2; i++) {
    memcpy(wd[i].light, woodc[0], sizeof woodc[0]);
    memcpy(wd[i].dark, woodc[1], sizeof woodc[1]);
    q4_plain(&q, wexpr[i], v);
    ramped[i] = nl_texture_ramp_image(&wr, v, q.w, q.w, 0.0, 0.25);
    ringed[i] = q4_wood(&q, &wd[i], v);
  }
  const char *wl[4] = {"table: ramp", "table: rings", "trunk: ramp", "trunk: rings"};
  if (fig_open(&f, dir, "wood.png", 4, q.w, wl, 4, "Wood: GCTBF through a ramp, and through a wood shader")) bad++;
  else {
    for (int i = 0; i < 4; i++)
      fig_rgb(&f, i, wl[i], nl_image_convert(i % 2 ? ringed[i / 2] : ramped[i / 2], 3));
    bad += fig_close(&f, 4, wl);
  }

  const char *tl[6] = {"marble", "wood F1 - F1F1", "wood F3 - F3F3", "sky F1F2 + F2F3", "sky F1", "flame F1"};
  if (fig_open(&f, dir, "textures.png", 6, q.w, tl, 3, "Fig. 6: GCTBF textures")) bad++;
  else {
    nl_texture_ramp mr = nl_texture_ramp_cellular_marble();
    q4_plain(&q, "marble", v);
    fig_rgb(&f, 0, tl[0], nl_texture_ramp_image(&mr, v, q.w, q.w, 0, 1));
    fig_rgb(&f, 1, tl[1], nl_image_convert(ringed[0], 3));
    fig_rgb(&f, 2, tl[2], nl_image_convert(ringed[1], 3));
    q4_cloud(&q, "F1F2 + F2F3", v);
    fig_rgb(&f, 3, tl[3], nl_texture_cloud_colour(v, q.w, q.w));
    q4_cloud(&q, "F1", v);
    fig_rgb(&f, 4, tl[4], nl_texture_cloud_colour(v, q.w, q.w));
    /* flame: the fractal sum of F1, sum_i F1(2^i k x) / 2^i, over [0.2, 1]
     * through the black-red-orange-yellow-white spline */
    const float firec[6][3] = {{0, 0, 0}, {0, 0, 0}, {0.8f, 0.1f, 0.0f}, {1.0f, 0.55f, 0.0f}, {1.0f, 0.95f, 0.5f},
                               {1.0f, 1.0f, 1.0f}};
    nl_texture_ramp fr = nl_texture_ramp_spline(6, firec);
    for (int j = 0; j < q.w; j++)
      for (int i = 0; i < q.w; i++) {
        double x = centre(i, q.w, q.extent), y = centre(j, q.w, q.extent), s = 0;
        for (int o = 0; o <= q.oct; o++) {
          double fq = q.k * ldexp(1.0, o);
          s += gctbf_at(q.c, "F1", fq * x, fq * y, fq * 0.5) / ldexp(1.0, o);
        }
        v[(size_t)j * q.w + i] = s;
      }
    fig_rgb(&f, 5, tl[5], nl_texture_ramp_image(&fr, v, q.w, q.w, 0.2, 1.0));
    bad += fig_close(&f, 6, tl);
  }
  for (int i = 0; i < 2; i++) {
    nl_image_free(ramped[i]);
    nl_image_free(ringed[i]);
  }
  free(v);
  nl_cellular_free(q.c);
  return bad;
}

int main(int argc, char **argv)
{
  if (argc != 3) {
    fprintf(stderr, "usage: oracle_sq s4|q1|q2|q3|q4 OUTDIR\n");
    return 2;
  }
  const char *dir = argv[2];
  nl_table *man = oracle_read_table("oracle_sq", dir, "manifest.tsv");
  if (!man) return 2;
  int bad;
  if (!strcmp(argv[1], "s4")) bad = check_s4(dir, man);
  else if (!strcmp(argv[1], "q1")) bad = check_q1(dir, man);
  else if (!strcmp(argv[1], "q2")) bad = check_q2(dir, man);
  else if (!strcmp(argv[1], "q3")) bad = check_q3(dir, man);
  else if (!strcmp(argv[1], "q4")) bad = check_q4(dir, man);
  else {
    fprintf(stderr, "oracle_sq: %s: wanted s4, q1, q2, q3 or q4\n", argv[1]);
    bad = -1;
  }
  nl_table_free(man);
  return bad < 0 ? 2 : bad > 0;
}
