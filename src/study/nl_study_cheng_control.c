/* Does an optimised table follow its pattern better than chance, better
 * than a flat image, and where do its seams come from: the tests behind the
 * "texture follows the pattern" verdicts of C1 and C7 (nl_study_cheng.h,
 * section "controllability tests and seams"). */
#include "study/nl_study_cheng.h"
#include "base/nl_parallel.h"
#include "stats/nl_stats.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

double nl_study_cheng_pattern_r(const nl_noise_grad2 *g, const nl_cheng_config *c,
                                const nl_cheng_pattern *pat)
{
  /* The pattern's points are its cells' centres, (col + 1/2, row + 1/2) /
   * grid, which are the centres of a grid x grid raster: one
   * nl_cheng_value_grid gives c at every point. */
  int n = pat->grid;
  double *v = nl_xmalloc((size_t)n * (size_t)n * sizeof *v);
  nl_cheng_value_grid(g, c, n, n, v);
  double sv = 0, sd = 0, svv = 0, sdd = 0, svd = 0, m = (double)pat->n;
  for (size_t i = 0; i < pat->n; i++) {
    double a = v[pat->cell[i]], d = pat->d[i];
    sv += a;
    sd += d;
    svv += a * a;
    sdd += d * d;
    svd += a * d;
  }
  free(v);
  double cov = svd - sv * sd / m, vv = svv - sv * sv / m, dd = sdd - sd * sd / m;
  return vv > 0 && dd > 0 ? cov / sqrt(vv * dd) : 0;   /* as nl_cheng_evaluate's r_pattern */
}

typedef struct {
  const nl_cheng_config *c;
  const nl_cheng_pattern *pat;
  unsigned long seed;
  double *out;
} random_r_job;

/* Item j: table j from its own stream, so the values do not depend on the
 * thread count. */
static void random_r_item(void *ctx, size_t j, int thread)
{
  (void)thread;
  random_r_job *job = ctx;
  nl_noise_grad2 *g = nl_noise_grad2_alloc(job->c->m);
  nl_noise_grad2_seed(g, nl_seed_stream(job->seed, "cheng.random_table", j));
  job->out[j] = nl_study_cheng_pattern_r(g, job->c, job->pat);
  nl_noise_grad2_free(g);
}

void nl_study_cheng_random_r(const nl_cheng_config *c, const nl_cheng_pattern *pat,
                             unsigned long seed, int n, int threads, double *out)
{
  random_r_job job = { c, pat, seed, out };
  nl_parallel_for((size_t)n, threads, random_r_item, &job);
}

double nl_study_mc_p_greater(const double *null, size_t n, double obs)
{
  size_t at_least = 0;
  for (size_t j = 0; j < n; j++) at_least += null[j] >= obs;
  return (1.0 + (double)at_least) / (1.0 + (double)n);
}

double nl_study_t_below_p(const double *x, size_t k, double mu)
{
  double m = nl_stats_mean(x, k, NL_STATS_RUNNING);
  double sd = k > 1 ? nl_stats_sd(x, k, NL_STATS_RUNNING) : 0;
  if (!(sd > 0)) return m < mu ? 0.0 : 1.0;   /* no spread: the sign decides */
  double t = (m - mu) / (sd / sqrt((double)k));
  return gsl_cdf_tdist_P(t, (double)k - 1);
}

static const char *const control_cols[] = {
  "seeds", "r_pattern", "r_random_mean", "r_random_sd", "n_random", "p_random", "E_con",
  "E_con_const", "con_vs_const", "p_flat", "con_offset_frac", "con_contrast_frac",
  "con_shape_frac", "mean_D", "offset_abs",
};
#define NCTL (sizeof control_cols / sizeof *control_cols)

nl_table *nl_study_cheng_control_alloc(int nlabels, const char *const *labels)
{
  const char *names[32];
  for (int i = 0; i < nlabels; i++) names[i] = labels[i];
  for (size_t i = 0; i < NCTL; i++) names[nlabels + (int)i] = control_cols[i];
  return nl_table_alloc((size_t)nlabels + NCTL, names);
}

void nl_study_cheng_control_add(const nl_study_cheng *s, nl_table *t, int nlabels,
                                const char *const *labels, const nl_cheng_config *c,
                                const nl_cheng_pattern *pat, const nl_cheng_eval *evs,
                                int n_random, unsigned long seed, double *r_random)
{
  int k = nl_harness_seeds(s->r);
  double *x = nl_xmalloc((size_t)k * sizeof *x), row[NCTL];
  double *null = r_random ? r_random : nl_xmalloc((size_t)n_random * sizeof *null);
  nl_study_cheng_random_r(c, pat, seed, n_random, nl_harness_threads(s->r), null);
  int q = 0;
  row[q++] = k;
  for (int i = 0; i < k; i++) x[i] = evs[i].r_pattern;
  double r = nl_stats_mean(x, (size_t)k, NL_STATS_RUNNING);
  row[q++] = r;
  row[q++] = nl_stats_mean(null, (size_t)n_random, NL_STATS_RUNNING);
  row[q++] = nl_stats_sd(null, (size_t)n_random, NL_STATS_RUNNING);
  row[q++] = n_random;
  row[q++] = nl_study_mc_p_greater(null, (size_t)n_random, r);
  for (int i = 0; i < k; i++) x[i] = evs[i].e_con;
  double e = nl_stats_mean(x, (size_t)k, NL_STATS_RUNNING), e0 = evs[0].e_con_const;
  row[q++] = e;
  row[q++] = e0;
  row[q++] = e / e0;
  row[q++] = nl_study_t_below_p(x, (size_t)k, e0);
  /* E_Con's parts as fractions of E_Con, over the seeds' sums: the same
   * split of the mean E_Con the row reports */
  double off = 0, con = 0, shp = 0, all = 0;
  for (int i = 0; i < k; i++) {
    off += evs[i].e_con_offset;
    con += evs[i].e_con_contrast;
    shp += evs[i].e_con_shape;
    all += evs[i].e_con;
  }
  row[q++] = all > 0 ? off / all : 0;
  row[q++] = all > 0 ? con / all : 0;
  row[q++] = all > 0 ? shp / all : 0;
  /* the offset's size: the pattern's mean D and |mean c - mean D| (from
   * E_Con's offset part, n (mean c - mean D)^2), mean over the seeds */
  double md = 0, oa = 0;
  for (size_t i = 0; i < pat->n; i++) md += pat->d[i] / (double)pat->n;
  for (int i = 0; i < k; i++) oa += sqrt(evs[i].e_con_offset / (double)pat->n) / k;
  row[q++] = md;
  row[q++] = oa;
  size_t rr = nl_table_append_empty(t);
  for (size_t i = 0; i < NCTL; i++) nl_table_set(t, rr, control_cols[i], row[i]);
  for (int i = 0; i < nlabels; i++) nl_table_set_text(t, rr, t->names[i], labels[i]);
  if (!r_random) free(null);
  free(x);
}

/* ---- negative controls ---------------------------------------------------- */

nl_cheng_pattern *nl_study_cheng_pattern_shuffled(const nl_cheng_pattern *p, unsigned long seed)
{
  nl_cheng_pattern *q = nl_xcalloc(1, sizeof *q);
  q->grid = p->grid;
  q->n = p->n;
  q->x = nl_xmalloc(p->n * sizeof *q->x);
  q->y = nl_xmalloc(p->n * sizeof *q->y);
  q->d = nl_xmalloc(p->n * sizeof *q->d);
  q->cell = nl_xmalloc(p->n * sizeof *q->cell);
  memcpy(q->x, p->x, p->n * sizeof *q->x);
  memcpy(q->y, p->y, p->n * sizeof *q->y);
  memcpy(q->d, p->d, p->n * sizeof *q->d);
  memcpy(q->cell, p->cell, p->n * sizeof *q->cell);
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, seed);
  gsl_ran_shuffle(rng, q->d, q->n, sizeof *q->d);
  gsl_rng_free(rng);
  return q;
}

nl_cheng_eval *nl_study_cheng_evaluate_tables(const nl_study_cheng *s, const nl_cheng_config *c,
                                              const nl_cheng_pattern *pat,
                                              nl_noise_grad2 *const *tables, int n)
{
  nl_cheng_eval *evs = nl_xmalloc((size_t)n * sizeof *evs);
  for (int i = 0; i < n; i++) {
    nl_error err;
    if (nl_cheng_evaluate(tables[i], c, pat, &evs[i], &err)) nl_harness_die(s->r, 1, "%s", err.msg);
    evs[i].e_con_random = evs[i].e_con;
  }
  return evs;
}

nl_noise_grad2 **nl_study_cheng_start_tables(const nl_study_cheng *s, size_t m)
{
  int k = nl_harness_seeds(s->r);
  unsigned long seed0 =
      s->role ? nl_seed_stream(nl_harness_seed(s->r), s->role, 0) : nl_harness_seed(s->r);
  nl_noise_grad2 **t = nl_xmalloc((size_t)k * sizeof *t);
  for (int i = 0; i < k; i++) {
    t[i] = nl_noise_grad2_alloc(m);
    nl_noise_grad2_seed(t[i], nl_seed_replicate(seed0, i)); /* as nl_cheng_run */
  }
  return t;
}

size_t nl_study_cheng_baselines_add(const nl_study_cheng *s, nl_table *t, int nlabels,
                                    const char *const *labels, const nl_cheng_config *c,
                                    const nl_cheng_pattern *pat, nl_noise_grad2 *const *tables,
                                    int n_random, unsigned long seed)
{
  int k = nl_harness_seeds(s->r);
  const char *lab[32];
  for (int i = 0; i < nlabels - 1; i++) lab[i] = labels[i];
  size_t first = t->nrows;
  nl_cheng_pattern *sh = nl_study_cheng_pattern_shuffled(pat, nl_seed_stream(seed, "cheng.shuffle", 0));
  nl_cheng_eval *evs = nl_study_cheng_evaluate_tables(s, c, sh, tables, k);
  lab[nlabels - 1] = "shuffled pattern";
  nl_study_cheng_control_add(s, t, nlabels, lab, c, sh, evs, n_random,
                             nl_seed_stream(seed, "cheng.shuffle", 1), NULL);
  free(evs);
  nl_cheng_pattern_free(sh);
  nl_noise_grad2 **st = nl_study_cheng_start_tables(s, c->m);
  evs = nl_study_cheng_evaluate_tables(s, c, pat, st, k);
  lab[nlabels - 1] = "start tables";
  nl_study_cheng_control_add(s, t, nlabels, lab, c, pat, evs, n_random,
                             nl_seed_stream(seed, "cheng.shuffle", 2), NULL);
  free(evs);
  for (int i = 0; i < k; i++) nl_noise_grad2_free(st[i]);
  free(st);
  return first;
}

double nl_study_spearman(const double *x, const double *y, size_t n)
{
  double *work = nl_xmalloc(2 * n * sizeof *work);
  double rho = gsl_stats_spearman(x, 1, y, 1, n, work); /* ties: average ranks */
  free(work);
  return rho;
}

double nl_study_spearman_perm_p(const double *x, const double *y, size_t n, int nperm,
                                unsigned long seed, double *rho)
{
  *rho = nl_study_spearman(x, y, n);
  double *yp = nl_xmalloc(n * sizeof *yp);
  memcpy(yp, y, n * sizeof *yp);
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, seed);
  int at_least = 0;
  for (int b = 0; b < nperm; b++) {
    gsl_ran_shuffle(rng, yp, n, sizeof *yp);
    /* a hair of tolerance: a permutation that only swaps tied values gives
     * the same rho up to rounding */
    at_least += nl_study_spearman(x, yp, n) >= *rho - 1e-12;
  }
  gsl_rng_free(rng);
  free(yp);
  return (1.0 + at_least) / (1.0 + nperm);
}

/* ---- seams ---------------------------------------------------------------- */

#define SEAM_N 128

/* Mean |step| across column boundary b (between columns b and b + 1) over
 * rows [r0, r1) of an n x n raster, over the mean of all column boundaries
 * over the same rows; dir 1: rows and columns swapped. */
static double boundary_ratio(const double *v, int n, int dir, int b, int r0, int r1)
{
  double at = 0, all = 0;
  for (int c = 0; c + 1 < n; c++) {
    double s = 0;
    for (int a = r0; a < r1; a++) {
      double d = dir ? v[(size_t)(c + 1) * n + a] - v[(size_t)c * n + a]
                     : v[(size_t)a * n + c + 1] - v[(size_t)a * n + c];
      s += fabs(d);
    }
    all += s;
    if (c == b) at = s;
  }
  return all > 0 ? at / (all / (n - 1)) : 0;
}

/* The half-line x = 1/2 over y < 1/2 and y = 1/2 over x < 1/2 (the edges of
 * the quarter [0, 1/2]^2), averaged; other: the same lines over the other
 * halves. */
static void midlines(const double *v, int n, double *quarter, double *other)
{
  int b = n / 2 - 1;
  *quarter = (boundary_ratio(v, n, 0, b, 0, n / 2) + boundary_ratio(v, n, 1, b, 0, n / 2)) / 2;
  *other = (boundary_ratio(v, n, 0, b, n / 2, n) + boundary_ratio(v, n, 1, b, n / 2, n)) / 2;
}

void nl_study_cheng_seams_measure(const nl_noise_grad2 *g, const nl_cheng_config *c,
                                  nl_study_cheng_seams *out)
{
  const int n = SEAM_N;
  double *v = nl_xmalloc((size_t)n * n * sizeof *v);
  nl_cheng_value_grid(g, c, n, n, v);
  midlines(v, n, &out->quarter, &out->other);
  out->border = (boundary_ratio(v, n, 0, 0, 0, n) + boundary_ratio(v, n, 0, n - 2, 0, n) +
                 boundary_ratio(v, n, 1, 0, 0, n) + boundary_ratio(v, n, 1, n - 2, 0, n)) /
                4;
  nl_noise_octaves o = nl_cheng_octaves(c);
  for (int l = 0; l < NL_STUDY_CHENG_SEAM_OCTAVES; l++) {
    out->octave_quarter[l] = NAN;
    if (l >= o.n) continue;
    double f = o.freq[l], other;
    for (int y = 0; y < n; y++)
      nl_noise_grad2_row(g, f * (c->origin + 0.5 / n), f / n, f * (c->origin + (y + 0.5) / n),
                         (size_t)n, v + (size_t)y * n);
    midlines(v, n, &out->octave_quarter[l], &other);
  }
  free(v);
  /* The outward component of octave 1's unit gradients on the lattice lines
   * of the domain's border, x = o, x = o + 1, y = o, y = o + 1 (f1 o integer:
   * lattice lines f1 o and f1 (o + 1)) */
  long L0 = (long)floor(o.freq[0] * c->origin), L = (long)ceil(o.freq[0] * (c->origin + 1));
  double s = 0;
  for (long j = L0; j <= L; j++) {
    s -= g->gx[nl_noise_grad2_index(g, L0, j)];
    s += g->gx[nl_noise_grad2_index(g, L, j)];
    s -= g->gy[nl_noise_grad2_index(g, j, L0)];
    s += g->gy[nl_noise_grad2_index(g, j, L)];
  }
  out->outward = s / (4.0 * (double)(L - L0 + 1));
}

static const char *const seam_cols[] = {
  "origin",       "tables",       "seam_ratio",   "seam_quarter", "seam_quarter_sd", "seam_other",
  "seam_border",  "seam_octave1", "seam_octave2", "seam_octave3",    "seam_octave4",
  "border_outward", "border_outward_sd",
};
#define NSEAM (sizeof seam_cols / sizeof *seam_cols)

nl_table *nl_study_cheng_seams_alloc(int nlabels, const char *const *labels)
{
  const char *names[32];
  for (int i = 0; i < nlabels; i++) names[i] = labels[i];
  for (size_t i = 0; i < NSEAM; i++) names[nlabels + (int)i] = seam_cols[i];
  return nl_table_alloc((size_t)nlabels + NSEAM, names);
}

void nl_study_cheng_seams_add(nl_table *t, int nlabels, const char *const *labels,
                              const nl_noise_grad2 *const *tables, int n,
                              const nl_cheng_config *c, const nl_cheng_pattern *pat)
{
  double *q = nl_xmalloc((size_t)n * sizeof *q), *w = nl_xmalloc((size_t)n * sizeof *w);
  double other = 0, border = 0, oct[NL_STUDY_CHENG_SEAM_OCTAVES] = { 0 }, ratio = 0;
  for (int i = 0; i < n; i++) {
    nl_cheng_eval ev;
    nl_error err;
    /* a config that failed its check never reaches here: NAN marks the impossible */
    ratio += nl_cheng_evaluate(tables[i], c, pat, &ev, &err) ? NAN : ev.seam_ratio / n;
    nl_study_cheng_seams s;
    nl_study_cheng_seams_measure(tables[i], c, &s);
    q[i] = s.quarter;
    w[i] = s.outward;
    other += s.other / n;
    border += s.border / n;
    for (int l = 0; l < NL_STUDY_CHENG_SEAM_OCTAVES; l++) oct[l] += s.octave_quarter[l] / n;
  }
  double row[NSEAM] = { c->origin,
                        n,
                        ratio,
                        nl_stats_mean(q, (size_t)n, NL_STATS_RUNNING),
                        n > 1 ? nl_stats_sd(q, (size_t)n, NL_STATS_RUNNING) : 0,
                        other,
                        border,
                        oct[0],
                        oct[1],
                        oct[2],
                        oct[3],
                        nl_stats_mean(w, (size_t)n, NL_STATS_RUNNING),
                        n > 1 ? nl_stats_sd(w, (size_t)n, NL_STATS_RUNNING) : 0 };
  size_t r = nl_table_append_empty(t);
  for (size_t i = 0; i < NSEAM; i++) nl_table_set(t, r, seam_cols[i], row[i]);
  for (int i = 0; i < nlabels; i++) nl_table_set_text(t, r, t->names[i], labels[i]);
  free(q);
  free(w);
}

/* lo..hi and count of column col over the rows of t from `from` at origin o */
static int seam_range(const nl_table *t, const char *from, double o, const char *col, double *lo,
                      double *hi)
{
  int n = 0;
  *lo = INFINITY;
  *hi = -INFINITY;
  for (size_t q = 0; q < t->nrows; q++)
    if (!strcmp(nl_table_text(t, q, "tables_from"), from) && nl_table_value(t, q, "origin") == o) {
      *lo = fmin(*lo, nl_table_value(t, q, col));
      *hi = fmax(*hi, nl_table_value(t, q, col));
      n++;
    }
  return n;
}

void nl_study_cheng_seams_text(nl_harness *r, const nl_table *t, const char *what)
{
  char cap[256];
  snprintf(cap, sizeof cap,
           "Seams of %s on the domain [1, 2]^2 (origin 1, the headline) and [0, 1]^2 (origin 0): "
           "a boundary's mean |step| over its strip's mean, 1 = no seam",
           what);
  nl_harness_report_table(r, t, cap, 3);
  const char *cols[3] = { "seam_quarter", "seam_border", "seam_ratio" };
  double lo[2][3], hi[2][3];
  int n1 = 0, n0 = 0;
  for (int c = 0; c < 3; c++) {
    n1 = seam_range(t, "optimised", 1, cols[c], &lo[1][c], &hi[1][c]);
    n0 = seam_range(t, "optimised", 0, cols[c], &lo[0][c], &hi[0][c]);
  }
  char start[256] = "";
  double slo, shi, blo, bhi;
  if (seam_range(t, "start table", 1, "seam_quarter", &slo, &shi) > 0) {
    seam_range(t, "start table", 1, "seam_border", &blo, &bhi);
    snprintf(start, sizeof start,
             " Unoptimised start tables on [1, 2]^2 give %.2f..%.2f across the quarter's edges and "
             "%.2f..%.2f at the borders.",
             slo, shi, blo, bhi);
  }
  if (n1 == 0 || n0 == 0) return;
  nl_harness_text(
      r,
      "**Seams and the domain.** Across the edges of the quarter (x = 1/2 over y < 1/2 and y = "
      "1/2 over x < 1/2 of the image, where on [0, 1]^2 octave l repeats octave l-1's border "
      "lines) the optimised tables step %.2f..%.2f x their strip's mean on [1, 2]^2 against "
      "%.2f..%.2f on [0, 1]^2; at the image borders %.2f..%.2f against %.2f..%.2f; the largest "
      "boundary anywhere (seam_ratio) %.2f..%.2f against %.2f..%.2f (%d and %d rows).%s On [1, "
      "2]^2 no octave's lattice lies inside another's (nl_cheng.h READINGS), so no octave repeats "
      "another's border; a step left at the borders comes with the control term (C7 measures it "
      "with the term off).\n",
      lo[1][0], hi[1][0], lo[0][0], hi[0][0], lo[1][1], hi[1][1], lo[0][1], hi[0][1], lo[1][2],
      hi[1][2], lo[0][2], hi[0][2], n1, n0, start);
}

/* ---- prose ---------------------------------------------------------------- */

/* Row q's labels (the first nlabels columns) joined by "/". */
static void row_label(const nl_table *t, size_t q, int nlabels, char *lab, size_t len)
{
  lab[0] = 0;
  for (int i = 0; i < nlabels; i++) {
    char buf[48];
    size_t used = strlen(lab);
    snprintf(lab + used, len - used, "%s%s", i ? "/" : "",
             nl_table_cell_text(t, q, (size_t)i, buf));
  }
}

int nl_study_cheng_flat_text(nl_harness *r, const nl_table *ctl, int nlabels)
{
  size_t cap = 256 + 256 * ctl->nrows, len = 0;
  char *list = nl_xmalloc(cap), lab[160];
  int worse = 0;
  list[0] = 0;
  for (size_t q = 0; q < ctl->nrows; q++) {
    double ratio = nl_table_value(ctl, q, "con_vs_const");
    double off = ratio * nl_table_value(ctl, q, "con_offset_frac");
    double con = ratio * nl_table_value(ctl, q, "con_contrast_frac");
    double shp = ratio * nl_table_value(ctl, q, "con_shape_frac");
    row_label(ctl, q, nlabels, lab, sizeof lab);
    len += (size_t)snprintf(list + len, cap - len,
                            "%s%s %.3f = %.3f + %.3f + %.3f (p_flat %.2g%s)", q ? "; " : "", lab,
                            ratio, off, con, shp, nl_table_value(ctl, q, "p_flat"),
                            ratio >= 1 && ratio - off < 1 ? ", below 1 without the offset" : "");
    worse += ratio >= 1;
  }
  nl_harness_text(r,
                  "E_Con against the best constant image (a flat image at the pattern's mean), "
                  "in units of the flat image's E_Con and split into mean offset + contrast (sd "
                  "of c against sd of D) + shape (1 - r), per row: %s. Above 1 is worse than "
                  "flat (%d of %zu rows). The contrast part is (1 - sd c / sd D)^2 whatever the "
                  "shape: gradient noise's low contrast alone costs that much, so beating the "
                  "flat image takes a high r and a small mean offset together.\n",
                  list, worse, ctl->nrows);
  free(list);
  return worse;
}
