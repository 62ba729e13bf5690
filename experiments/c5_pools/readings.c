/* C5's readings of Tables 4.2-4.4: sample size x clustering distance x pool
 * rule x cutoff rule, over pool replicates (rules in readings.h). */
#include "readings.h"
#include "stats/nl_cluster.h"
#include "base/nl_parallel.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAXREP 16
#define NRD    16 /* cutoff rule x n x distance x pool rule, table order */

/* clang-format off */
static const char *const rd_cols[] = {
  "texture", "reading", "n_rule", "distance", "pool_rule", "cutoff_rule", "k0_is_input", "reps",
  "input_samples", "cluster_samples", "dim", "stride", "cutoff", "cutoff_sd", "K0", "K0_sd",
  "K_final", "K_final_sd", "AIC", "AIC_sd", "AIC_per_nd", "n_ok", "n_kmax", "status", "matches",
  "headline", "best_match", "seconds", "paper_K_initial", "paper_K_final", "paper_cutoff",
  "paper_AIC"
};
static const char *const ess_cols[] = {
  "texture", "rep", "pool_rule", "stride", "rows", "runs", "tau_rows", "tau_sweeps", "ess_tau",
  "tau_capped", "icc", "ess_kish", "ess_kish_per_run", "dec_sweeps"
};
/* clang-format on */
static const char *const n_names[2] = { "sub1000", "all" };
static const char *const d_names[2] = { "cossin", "angles" };
static const char *const p_names[2] = { "successive", "spaced" };
static const char *const c_names[2] = { "thesis", "matched_K0" };

/* clang-format off */
static const char *const rep_cols[] = {
  "texture", "reading", "k0_is_input", "K", "reps_drawn", "E_ks", "E_ks_sd", "E_con", "E_con_sd",
  "below_ks", "below_con", "E_ks_original", "E_con_original"
};
/* clang-format on */

typedef struct {
  double cut[MAXREP], k0[MAXREP], k[MAXREP], aic[MAXREP], apn[MAXREP], dim[MAXREP], sec;
  int n, ok, kmax, nin, ncl;
  const char *status;
} acc;

void c5_readings_params(nl_harness *r, c5_readings_options *ro)
{
  int q = nl_harness_quick(r);
  ro->reps = (int)nl_harness_param_int(r, "reps", q ? 2 : 3, 1, MAXREP,
                                       "pool replicates: each re-runs the original optimisation, "
                                       "the pool and the fits from its own seed (quick 2)");
  ro->stride = (int)nl_harness_param_int(r, "stride", 2, 1, 1000,
                                         "sweeps between the states of the spaced pool rule (the "
                                         "pool collects N x stride tail states per run)");
  ro->draws = (int)nl_harness_param_int(r, "draws", q ? 4 : 24, 0, 4096,
                                        "C6's question under each reading: reproductions drawn "
                                        "(swap 1) from replicate 0's models (quick 4)");
  ro->all_reps = (int)nl_harness_param_int(
      r, "all_reps", 1, 0, MAXREP,
      "replicates whose mixtures are also fitted on all pool rows (n = all; the costly fits)");
}

void c5_readings_alloc(c5_readings *R)
{
  R->readings = nl_table_alloc(sizeof rd_cols / sizeof *rd_cols, rd_cols);
  R->ess = nl_table_alloc(sizeof ess_cols / sizeof *ess_cols, ess_cols);
  R->repro = nl_table_alloc(sizeof rep_cols / sizeof *rep_cols, rep_cols);
  const char *pc[] = { "texture", "reading", "K", "AIC", "BIC", "headline", "best_match" };
  R->paths = nl_table_alloc(7, pc);
  c5_floor_alloc(&R->floor);
}

void c5_readings_free(c5_readings *R)
{
  nl_table_free(R->readings);
  nl_table_free(R->ess);
  nl_table_free(R->repro);
  nl_table_free(R->paths);
  c5_floor_free(&R->floor);
}

static int rd_index(int cr, int n, int d, int p) { return ((cr * 2 + n) * 2 + d) * 2 + p; }

/* What the tables need of one reading's fit (the model itself is freed in
 * the item that fitted it). */
typedef struct {
  double cutoff, acut, k0, k, aic, sec; /* acut: the matched fit's cutoff on raw angles */
  size_t n_in, n_cl, d;
  nl_cheng_model_status status;
  int capped;        /* the path ended at its cap K0 + k_extra with AIC still falling, whatever the
                        status (a one-cluster start reports one_cluster first) */
  nl_gmm_step *path; /* replicate 0: the AIC path (the figure) */
  size_t npath;
  int drawn;      /* replicate 0: C6's question answered (rep) */
  double rep[10]; /* K, draws, E_ks, E_ks_sd, E_con, E_con_sd, below_ks, below_con, E_ks_orig,
                     E_con_orig */
} fit_out;

static void add(acc *a, const fit_out *f, double cutoff)
{
  int i = a->n++;
  a->cut[i] = cutoff;
  a->k0[i] = f->k0;
  a->k[i] = f->k;
  a->aic[i] = f->aic;
  a->sec += f->sec;
  a->nin = (int)f->n_in;
  a->ncl = (int)f->n_cl;
  a->dim[i] = (double)f->d;
  a->apn[i] = a->aic[i] / ((double)f->n_in * (double)f->d); /* the dimension varies by replicate */
  a->kmax += f->capped;
  if (f->status == NL_CHENG_MODEL_OK)
    a->ok++;
  else if (!a->status)
    a->status = nl_cheng_model_status_name(f->status);
}

/* The cutoff that gives k clusters of the model's clustered rows on raw angles. */
static nl_status angle_cutoff_for_k(const nl_cheng_pool *pool, const nl_cheng_model *m, size_t k,
                                    double *c, nl_error *err)
{
  size_t n = m->n_cl, nl = pool->nlow;
  double *x = nl_xmalloc(n * nl * sizeof *x);      /* the rows' raw angles */
  double *Z = nl_xmalloc((n - 1) * 4 * sizeof *Z); /* the linkage */
  for (size_t i = 0; i < n; i++) memcpy(x + i * nl, pool->theta + m->cl[i] * nl, nl * sizeof *x);
  nl_status st = nl_cluster_linkage(x, n, nl, NL_LINKAGE_COMPLETE, Z, err);
  if (!st) *c = nl_cheng_cutoff_for_k(Z, n, k);
  free(x);
  free(Z);
  return st;
}

/* C6's question (are reproductions close to and often below the original?)
 * under one reading's model: `draws` reproductions with every high entry
 * swapped, E_KS and E_Con over all entries, as C6 (stream "c5.reproduce"). */
typedef struct {
  nl_harness *r;
  const nl_study_cheng_repro *rp;
  const nl_cheng_config *c;
  const nl_cheng_pattern *pat;
  int draws;
} repro_ctx;

static nl_status repro_draws(const repro_ctx *x, const nl_cheng_model *m, fit_out *f, nl_error *err)
{
  f->npath = m->npath; /* replicate 0's AIC path of this reading (the figure) */
  f->path = nl_xmalloc((m->npath ? m->npath : 1) * sizeof *f->path);
  memcpy(f->path, m->path, m->npath * sizeof *f->path);
  if (!m->gmm || x->draws < 1) return NL_OK;
  double ks[4096], con[4096], bk = 0, bc = 0;
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(nl_harness_seed(x->r), "c5.reproduce", 0));
  nl_noise_grad2 *out = nl_noise_grad2_alloc(x->rp->opt->m);
  nl_status st = NL_OK;
  for (int i = 0; i < x->draws && !st; i++) {
    nl_cheng_eval ev;
    if ((st = nl_cheng_reproduce(x->rp->opt, m, 1.0, rng, out, err)) ||
        (st = nl_cheng_evaluate(out, x->c, x->pat, &ev, err)))
      break;
    ks[i] = ev.e_ks;
    con[i] = ev.e_con;
    bk += ev.e_ks < x->rp->ev.e_ks;
    bc += ev.e_con < x->rp->ev.e_con;
  }
  if (!st) {
    double v[10] = { (double)m->k,
                     (double)x->draws,
                     nl_stats_mean(ks, x->draws, NL_STATS_RUNNING),
                     nl_stats_sd(ks, x->draws, NL_STATS_RUNNING),
                     nl_stats_mean(con, x->draws, NL_STATS_RUNNING),
                     nl_stats_sd(con, x->draws, NL_STATS_RUNNING),
                     bk / x->draws,
                     bc / x->draws,
                     x->rp->ev.e_ks,
                     x->rp->ev.e_con };
    memcpy(f->rep, v, sizeof v);
    f->drawn = 1;
  }
  nl_noise_grad2_free(out);
  gsl_rng_free(rng);
  return st;
}

static void reading_id(char *id, size_t len, int cr, int n, int d, int p)
{
  snprintf(id, len, "%s/%s/%s/%s", n_names[n], d_names[d], p_names[p], c_names[cr]);
}

/* One replicate's fits on one pool (p) and one sample rule (n): the thesis's
 * cutoff on both distances (K0 a result), then the matched K0 (one fit for
 * both distances). The three share the mixture's rows and seed, so their AIC
 * paths share fits through the options' memo (nl_gmm.h). */
typedef struct {
  const nl_cheng_pool *pool;
  const nl_study_cheng_thesis_gmm *th;
  const nl_cheng_model_options *mo;
  unsigned long seed;
  int n;
  const repro_ctx *x; /* replicate 0 only */
  fit_out f[3];       /* d = 0, d = 1, matched */
  nl_status st;
  nl_error err;
} group;

static nl_status group_fits(group *g)
{
  nl_cheng_model_options o = *g->mo;
  o.gmm.seed = g->seed;
  o.cluster_samples = g->mo->samples; /* the clustering always on the subsample */
  o.samples = g->n ? 0 : g->mo->samples;
  for (int v = 0; v < 3; v++) {
    if (v < 2) {
      o.cluster_angles = v;
      o.cutoff = g->th->cutoff;
    } /* the thesis's cutoff: K0 a result */
    else {
      o.cluster_angles = 0;
      o.cutoff = -1;
      o.target_k = (size_t)g->th->k0;
    } /* K0 an input */
    nl_cheng_model *m;
    nl_status st = nl_cheng_model_fit(g->pool, &o, o.gmm.seed, &m, &g->err);
    if (st) return st;
    fit_out *f = &g->f[v];
    *f = (fit_out){ .cutoff = m->cutoff,
                    .acut = NAN,
                    .k0 = (double)m->k0,
                    .k = (double)m->k,
                    .aic = m->gmm ? m->gmm->aic : NAN,
                    .sec = m->seconds_cluster + m->seconds_gmm,
                    .n_in = m->n_in,
                    .n_cl = m->n_cl,
                    .d = m->d,
                    .status = m->status };
    size_t cap = m->k0 + o.k_extra < m->n_in ? m->k0 + o.k_extra : m->n_in;
    f->capped = m->gmm && m->k == cap && m->npath == cap - m->k0 + 1;
    if (v == 2 && m->n_cl > (size_t)g->th->k0)
      st = angle_cutoff_for_k(g->pool, m, (size_t)g->th->k0, &f->acut, &g->err);
    if (!st && g->x) st = repro_draws(g->x, m, f, &g->err);
    nl_cheng_model_free(m);
    if (st) return st;
  }
  return NL_OK;
}

static void group_item(void *ctx, size_t i, int t)
{
  (void)t;
  group **gs = ctx;
  gs[i]->st = group_fits(gs[i]);
}

/* The rows of one fit: its reading's accumulator, and on replicate 0 its
 * AIC path and C6's question. */
static void fit_rows(c5_readings *R, acc *a, const fit_out *f, double cutoff, const char *tex,
                     int cr, int n, int d, int p)
{
  add(a, f, cutoff);
  if (!f->path || (cr && d))
    return; /* the matched fit's path and draws: once, under the cossin id */
  char id[80];
  reading_id(id, sizeof id, cr, n, d, p);
  for (size_t i = 0; i < f->npath; i++)
    nl_table_append(R->paths, "ssddddd", tex, id, (double)f->path[i].k, f->path[i].aic,
                    f->path[i].bic, 0.0, 0.0);
  const double *v = f->rep;
  if (f->drawn)
    nl_table_append(R->repro, "ssddddddddddd", tex, id, (double)cr, v[0], v[1], v[2], v[3], v[4],
                    v[5], v[6], v[7], v[8], v[9]);
}

static void ess_row(nl_table *t, const char *tex, int k, int p, int stride,
                    const nl_cheng_pool *pool)
{
  nl_cheng_pool_ess_result e;
  nl_cheng_pool_ess(pool, &e);
  int st = p ? stride : 1;
  nl_table_append(t, "sdsddddddddddd", tex, (double)k, p_names[p], (double)st, (double)pool->n,
                  (double)pool->runs, e.tau, e.tau * st, e.ess_tau, (double)e.capped, e.icc,
                  e.ess_kish, e.ess_kish / pool->runs, e.dec * st);
}

/* Mean over the finite values; sd over them (0 for fewer than 2). */
static void mean_sd(const double *x, int n, double *m, double *sd)
{
  double v[MAXREP];
  int k = 0;
  for (int i = 0; i < n; i++)
    if (isfinite(x[i])) v[k++] = x[i];
  *m = k ? nl_stats_mean(v, k, NL_STATS_RUNNING) : 0;
  *sd = k ? nl_stats_sd(v, k, NL_STATS_RUNNING) : 0;
}

static int within(double ours, double paper, int factor)
{
  if (!(ours > 0 || ours < 0)) return 0;
  return factor ? fmax(ours / paper, paper / ours) <= C5_MATCH_FACTOR
                : fabs(ours - paper) <= C5_MATCH_REL * fabs(paper);
}

static void rows(c5_readings *R, const acc *A, const nl_study_cheng_thesis_gmm *th, int stride)
{
  nl_table *t = R->readings;
  for (int cr = 0; cr < 2; cr++)
    for (int n = 0; n < 2; n++)
      for (int d = 0; d < 2; d++)
        for (int p = 0; p < 2; p++) {
          const acc *a = &A[rd_index(cr, n, d, p)];
          if (!a->n) continue;
          double v[4][2];
          mean_sd(a->cut, a->n, &v[0][0], &v[0][1]);
          mean_sd(a->k0, a->n, &v[1][0], &v[1][1]);
          mean_sd(a->k, a->n, &v[2][0], &v[2][1]);
          mean_sd(a->aic, a->n, &v[3][0], &v[3][1]);
          char id[80];
          reading_id(id, sizeof id, cr, n, d, p);
          int match = (cr ? within(v[0][0], th->cutoff, 1) : within(v[1][0], th->k0, 1)) +
                      within(v[2][0], th->k, 1) + within(v[3][0], th->aic, 0);
          size_t q = nl_table_append_empty(t);
          nl_table_set_text(t, q, "texture", th->texture);
          nl_table_set_text(t, q, "reading", id);
          nl_table_set_text(t, q, "n_rule", n_names[n]);
          nl_table_set_text(t, q, "distance", d_names[d]);
          nl_table_set_text(t, q, "pool_rule", p_names[p]);
          nl_table_set_text(t, q, "cutoff_rule", c_names[cr]);
          nl_table_set(t, q, "k0_is_input", cr);
          nl_table_set(t, q, "reps", a->n);
          nl_table_set(t, q, "input_samples", a->nin);
          nl_table_set(t, q, "cluster_samples", a->ncl);
          double apn, apn_sd, dm, dm_sd;
          mean_sd(a->apn, a->n, &apn, &apn_sd);
          mean_sd(a->dim, a->n, &dm, &dm_sd);
          nl_table_set(t, q, "dim", dm);
          nl_table_set(t, q, "stride", p ? stride : 1);
          const char *vc[4][2] = { { "cutoff", "cutoff_sd" },
                                   { "K0", "K0_sd" },
                                   { "K_final", "K_final_sd" },
                                   { "AIC", "AIC_sd" } };
          for (int k = 0; k < 4; k++) {
            nl_table_set(t, q, vc[k][0], v[k][0]);
            nl_table_set(t, q, vc[k][1], v[k][1]);
          }
          nl_table_set(t, q, "AIC_per_nd", apn);
          nl_table_set(t, q, "n_ok", a->ok);
          nl_table_set(t, q, "n_kmax", a->kmax);
          nl_table_set_text(t, q, "status", a->status ? a->status : "ok");
          nl_table_set(t, q, "matches", match);
          nl_table_set(t, q, "headline", !strcmp(id, C5_HEADLINE));
          nl_table_set(t, q, "best_match", 0);
          nl_table_set(t, q, "seconds", a->sec);
          if (cr) /* K0 was the input: nothing to compare */
            nl_table_set_text(t, q, "paper_K_initial", "n/a");
          else
            nl_table_set(t, q, "paper_K_initial", th->k0);
          nl_table_set(t, q, "paper_K_final", th->k);
          nl_table_set(t, q, "paper_cutoff", th->cutoff);
          nl_table_set(t, q, "paper_AIC", th->aic);
        }
}

/* A fit's values in the unit store: the fields of fit_out, then its path's
 * length (-1: no path), K, AIC and BIC per step under its own key. */
#define FIT_VALS 25

static void fit_pack(const fit_out *f, double *v)
{
  double w[15] = { f->cutoff, f->acut, f->k0, f->k, f->aic, f->sec, (double)f->n_in,
                   (double)f->n_cl, (double)f->d, (double)f->status, (double)f->capped,
                   (double)f->drawn, f->path ? (double)f->npath : -1.0, 0, 0 };
  memcpy(v, w, 13 * sizeof *v);
  memcpy(v + 13, f->rep, 10 * sizeof *v);
  v[23] = v[24] = 0;
}

static void fit_unpack(nl_harness *r, long u, const char *pkey, const double *v, fit_out *f)
{
  *f = (fit_out){ .cutoff = v[0],
                  .acut = v[1],
                  .k0 = v[2],
                  .k = v[3],
                  .aic = v[4],
                  .sec = v[5],
                  .n_in = (size_t)v[6],
                  .n_cl = (size_t)v[7],
                  .d = (size_t)v[8],
                  .status = (nl_cheng_model_status)v[9],
                  .capped = (int)v[10],
                  .drawn = (int)v[11] };
  memcpy(f->rep, v + 13, 10 * sizeof *v);
  if (v[12] < 0) return;
  size_t n;
  const double *p = nl_harness_unit_get(r, u, pkey, &n);
  f->npath = n / 3;
  f->path = nl_xmalloc((f->npath ? f->npath : 1) * sizeof *f->path);
  for (size_t i = 0; i < f->npath; i++)
    f->path[i] = (nl_gmm_step){ .k = (size_t)p[3 * i], .aic = p[3 * i + 1], .bic = p[3 * i + 2] };
}

void c5_readings_unit(const nl_study_cheng *s, const nl_study_cheng_thesis_gmm *th,
                      const nl_cheng_pool_options *po, const nl_cheng_model_options *mm,
                      const c5_readings_options *ro, int nseeds, int full, int k,
                      const nl_cheng_pattern *pat, const nl_cheng_config *c)
{
  nl_harness *r = s->r;
  unsigned long seed = nl_seed_replicate(nl_harness_seed(r), k);
  nl_cheng_pool_options pl = *po;
  pl.keep = po->keep * ro->stride; /* N x stride tail states per run */
  nl_study_cheng_repro rp;
  nl_error err;
  /* the original, then the pool (its runs are the items) */
  if (nl_study_cheng_repro_original(c, pat, seed, &rp, &err) ||
      nl_study_cheng_repro_pool(&rp, c, pat, &pl, seed, &err))
    nl_harness_die(r, 1, "%s: %s", th->texture, err.msg);
  nl_cheng_pool *pools[2] = { nl_cheng_pool_thin(rp.pool, po->keep, 1),
                              nl_cheng_pool_thin(rp.pool, po->keep, ro->stride) };
  nl_table *ess = nl_table_alloc(sizeof ess_cols / sizeof *ess_cols, ess_cols);
  for (int p = 0; p < 2; p++) ess_row(ess, th->texture, k, p, ro->stride, pools[p]);
  nl_harness_unit_put_table(r, "ess", ess);
  nl_table_free(ess);
  { /* the headline's settings the thesis leaves open: floor and linkage (floor.h) */
    nl_cheng_model_options ho = *mm;
    ho.samples = ho.cluster_samples = mm->samples;
    ho.cluster_angles = 1;
    ho.cutoff = th->cutoff;
    double v[C5_FLOOR_VALS];
    c5_floor_unit(r, th->texture, &ho, pools[0], seed, po->threads, v);
    nl_harness_unit_put(r, "floor", v, C5_FLOOR_VALS);
  }
  if (k == 0) { /* the older tables: replicate 0, successive states (the default pool) */
    c5_pools T;
    c5_pools_alloc(&T);
    nl_study_cheng_repro r0 = rp;
    r0.pool = pools[0];
    c5_pool_case_with(s, &T, th, po, mm, nseeds, full, &r0);
    c5_pools_put(r, &T);
    c5_pools_free(&T);
  }
  /* Every (sample rule, pool rule) group is an item; the costly all-rows
   * groups first so the threads end together. */
  repro_ctx x = { r, &rp, c, pat, ro->draws };
  group gs[4], *order[4];
  int ng = 0;
  for (int n = 1; n >= 0; n--)
    for (int p = 0; p < 2 && (n == 0 || k < ro->all_reps); p++) {
      group *g = &gs[n * 2 + p];
      *g = (group){ .pool = pools[p],
                    .th = th,
                    .mo = mm,
                    .seed = seed,
                    .n = n,
                    .x = k == 0 ? &x : NULL };
      order[ng++] = g;
    }
  nl_parallel_for((size_t)ng, po->threads, group_item, order);
  for (int i = 0; i < ng; i++) {
    group *g = order[i];
    if (g->st) nl_harness_die(r, 1, "%s", g->err.msg);
    int p = (int)(g - gs) % 2;
    double v[3 * FIT_VALS];
    char key[32];
    for (int f = 0; f < 3; f++) {
      fit_pack(&g->f[f], v + f * FIT_VALS);
      if (g->f[f].path) {
        double *pv = nl_xmalloc((3 * g->f[f].npath + 1) * sizeof *pv);
        for (size_t q = 0; q < g->f[f].npath; q++) {
          pv[3 * q] = (double)g->f[f].path[q].k;
          pv[3 * q + 1] = g->f[f].path[q].aic;
          pv[3 * q + 2] = g->f[f].path[q].bic;
        }
        snprintf(key, sizeof key, "path%d%d%d", g->n, p, f);
        nl_harness_unit_put(r, key, pv, 3 * g->f[f].npath);
        free(pv);
      }
      free(g->f[f].path);
    }
    snprintf(key, sizeof key, "group%d%d", g->n, p);
    nl_harness_unit_put(r, key, v, 3 * FIT_VALS);
  }
  nl_cheng_pool_free(pools[0]);
  nl_cheng_pool_free(pools[1]);
  nl_study_cheng_repro_clear(&rp);
}

void c5_readings_gather(const nl_study_cheng *s, c5_readings *R, c5_pools *T,
                        const nl_study_cheng_thesis_gmm *th, const c5_readings_options *ro, long u0)
{
  nl_harness *r = s->r;
  int reps = ro->reps;
  acc *A = nl_xcalloc(NRD, sizeof *A);
  const double *fl[MAXREP];
  for (int k = 0; k < reps; k++) {
    nl_harness_unit_get_rows(r, u0 + k, "ess", R->ess);
    fl[k] = nl_harness_unit_get(r, u0 + k, "floor", NULL);
  }
  c5_floor_gather(r, &R->floor, th->texture, th->aic, th->cutoff, fl, reps);
  if (T) {
    c5_pools_get(r, u0, T);
    nl_harness_unit_notes(r, u0);
  }
  for (int k = 0; k < reps; k++)
    for (int n = 0; n < 1 + (k < ro->all_reps); n++)
      for (int p = 0; p < 2; p++) {
        char key[32], pk[3][32];
        snprintf(key, sizeof key, "group%d%d", n, p);
        const double *v = nl_harness_unit_get(r, u0 + k, key, NULL);
        fit_out f[3];
        for (int q = 0; q < 3; q++) {
          snprintf(pk[q], sizeof pk[q], "path%d%d%d", n, p, q);
          fit_unpack(r, u0 + k, pk[q], v + q * FIT_VALS, &f[q]);
        }
        for (int d = 0; d < 2; d++)
          fit_rows(R, &A[rd_index(0, n, d, p)], &f[d], f[d].cutoff, th->texture, 0, n, d, p);
        fit_rows(R, &A[rd_index(1, n, 0, p)], &f[2], f[2].cutoff, th->texture, 1, n, 0, p);
        fit_rows(R, &A[rd_index(1, n, 1, p)], &f[2], f[2].acut, th->texture, 1, n, 1, p);
        for (int q = 0; q < 3; q++) free(f[q].path);
      }
  rows(R, A, th, ro->stride);
  free(A);
}

const char *c5_readings_write(nl_harness *r, c5_readings *R)
{
  nl_table *t = R->readings;
  static char best[80];
  int bestn = -1;
  for (size_t q = 0; q < t->nrows; q++) { /* BEST-MATCH RULE: matches summed over the textures */
    if (nl_table_value(t, q, "k0_is_input") != 0) continue;
    const char *id = nl_table_text(t, q, "reading");
    int sum = 0;
    for (size_t u = 0; u < t->nrows; u++)
      if (!strcmp(nl_table_text(t, u, "reading"), id)) sum += (int)nl_table_value(t, u, "matches");
    if (sum > bestn) {
      bestn = sum;
      snprintf(best, sizeof best, "%s", id);
    }
  }
  for (size_t q = 0; q < t->nrows; q++)
    nl_table_set(t, q, "best_match", !strcmp(nl_table_text(t, q, "reading"), best));
  for (size_t q = 0; q < R->paths->nrows; q++) {
    const char *id = nl_table_text(R->paths, q, "reading");
    nl_table_set(R->paths, q, "headline", !strcmp(id, C5_HEADLINE));
    nl_table_set(R->paths, q, "best_match", !strcmp(id, best));
  }
  nl_harness_write_table(r, R->paths, "aic_readings.tsv");
  nl_harness_time_column(r, "readings.tsv", "seconds"); /* times: times.tsv */
  nl_harness_write_table(r, t, "readings.tsv");
  nl_harness_write_table(r, R->ess, "ess.tsv");
  nl_harness_write_table(r, R->repro, "reproduce.tsv");
  c5_floor_write(r, &R->floor);
  return best;
}
