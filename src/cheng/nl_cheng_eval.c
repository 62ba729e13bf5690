/* Final measures of an optimised table, controlled values on a raster, and
 * the one-run loop the experiments share (the textures of sec. 4.1 are
 * images: src/study/nl_study_cheng_image.c). */
#include "cheng/nl_cheng_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static double amp_scale(const nl_noise_octaves *o)
{
  double a = 0;
  for (int l = 0; l < o->n; l++) a += o->amp[l];
  return 1.0 / (NL_NOISE2_BOUND * a);
}

/* E_Con over all F octaves with the noise kernel itself (nl_noise_grad2_eval), an
 * evaluation path independent of the optimiser's stored corners; with out !=
 * NULL also Pearson's r of the control value c and the target D over the n
 * points, and E_Con's three parts. With population means and sds,
 *   sum (c - D)^2 = n (mc - mD)^2 + n (sc - sD)^2 + 2 n sc sD (1 - r),
 * an offset, a contrast and a shape term: an E_Con above the flat image's is
 * explained by which of them dominates. */
static double control_error(const nl_noise_grad2 *g, const nl_cheng_config *c, const nl_cheng_pattern *pat,
                            nl_cheng_eval *out)
{
  nl_noise_octaves o = nl_cheng_octaves(c);   /* with the config's gains (X6) */
  double s = amp_scale(&o), e = 0, nv[NL_CHENG_MAX_OCTAVES];
  double sv = 0, sd = 0, svv = 0, sdd = 0, svd = 0, n = (double)pat->n;
  for (size_t i = 0; i < pat->n; i++) {
    for (int l = 0; l < o.n; l++)
      nv[l] = nl_noise_grad2_eval(g, o.freq[l] * (c->origin + pat->x[i]), o.freq[l] * (c->origin + pat->y[i]));
    double v = nl_cheng__control_value(c->con, nv, o.amp, o.n, s, c->literal), d = v - pat->d[i];
    e += d * d;
    sv += v; sd += pat->d[i]; svv += v * v; sdd += pat->d[i] * pat->d[i]; svd += v * pat->d[i];
  }
  if (out) {
    double cov = svd - sv * sd / n, vv = svv - sv * sv / n, dd = sdd - sd * sd / n;
    double r = vv > 0 && dd > 0 ? cov / sqrt(vv * dd) : 0;   /* a flat value or pattern: no correlation */
    double sc = sqrt(fmax(vv, 0) / n), sD = sqrt(fmax(dd, 0) / n), dm = (sv - sd) / n;
    out->r_pattern = r;
    out->e_con_offset = n * dm * dm;
    out->e_con_contrast = n * (sc - sD) * (sc - sD);
    out->e_con_shape = 2 * n * sc * sD * (1 - r);
  }
  return e;
}

/* The best constant image's E_Con: the constant mean D (least squares). */
static double const_error(const nl_cheng_pattern *pat)
{
  double m = 0, e = 0;
  for (size_t i = 0; i < pat->n; i++) m += pat->d[i];
  m /= (double)pat->n;
  for (size_t i = 0; i < pat->n; i++) e += (pat->d[i] - m) * (pat->d[i] - m);
  return e;
}

#define ROUGH_N 128

/* The seam ratio of a w x h raster: the mean |difference| across each
 * boundary between two adjacent columns (over the rows), and between two
 * adjacent rows, each divided by the mean over all boundaries of its
 * direction; the largest of these. A noise image without seams has no
 * preferred boundary, but the largest of 254 noisy means is about 1.4-1.5 for
 * unoptimised tables at 128^2; a seam along x = 0.5 or at the border shows
 * as a ratio near 2 (nl_cheng.h READINGS: where the seams come from). */
static double seam_ratio(const double *v, int w, int h)
{
  double *col = nl_xcalloc((size_t)(w > h ? w : h), sizeof *col), best = 0;
  for (int dir = 0; dir < 2; dir++) {
    int nb = dir ? h - 1 : w - 1, along = dir ? w : h;
    double all = 0;
    for (int b = 0; b < nb; b++) {
      double s = 0;
      for (int a = 0; a < along; a++) {
        double d = dir ? v[(b + 1) * w + a] - v[b * w + a] : v[a * w + b + 1] - v[a * w + b];
        s += fabs(d);
      }
      col[b] = s / along;
      all += col[b];
    }
    all /= nb;
    for (int b = 0; b < nb && all > 0; b++)
      if (col[b] / all > best) best = col[b] / all;
  }
  free(col);
  return best;
}

/* rms of the finite-difference gradient of the control value, per unit
 * length: a number for "smoother" (Fig 4.7); *contrast = the value's sd on
 * the same raster, *seam its seam ratio. */
static double roughness(const nl_noise_grad2 *g, const nl_cheng_config *c, double *contrast,
                        double *seam)
{
  double *v = nl_xmalloc(ROUGH_N * ROUGH_N * sizeof *v), s = 0, m = 0, q = 0;
  nl_cheng_value_grid(g, c, ROUGH_N, ROUGH_N, v);
  for (int i = 0; i < ROUGH_N * ROUGH_N; i++) m += v[i];
  m /= ROUGH_N * ROUGH_N;
  for (int i = 0; i < ROUGH_N * ROUGH_N; i++) q += (v[i] - m) * (v[i] - m);
  *contrast = sqrt(q / (ROUGH_N * ROUGH_N - 1.0));
  *seam = seam_ratio(v, ROUGH_N, ROUGH_N);
  for (int y = 0; y + 1 < ROUGH_N; y++)
    for (int x = 0; x + 1 < ROUGH_N; x++) {
      double dx = v[y * ROUGH_N + x + 1] - v[y * ROUGH_N + x], dy = v[(y + 1) * ROUGH_N + x] - v[y * ROUGH_N + x];
      s += dx * dx + dy * dy;
    }
  free(v);
  return sqrt(s / ((ROUGH_N - 1.0) * (ROUGH_N - 1.0))) * ROUGH_N;
}

nl_status nl_cheng_evaluate(const nl_noise_grad2 *g, const nl_cheng_config *c,
                            const nl_cheng_pattern *pat, nl_cheng_eval *out, nl_error *err)
{
  nl_status s = nl_cheng_config_check(c, err);
  if (s) return s;
  nl_stats_ks_result ks;
  nl_stats_kuiper_result ku;
  nl_stats_chisq_result ch;
  if ((s = nl_stats_ks_test_uniform(g->angle, g->m, 0.0, NL_TWO_PI, &ks, err))) return s;
  if ((s = nl_stats_kuiper_test_uniform(g->angle, g->m, 0.0, NL_TWO_PI, &ku, err))) return s;
  if ((s = nl_stats_chisq_test_uniform(g->angle, g->m, c->chisq_bins, 0.0, NL_TWO_PI, &ch, err))) return s;
  out->e_ks = ks.d; out->p_ks = ks.p;
  out->kuiper_v = ku.v; out->p_kuiper = ku.p;
  out->chi2 = ch.chi2; out->p_chi2 = ch.p;
  out->e_con = control_error(g, c, pat, out);
  out->rms_con = sqrt(out->e_con / (double)pat->n);
  out->roughness = roughness(g, c, &out->contrast, &out->seam_ratio);
  out->e_con_const = const_error(pat);
  out->e_con_random = NAN;
  out->moves = 0;
  out->cpu_seconds = 0;
  double stat = nl_cheng__stat_full(c->stat, c->chisq_bins, g->angle, g->m);
  out->e = nl_cheng_objective(c, stat, out->e_con);
  memcpy(out->log_gain, c->log_gain, sizeof out->log_gain);
  return NL_OK;
}

void nl_cheng_value_grid(const nl_noise_grad2 *g, const nl_cheng_config *c, int w, int h, double *out)
{
  nl_noise_octaves o = nl_cheng_octaves(c);   /* with the config's gains (X6) */
  double s = amp_scale(&o), nv[NL_CHENG_MAX_OCTAVES];
  double *rows = nl_xmalloc((size_t)o.n * (size_t)w * sizeof *rows);
  for (int y = 0; y < h; y++) {
    for (int l = 0; l < o.n; l++)
      nl_noise_grad2_row(g, o.freq[l] * (c->origin + 0.5 / w), o.freq[l] / w,
                         o.freq[l] * (c->origin + (y + 0.5) / h), (size_t)w, rows + (size_t)l * w);
    for (int x = 0; x < w; x++) {
      for (int l = 0; l < o.n; l++) nv[l] = rows[(size_t)l * w + x];
      out[(size_t)y * w + x] = nl_cheng__control_value(c->con, nv, o.amp, o.n, s, c->literal);
    }
  }
  free(rows);
}

nl_status nl_cheng_run(const nl_cheng_config *c, const nl_cheng_pattern *pat, unsigned long seed,
                       nl_cheng_eval *ev, nl_cheng_level_stats *stats, nl_noise_grad2 **table_out,
                       nl_error *err)
{
  nl_noise_grad2 *g = nl_noise_grad2_alloc(c->m);
  nl_noise_grad2_seed(g, seed);
  double e_random = control_error(g, c, pat, NULL);   /* baseline: the random start, unoptimised */
  double t0 = nl_time_thread_cpu();
  nl_cheng_problem *p = nl_cheng_problem_alloc(c, pat, g, err);
  if (!p) { nl_noise_grad2_free(g); return NL_EINVAL; }
  /* The table and the annealer take streams of their own roles from the one
   * seed (noise.grad2, cheng.anneal), so they are independent. */
  nl_cheng_level_stats own[NL_CHENG_MAX_OCTAVES];
  if (!stats) stats = own;
  nl_cheng_optimise(p, seed, stats);
  double cpu = nl_time_thread_cpu() - t0;
  long moves = 0;
  for (int l = 0; l < c->octaves; l++) moves += stats[l].moves;
  nl_cheng_config ce = *c;
  nl_cheng_log_gains(p, ce.log_gain);   /* evaluated with the optimised amplitudes (X6); c's when fixed */
  nl_cheng_problem_free(p);
  nl_status s = ev ? nl_cheng_evaluate(g, &ce, pat, ev, err) : NL_OK;
  if (ev && !s) { ev->e_con_random = e_random; ev->moves = moves; ev->cpu_seconds = cpu; }
  if (table_out && !s) *table_out = g;
  else nl_noise_grad2_free(g);
  return s;
}
