/* oracle_al - the panels of A2, A4, L1, L2, L3 and L4 against their captions.
 *
 *   oracle_al a2|a4|l1|l2|l3|l4 OUTDIR
 *
 * Each panel is recomputed from its caption by another path than the code
 * that drew it, from the run's manifest (seed, parameters), and compared
 * with the panel read back out of the PNG (oracle.h):
 *   a2  balls.png, ball.png: the smoke ball CLAMP(a d + 1 + Fnoise(f0 p)) at
 *       N = 0, 1, 2, 5, 7, 10 (N + offset terms), ray-marched here one ray
 *       and one sample at a time without bounding (the figure shows the
 *       bounded march, which leaves every pixel as it is), first seed;
 *       bounds.png: the terms eq. 5.4 needs per pixel of the slice z = 0;
 *   a4  normalised.png: noise(p) and noise(p / F_sup), F_sup = 1.7460938
 *       (Table 5.2), on the plane z = 0.5, point by point;
 *   l1  noise.png: band k of 2D and of 3D wavelet noise by the tile's point
 *       calls, and their power spectra by a direct DFT (rows, then columns);
 *   l2  noise.png: (b) the noise of the true weights, (d) that of eq. 12's
 *       weights as weights.tsv prints them, by point calls;
 *   l3  synthesis_KIND.png: the exemplar and its five syntheses, each
 *       channel's multiresolution noise by point calls, histogram matched
 *       and recorrelated here (M^T c + mean), red channel compared;
 *   l4  editing.png (synthesis, edited, two solid slices) and morph.png,
 *       the same way.
 * A panel that shows another seed, another band or octave, another divisor
 * or another variant fails on grey levels and correlation. Exit 0 when
 * every panel matches, 1 with one line per mismatch, 2 on a bad call.
 */
#include "oracle.h"

#include "base/nl_base.h"
#include "byexample/nl_byexample.h"
#include "byexample/nl_byexample_leak.h"
#include "noise/nl_noise.h"
#include "study/nl_study_exemplars.h"
#include "table/nl_table.h"
#include "texture/nl_texture.h"
#include "wavelet/nl_wavelet.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static unsigned long run_seed(const nl_table *m)
{
  const char *s = oracle_manifest_value(m, "seed");
  return s ? strtoul(s, NULL, 10) : 1;
}

/* Reports panel i of m against v (w x h, mapped lo..hi); returns 1 if it
 * differs. */
static int judge(const char *file, const oracle_montage *m, int i, const char *label, const double *v,
                 int w, int h, double lo, double hi)
{
  oracle_result res = oracle_panel_compare(m, i, v, w, h, lo, hi);
  if (res.max_diff > ORACLE_TOL_8BIT || res.corr < 0.999) {
    printf("%s: panel %s is not its caption: max grey difference %.4f at (%d, %d), correlation %.4f\n",
           file, label, res.max_diff, res.x, res.y, res.corr);
    return 1;
  }
  return 0;
}

/* The same for a colour panel's channel v, in [0, 1] but for the excursions
 * a synthesis makes: the montage box-filters the image as it is and the PNG
 * clamps afterwards, so the expected values are reduced unclamped and
 * clamped last. */
static int judge_colour(const char *file, const oracle_montage *m, int i, const char *label,
                        const double *v, int w, int h)
{
  nl_image *full = nl_image_alloc(w, h, 1);
  for (size_t k = 0; k < (size_t)w * h; k++) full->data[k] = (float)v[k];
  nl_image *e = m->g.factor > 1 ? nl_image_downsample(full, m->g.factor) : full;
  double *c = malloc((size_t)e->width * e->height * sizeof *c);
  for (size_t k = 0; k < (size_t)e->width * e->height; k++)
    c[k] = e->data[k] < 0 ? 0 : e->data[k] > 1 ? 1 : e->data[k];
  /* c is already at the panel's size: compared with factor 1 */
  oracle_montage one = *m;
  one.g.factor = 1;
  int bad = judge(file, &one, i, label, c, e->width, e->height, 0, 1);
  if (e != full) nl_image_free(e);
  nl_image_free(full);
  free(c);
  return bad;
}

static int open_montage(oracle_montage *m, const char *dir, const char *file, const int *w, const int *h,
                        const char *const *labels, int n, int cols, const char *title)
{
  char path[1024];
  snprintf(path, sizeof path, "%s/%s", dir, file);
  if (oracle_montage_read(m, path, w, h, labels, n, cols, title)) {
    printf("%s: %s\n", file, m->err);
    oracle_montage_free(m);
    return 1;
  }
  return 0;
}

/* Captions that differ show different pictures. */
static int distinct(const char *file, const oracle_montage *m, const char *const *labels, int n)
{
  int bad = 0;
  for (int i = 0; i + 1 < n; i++) {
    double c = oracle_panels_corr(m, i, i + 1);
    if (c > 0.9999) {
      printf("%s: panels %s and %s show one picture (correlation %.5f)\n", file, labels[i], labels[i + 1], c);
      bad++;
    }
  }
  return bad;
}

/* ---- A2: the smoke ball -------------------------------------------------- */

typedef struct {
  int size;
  double step, stop, slope, freq, kappa;
} smoke;

/* One ray per pixel along +z through [-1/2, 1/2]^3, every sample of every
 * term, for n term counts at once (the octaves of the longest sum serve
 * the shorter ones): T <- T exp(-kappa dens h), colour += the light
 * absorbed, until T reaches 1 - stop. img[i] gets terms[i]'s image. */
static void smoke_march(const nl_noise_perm3 *p, const smoke *s, const int *terms, int n, double **img)
{
  long nsteps = (long)floor(1.0 / s->step);
  int most = 0;
  for (int i = 0; i < n; i++) most = terms[i] > most ? terms[i] : most;
  for (int r = 0; r < s->size; r++)
    for (int c = 0; c < s->size; c++) {
      double x = -0.5 + (c + 0.5) / s->size, y = -0.5 + (r + 0.5) / s->size, tr[8], col[8];
      for (int i = 0; i < n; i++) tr[i] = 1, col[i] = 0;
      for (long k = 0; k <= nsteps; k++) {
        int need = 0;
        for (int i = 0; i < n; i++)
          if (tr[i] > 1.0 - s->stop && terms[i] > need) need = terms[i];
        if (!need && most) break;
        double z = -0.5 + (double)k * s->step, d = sqrt(x * x + y * y + z * z);
        double part[40], f = s->freq, a = 1;
        part[0] = s->slope * d + 1.0;
        for (int l = 0; l < need; l++, f *= 2, a *= 0.5)
          part[l + 1] = part[l] + a * nl_noise_perm3_eval_general(p, f * x, f * y, f * z);
        for (int i = 0; i < n; i++) {
          if (!(tr[i] > 1.0 - s->stop)) continue;
          double dens = part[terms[i]];
          dens = dens < 0 ? 0 : dens > 1 ? 1 : dens;
          double t1 = tr[i] * exp(-s->kappa * dens * s->step);
          col[i] += tr[i] - t1;
          tr[i] = t1;
        }
      }
      for (int i = 0; i < n; i++) img[i][(size_t)r * s->size + c] = col[i];
    }
}

/* bounds.png, Fig. 5.3: per pixel of the slice z = 0 at the largest N, how
 * many terms were summed before eq. 5.4's interval (partial +- the
 * octave bound times the remaining amplitudes) left (0, 1), N + offset + 1
 * where it never did; coloured by the figure's ramp (a2_smoke_decision_image)
 * and compared channel by channel. A pixel whose partial sum lands on the
 * interval's edge may be decided one term apart by two roundings: at most
 * 0.1% of the pixels may differ. */
static int check_a2_bounds(const char *dir, const nl_table *man, const smoke *s, int terms)
{
  double bound = oracle_param(man, "octave_bound", NL_NOISE3_BOUND), rem[40];
  rem[terms] = 0;
  for (int k = terms - 1; k >= 0; k--) rem[k] = rem[k + 1] + bound * ldexp(1.0, -k);
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, run_seed(man));
  int n = s->size;
  double *v = malloc((size_t)n * n * sizeof *v);
  for (int r = 0; r < n; r++)
    for (int c = 0; c < n; c++) {
      double x = -0.5 + (c + 0.5) / n, y = -0.5 + (r + 0.5) / n, base = s->slope * sqrt(x * x + y * y) + 1;
      double part = 0, f = s->freq;
      int k = 0;
      for (; k <= terms; k++, f *= 2) {
        if (base + part + rem[k] <= 0 || base + part - rem[k] >= 1) break;
        if (k < terms) part += ldexp(1.0, -k) * nl_noise_perm3_eval_general(&p, f * x, f * y, 0.0);
      }
      v[(size_t)r * n + c] = k; /* terms + 1: never decided */
    }
  const double pos[] = {0.0, 0.25 * terms, 0.5 * terms, 0.75 * terms, terms, terms + 0.5, terms + 1};
  const float rgb[][3] = {{0.1f, 0.2f, 0.9f}, {0.1f, 0.8f, 0.9f}, {0.2f, 0.8f, 0.2f}, {0.95f, 0.85f, 0.1f},
                          {0.9f, 0.1f, 0.1f}, {0.9f, 0.1f, 0.1f}, {0, 0, 0}};
  nl_texture_ramp ramp = nl_texture_ramp_linear(7, pos, rgb);
  nl_image *e = nl_texture_ramp_image(&ramp, v, n, n, 0.0, 1.0), *im = NULL;
  char path[1024];
  snprintf(path, sizeof path, "%s/bounds.png", dir);
  nl_error err;
  int bad = 0;
  if (nl_image_read(path, &im, &err) || im->width != n || im->height != n || im->channels < 3) {
    printf("bounds.png: %s\n", im ? "not the size of the slice" : err.msg);
    bad = 1;
  } else {
    long off = 0;
    for (int y = 0; y < n; y++)
      for (int x = 0; x < n; x++)
        for (int ch = 0; ch < 3; ch++)
          if (fabs(nl_image_pixel(im, x, y)[ch] - nl_image_pixel(e, x, y)[ch]) > ORACLE_TOL_8BIT) {
            off++;
            break;
          }
    if (off > (long)n * n / 1000) {
      printf("bounds.png: %ld of %d pixels are not the terms eq. 5.4 needs\n", off, n * n);
      bad = 1;
    }
  }
  nl_image_free(im);
  nl_image_free(e);
  free(v);
  return bad;
}

static int check_a2(const char *dir, const nl_table *man)
{
  static const int label[6] = {0, 1, 2, 5, 7, 10};
  smoke s = {(int)oracle_param(man, "size", 32), oracle_param(man, "step", 0.01), oracle_param(man, "stop_opacity", 0.99),
             oracle_param(man, "slope", -5), oracle_param(man, "freq", 2), oracle_param(man, "kappa", 15360)};
  int offset = (int)oracle_param(man, "offset", 1), w[6], h[6], bad = 0;
  char lab[6][32];
  const char *labels[6];
  for (int i = 0; i < 6; i++) {
    w[i] = h[i] = s.size;
    snprintf(lab[i], sizeof lab[i], "N = %d", label[i]);
    labels[i] = lab[i];
  }
  oracle_montage m;
  if (open_montage(&m, dir, "balls.png", w, h, labels, 6, 3, "Smoke ball, incremental bounding")) return 1;
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, nl_seed_replicate(run_seed(man), 0));
  double *img[6];
  int terms[6];
  for (int i = 0; i < 6; i++) {
    img[i] = malloc((size_t)s.size * s.size * sizeof *img[i]);
    terms[i] = label[i] + offset;
  }
  smoke_march(&p, &s, terms, 6, img);
  for (int i = 0; i < 6; i++) bad += judge("balls.png", &m, i, labels[i], img[i], s.size, s.size, 0, 1);
  double *v = img[5];
  /* no distinctness check: at a small size the finest octaves of N = 7 and
   * N = 10 fall below a pixel and the two balls may agree to 8 bits */
  oracle_montage_free(&m);
  /* ball.png: the last panel alone, at full size */
  char path[1024];
  snprintf(path, sizeof path, "%s/ball.png", dir);
  nl_image *im = NULL;
  nl_error err;
  if (nl_image_read(path, &im, &err) || im->width != s.size || im->height != s.size) {
    printf("ball.png: %s\n", im ? "not the size of the render" : err.msg);
    bad++;
  } else {
    oracle_montage one = {im, {0}, calloc(1, sizeof(nl_image_rect)), 1, ""};
    one.g.factor = 1;
    one.rect[0] = (nl_image_rect){0, 0, s.size, s.size};
    bad += judge("ball.png", &one, 0, "N = 10", v, s.size, s.size, 0, 1);
    free(one.rect);
  }
  nl_image_free(im);
  for (int i = 0; i < 6; i++) free(img[i]);
  return bad + check_a2_bounds(dir, man, &s, label[5] + offset);
}

/* ---- A4: normalised noise ------------------------------------------------ */

static int check_a4(const char *dir, const nl_table *man)
{
  int size = (int)oracle_param(man, "size", 96);
  double rate = oracle_param(man, "rate", 2), extent = size / rate, div[2] = {1.0, 1.7460938};
  const char *labels[2] = {"(a) noise(x)", "(b) noise(x / F_sup)"};
  int w[2] = {size, size}, bad = 0;
  char title[96];
  snprintf(title, sizeof title, "Fig. 5.7: %g samples per unit", rate);
  oracle_montage m;
  if (open_montage(&m, dir, "normalised.png", w, w, labels, 2, 2, title)) return 1;
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, run_seed(man));
  double *v = malloc((size_t)size * size * sizeof *v);
  for (int i = 0; i < 2; i++) {
    double f = 1.0 / div[i], d = extent / size;
    for (int y = 0; y < size; y++)
      for (int x = 0; x < size; x++)
        v[(size_t)y * size + x] = nl_noise_perm3_eval_general(&p, f * (x + 0.5) * d, f * (y + 0.5) * d, f * 0.5);
    bad += judge("normalised.png", &m, i, labels[i], v, size, size, -1, 1);
  }
  free(v);
  oracle_montage_free(&m);
  return bad;
}

/* ---- wavelet noise by point calls ---------------------------------------- */

/* sum_k w[k] N(2^-k (x + 1/2, y + 1/2, z) + o_k) at every pixel of a w x h
 * raster, one point call at a time. */
static void bands_points(const nl_wavelet_tile *t, const nl_wavelet_bands *b, int w, int h, double z,
                         double *out)
{
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      double s = 0;
      for (int k = 0; k < b->nbands; k++) {
        if (b->w[k] == 0) continue;
        double sc = ldexp(1.0, -k), px = (x + 0.5) * sc + b->off[k][0], py = (y + 0.5) * sc + b->off[k][1];
        s += b->w[k] * (t->dim == 3 ? nl_wavelet_eval3(t, px, py, z * sc + b->off[k][2])
                                    : nl_wavelet_eval2(t, px, py));
      }
      out[(size_t)y * w + x] = s;
    }
}

/* The power spectrum of a w x w image by a direct DFT (rows, then columns),
 * log10, DC at the centre: out gets log10 |F|^2 and *top its largest
 * value off the DC (the figure shows top - decades .. top). */
static void dft_log_power(const double *img, int w, double *out, double *top)
{
  size_t n = (size_t)w * w;
  double *re = calloc(n, sizeof *re), *im = calloc(n, sizeof *im);
  double *cs = malloc((size_t)w * sizeof *cs), *sn = malloc((size_t)w * sizeof *sn);
  for (int k = 0; k < w; k++) {
    cs[k] = cos(2 * M_PI * k / w);
    sn[k] = sin(2 * M_PI * k / w);
  }
  for (int y = 0; y < w; y++) /* rows */
    for (int u = 0; u < w; u++) {
      double a = 0, b = 0;
      for (int x = 0; x < w; x++) {
        int k = (int)(((long)u * x) % w);
        a += img[(size_t)y * w + x] * cs[k];
        b -= img[(size_t)y * w + x] * sn[k];
      }
      re[(size_t)y * w + u] = a;
      im[(size_t)y * w + u] = b;
    }
  *top = -INFINITY;
  double *cr = malloc((size_t)w * sizeof *cr), *ci = malloc((size_t)w * sizeof *ci);
  for (int u = 0; u < w; u++) { /* columns */
    for (int y = 0; y < w; y++) {
      cr[y] = re[(size_t)y * w + u];
      ci[y] = im[(size_t)y * w + u];
    }
    for (int v = 0; v < w; v++) {
      double a = 0, b = 0;
      for (int y = 0; y < w; y++) {
        int k = (int)(((long)v * y) % w);
        a += cr[y] * cs[k] + ci[y] * sn[k];
        b += ci[y] * cs[k] - cr[y] * sn[k];
      }
      double l = log10((a * a + b * b) / ((double)n * n) + 1e-300);
      out[(size_t)((v + w / 2) % w) * w + (size_t)((u + w / 2) % w)] = l;
      if (u || v) *top = fmax(*top, l);
    }
  }
  free(re);
  free(im);
  free(cs);
  free(sn);
  free(cr);
  free(ci);
}

/* ---- L1: one band of wavelet noise and its spectrum ---------------------- */

static int check_l1(const char *dir, const nl_table *man)
{
  int size = (int)oracle_param(man, "size", 128), tile = (int)oracle_param(man, "tile", NL_BYEXAMPLE_TILE);
  int tile3 = (int)oracle_param(man, "tile3", 32), band = (int)oracle_param(man, "band", 2), bad = 0;
  unsigned long seed = run_seed(man);
  int w3 = size < (tile3 << band) ? size : tile3 << band;
  char lb[64], title[96];
  snprintf(lb, sizeof lb, w3 == tile3 << band ? "(b) 3D slice, one period" : "(b) 3D slice, %d px", w3);
  const char *labels[4] = {"(a) 2D wavelet noise", lb, "(c) power spectrum of (a)", "(d) power spectrum of (b)"};
  snprintf(title, sizeof title, "One band (k = %d: 1/%d..1/%d cycles per pixel)", band, 4 << band, 2 << band);
  int w[4] = {size, w3, size, w3};
  oracle_montage m;
  if (open_montage(&m, dir, "noise.png", w, w, labels, 4, 2, title)) return 1;
  double wt[NL_WAVELET_MAX_BANDS] = {0};
  wt[band] = 1;
  nl_wavelet_tile *t2 = nl_wavelet_tile_alloc(2, tile), *t3 = nl_wavelet_tile_alloc(3, tile3);
  nl_wavelet_tile_seed(t2, seed);
  nl_wavelet_tile_seed(t3, seed);
  nl_wavelet_bands b;
  double *a = malloc((size_t)size * size * sizeof *a), *c = malloc((size_t)w3 * w3 * sizeof *c);
  double *l = malloc((size_t)size * size * sizeof *l), top;
  nl_wavelet_bands_init(&b, band + 1, wt, tile, seed, NULL);
  bands_points(t2, &b, size, size, 0, a);
  nl_wavelet_bands_init(&b, band + 1, wt, tile3, seed, NULL);
  bands_points(t3, &b, w3, w3, 3.3, c);
  bad += judge("noise.png", &m, 0, labels[0], a, size, size, -1.5, 1.5);
  bad += judge("noise.png", &m, 1, labels[1], c, w3, w3, -1.5, 1.5);
  dft_log_power(a, size, l, &top);
  bad += judge("noise.png", &m, 2, labels[2], l, size, size, top - 4, top);
  dft_log_power(c, w3, l, &top);
  bad += judge("noise.png", &m, 3, labels[3], l, w3, w3, top - 4, top);
  free(a);
  free(c);
  free(l);
  nl_wavelet_tile_free(t2);
  nl_wavelet_tile_free(t3);
  oracle_montage_free(&m);
  return bad;
}

/* ---- L2: Fig. 4's two noises --------------------------------------------- */

static int check_l2(const char *dir, const nl_table *man)
{
  int size = (int)oracle_param(man, "size", 128), tile = (int)oracle_param(man, "tile", NL_BYEXAMPLE_TILE), bad = 0;
  unsigned long seed = run_seed(man);
  int nb = nl_byexample_band_count(size, size);
  const char *labels[2] = {"(b) true weights", "(d) estimated weights"};
  int w[2] = {size, size};
  oracle_montage m;
  if (open_montage(&m, dir, "noise.png", w, w, labels, 2, 2, "Fig. 4: validation of noise by example")) return 1;
  /* the true weights as nl_byexample_trial draws them; eq. 12's from weights.tsv */
  double truth[NL_WAVELET_MAX_BANDS], est[NL_WAVELET_MAX_BANDS], ss = 0;
  unsigned long ts = nl_seed_stream(seed, "byexample.true_weights", 0);
  gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(g, ts);
  for (int k = 0; k < nb; k++) truth[k] = gsl_rng_uniform(g);
  gsl_rng_free(g);
  for (int k = 0; k < nb; k++) {
    truth[k] = NL_BYEXAMPLE_TRUE_WEIGHT_MIN + (NL_BYEXAMPLE_TRUE_WEIGHT_MAX - NL_BYEXAMPLE_TRUE_WEIGHT_MIN) * truth[k];
    ss += truth[k] * truth[k];
  }
  char path[1024];
  snprintf(path, sizeof path, "%s/weights.tsv", dir);
  nl_table *wt = NULL;
  nl_error err;
  if (nl_table_read(path, NL_TABLE_TEXT, &wt, &err) || (int)wt->nrows != nb) {
    printf("weights.tsv: %s\n", wt ? "not one row per band" : err.msg);
    nl_table_free(wt);
    oracle_montage_free(&m);
    return 1;
  }
  for (int k = 0; k < nb; k++) est[k] = nl_table_value(wt, (size_t)k, "est");
  nl_table_free(wt);
  double sd = sqrt(nl_byexample_sigma2(tile) * ss);
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(2, tile);
  nl_wavelet_tile_seed(t, seed);
  nl_wavelet_bands b;
  double *v = malloc((size_t)size * size * sizeof *v);
  nl_wavelet_bands_init(&b, nb, truth, tile, seed, NULL);
  bands_points(t, &b, size, size, 0, v);
  bad += judge("noise.png", &m, 0, labels[0], v, size, size, -3 * sd, 3 * sd);
  nl_wavelet_bands_init(&b, nb, est, tile, nl_seed_stream(seed, "l2.new_offsets", 0), NULL);
  bands_points(t, &b, size, size, 0, v);
  bad += judge("noise.png", &m, 1, labels[1], v, size, size, -3 * sd, 3 * sd);
  free(v);
  nl_wavelet_tile_free(t);
  oracle_montage_free(&m);
  return bad;
}

/* ---- L3, L4: syntheses by example ---------------------------------------- */

/* The synthesis of p (no calibration) at size x size, seed, solid slice z
 * when solid: each channel's bands by point calls, matched to its
 * histogram, recorrelated by M^T c + mean; channel ch into out. */
static void synth_points(const nl_byexample_params *p, int size, unsigned long seed, int solid, double z,
                         nl_byexample_spline_kind spline, int ch, double *out)
{
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(solid ? 3 : 2, solid ? NL_BYEXAMPLE_TILE3 : p->tile);
  nl_wavelet_tile_seed(t, seed);
  double gain = sqrt(p->sigma2 / nl_wavelet_tile_variance(t, solid ? 2 : 4));
  size_t n = (size_t)size * size;
  double *plane[3];
  for (int c = 0; c < p->channels; c++) {
    plane[c] = malloc(n * sizeof *plane[c]);
    double wts[NL_WAVELET_MAX_BANDS], ss = 0;
    for (int k = 0; k < p->nbands; k++) {
      wts[k] = gain * p->w[c][k];
      ss += p->w[c][k] * p->w[c][k];
    }
    nl_wavelet_bands b;
    nl_wavelet_bands_init(&b, p->nbands, wts, t->n, nl_seed_stream(seed, "example.channel", (unsigned long)c), NULL);
    bands_points(t, &b, size, size, z, plane[c]);
    if (p->histogram) {
      double sm = sqrt(p->sigma2 * ss);
      if (sm > 0)
        nl_byexample_match_kind(plane[c], n, sm, p->hist_kind, p->hist[c], spline);
      else
        for (size_t i = 0; i < n; i++) plane[c][i] = p->hist[c][p->nhist / 2];
    }
  }
  for (size_t i = 0; i < n; i++) {
    double s = p->mean[ch];
    for (int r = 0; r < p->channels; r++) s += p->matrix[r][ch] * plane[r][i];
    out[i] = s;
  }
  for (int c = 0; c < p->channels; c++) free(plane[c]);
  nl_wavelet_tile_free(t);
}

static void red(const nl_image *im, double *out)
{
  for (size_t i = 0; i < (size_t)im->width * im->height; i++) out[i] = im->data[i * im->channels];
}

static int check_l3(const char *dir, const nl_table *man)
{
  static const char *kinds[4] = {"wavelet", "clouds", "granite", "marble"};
  const char *labels[6] = {"(a) exemplar", "(b) paper", "(c) no hist.", "(d) RGB", "(e) FC", "(f) gauss33"};
  /* {decorrelate, histogram, sigma2, tile, hist_kind, calibrate} of each panel's analysis */
  const nl_byexample_options opt[5] = {{1, 1, 0, 0, NL_HIST_PAPER, 0}, {1, 0, 0, 0, NL_HIST_PAPER, 0},
                                       {0, 1, 0, 0, NL_HIST_PAPER, 0}, {1, 1, 0, 0, NL_HIST_PAPER, 0},
                                       {1, 1, 0, 0, NL_HIST_GAUSS, 0}};
  int size = (int)oracle_param(man, "size", 128), bad = 0, w[6];
  unsigned long seed = run_seed(man);
  for (int i = 0; i < 6; i++) w[i] = size;
  double *v = malloc((size_t)size * size * sizeof *v);
  for (int k = 0; k < 4; k++) {
    char file[64], title[96];
    snprintf(file, sizeof file, "synthesis_%s.png", kinds[k]);
    snprintf(title, sizeof title, "%s exemplar, %d x %d, seed %lu", kinds[k], size, size, seed);
    oracle_montage m;
    if (open_montage(&m, dir, file, w, w, labels, 6, 6, title)) {
      bad++;
      continue;
    }
    nl_image *ex = nl_byexample_exemplar(kinds[k], size, nl_seed_stream(seed, "l3.exemplar", (unsigned long)k));
    red(ex, v);
    bad += judge_colour(file, &m, 0, labels[0], v, size, size);
    for (int i = 0; i < 5; i++) {
      nl_byexample_params p;
      nl_error err;
      if (nl_byexample_analyse(ex, &opt[i], &p, &err)) {
        printf("%s: %s\n", file, err.msg);
        bad++;
        continue;
      }
      synth_points(&p, size, nl_seed_replicate(seed, 0), 0, 0,
                   i == 3 ? NL_SPLINE_FRITSCH_CARLSON : NL_SPLINE_STEFFEN, 0, v);
      bad += judge_colour(file, &m, i + 1, labels[i + 1], v, size, size);
    }
    nl_image_free(ex);
    oracle_montage_free(&m);
  }
  free(v);
  return bad;
}

/* photos_montage.png: per photograph (the first `photos` PNGs of the run's
 * exemplars folder, by name) the photo and the top-left crops of its
 * gauss33, paper10 and calibrated syntheses (replicate 0). The first two
 * are recomputed by point calls (no pixel of them depends on the image's
 * size); the calibrated one adjusts its bands by FFTs of the whole output,
 * which only nl_byexample_synthesize does: it is compared with that call,
 * which checks the montage (crop, order, replicate), not the calibration. */
static int check_l3_photos(const char *dir, const nl_table *man)
{
  const char *ex = oracle_manifest_value(man, "exemplars");
  if (!ex) ex = "data/exemplars"; /* --exemplars' default */
  int np = (int)oracle_param(man, "photos", 2), size = (int)oracle_param(man, "photo_size", 128), bad = 0;
  int c = size < 256 ? size : 256;
  unsigned long seed = run_seed(man);
  char exdir[1024];
  /* a relative folder is the repository's, two levels above a results folder */
  snprintf(exdir, sizeof exdir, "%s", ex);
  struct stat sb;
  if (ex[0] != '/' && stat(exdir, &sb)) snprintf(exdir, sizeof exdir, "%s/../../%s", dir, ex);
  char **paths = NULL;
  int n = 0;
  nl_error err;
  if (nl_study_pngs(exdir, &paths, &n, &err)) {
    printf("photos_montage.png: %s\n", err.msg);
    return 1;
  }
  np = np < n ? np : n;
  int *w = calloc((size_t)4 * np, sizeof *w), *h = calloc((size_t)4 * np, sizeof *h);
  char(*lab)[96] = calloc((size_t)4 * np, sizeof *lab);
  const char **labels = calloc((size_t)4 * np, sizeof *labels);
  nl_image **photo = calloc((size_t)np, sizeof *photo);
  const char *rep[3] = {"gauss33", "paper10", "calibrated"};
  for (int i = 0; i < np; i++) {
    if (nl_image_read(paths[i], &photo[i], &err)) {
      printf("photos_montage.png: %s\n", err.msg);
      bad++;
      np = i;
      break;
    }
    const char *base = strrchr(paths[i], '/') ? strrchr(paths[i], '/') + 1 : paths[i];
    snprintf(lab[4 * i], sizeof lab[0], "%.*s %dx%d", (int)(strlen(base) - 4), base, photo[i]->width,
             photo[i]->height);
    w[4 * i] = photo[i]->width;
    h[4 * i] = photo[i]->height;
    for (int k = 0; k < 3; k++) {
      snprintf(lab[4 * i + 1 + k], sizeof lab[0], "%s", rep[k]);
      w[4 * i + 1 + k] = h[4 * i + 1 + k] = c;
    }
  }
  for (int i = 0; i < 4 * np; i++) labels[i] = lab[i];
  char title[128];
  snprintf(title, sizeof title, "photographs | synthesis %d x %d (seed %lu), top-left %d x %d", size, size,
           seed, c, c);
  oracle_montage m;
  if (!bad && !open_montage(&m, dir, "photos_montage.png", w, h, labels, 4 * np, 4, title)) {
    double *v = malloc((size_t)4096 * 4096 * sizeof *v);
    for (int i = 0; i < np; i++) {
      red(photo[i], v);
      bad += judge_colour("photos_montage.png", &m, 4 * i, labels[4 * i], v, photo[i]->width, photo[i]->height);
      const nl_byexample_hist_kind kinds[3] = {NL_HIST_GAUSS, NL_HIST_PAPER, NL_HIST_GAUSS};
      for (int k = 0; k < 3; k++) {
        nl_byexample_options o = {1, 1, 0, 0, kinds[k], k == 2 ? NL_BYEXAMPLE_CALIBRATE : 0};
        nl_byexample_params p;
        if (nl_byexample_analyse(photo[i], &o, &p, &err)) {
          printf("photos_montage.png: %s\n", err.msg);
          bad++;
          continue;
        }
        if (k < 2)
          synth_points(&p, c, nl_seed_replicate(seed, 0), 0, 0, NL_SPLINE_STEFFEN, 0, v);
        else {
          nl_image *syn;
          if (nl_byexample_synthesize(&p, size, size, nl_seed_replicate(seed, 0), NULL, &syn, &err)) {
            printf("photos_montage.png: %s\n", err.msg);
            bad++;
            continue;
          }
          for (int y = 0; y < c; y++)
            for (int x = 0; x < c; x++) v[(size_t)y * c + x] = nl_image_pixel(syn, x, y)[0];
          nl_image_free(syn);
        }
        bad += judge_colour("photos_montage.png", &m, 4 * i + 1 + k, labels[4 * i + 1 + k], v, c, c);
      }
    }
    free(v);
    oracle_montage_free(&m);
  } else
    bad++;
  for (int i = 0; i < np; i++) nl_image_free(photo[i]);
  nl_study_paths_free(paths);
  free(photo);
  free(w);
  free(h);
  free(lab);
  free(labels);
  return bad;
}

static int check_l4(const char *dir, const nl_table *man)
{
  int size = (int)oracle_param(man, "size", 128), nfine = (int)oracle_param(man, "edit_bands", 3), bad = 0;
  double factor = oracle_param(man, "edit_factor", 0.25);
  unsigned long seed = run_seed(man);
  nl_error err;
  nl_image *ex = nl_byexample_exemplar("granite", size, nl_seed_stream(seed, "l4.exemplar", 0));
  nl_image *ex2 = nl_byexample_exemplar("clouds", size, nl_seed_stream(seed, "l4.exemplar2", 0));
  nl_byexample_params p, pe, pc;
  if (nl_byexample_analyse(ex, NULL, &p, &err) || nl_byexample_analyse(ex2, NULL, &pc, &err)) {
    printf("l4: %s\n", err.msg);
    return 1;
  }
  pe = p;
  nl_byexample_attenuate(&pe, nfine, factor);
  const char *labels[5] = {"(a) exemplar", "(b) synthesis", "(c) edited", "(d) solid z=0", "(d') z=size/4"};
  int w[5];
  for (int i = 0; i < 5; i++) w[i] = size;
  double *v = malloc((size_t)size * size * sizeof *v);
  oracle_montage m;
  if (!open_montage(&m, dir, "editing.png", w, w, labels, 5, 5, "Fig. 10: editing and solid extrapolation")) {
    red(ex, v);
    bad += judge_colour("editing.png", &m, 0, labels[0], v, size, size);
    synth_points(&p, size, seed, 0, 0, NL_SPLINE_STEFFEN, 0, v);
    bad += judge_colour("editing.png", &m, 1, labels[1], v, size, size);
    synth_points(&pe, size, seed, 0, 0, NL_SPLINE_STEFFEN, 0, v);
    bad += judge_colour("editing.png", &m, 2, labels[2], v, size, size);
    synth_points(&p, size, seed, 1, 0.0, NL_SPLINE_STEFFEN, 0, v);
    bad += judge_colour("editing.png", &m, 3, labels[3], v, size, size);
    synth_points(&p, size, seed, 1, size / 4.0, NL_SPLINE_STEFFEN, 0, v);
    bad += judge_colour("editing.png", &m, 4, labels[4], v, size, size);
    oracle_montage_free(&m);
  } else
    bad++;
  const char *tl[5] = {"t = 0", "t = 0.25", "t = 0.5", "t = 0.75", "t = 1"};
  if (!open_montage(&m, dir, "morph.png", w, w, tl, 5, 5, "Fig. 12: morphing clouds into granite")) {
    for (int i = 0; i < 5; i++) {
      nl_byexample_params q;
      if (nl_byexample_morph(&pc, &p, i / 4.0, &q, &err)) {
        printf("morph.png: %s\n", err.msg);
        bad++;
        continue;
      }
      synth_points(&q, size, seed, 0, 0, NL_SPLINE_STEFFEN, 0, v);
      bad += judge_colour("morph.png", &m, i, tl[i], v, size, size);
    }
    bad += distinct("morph.png", &m, tl, 5);
    oracle_montage_free(&m);
  } else
    bad++;
  free(v);
  nl_image_free(ex);
  nl_image_free(ex2);
  return bad;
}

int main(int argc, char **argv)
{
  if (argc != 3) {
    fprintf(stderr, "usage: oracle_al a2|a4|l1|l2|l3|l4 OUTDIR\n");
    return 2;
  }
  const char *dir = argv[2];
  nl_table *man = oracle_read_table("oracle_al", dir, "manifest.tsv");
  if (!man) return 2;
  int bad;
  if (!strcmp(argv[1], "a2")) bad = check_a2(dir, man);
  else if (!strcmp(argv[1], "a4")) bad = check_a4(dir, man);
  else if (!strcmp(argv[1], "l1")) bad = check_l1(dir, man);
  else if (!strcmp(argv[1], "l2")) bad = check_l2(dir, man);
  else if (!strcmp(argv[1], "l3")) bad = check_l3(dir, man) + check_l3_photos(dir, man);
  else if (!strcmp(argv[1], "l4")) bad = check_l4(dir, man);
  else {
    fprintf(stderr, "oracle_al: unknown id '%s'\n", argv[1]);
    nl_table_free(man);
    return 2;
  }
  nl_table_free(man);
  return bad ? 1 : 0;
}
