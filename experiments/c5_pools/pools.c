/* C5's tables of Tables 4.2-4.4 (pools.h): one texture at one low/high split
 * per c5_pool_case - the original against its pool, a gmm and AIC-path row per
 * cutoff rule over the fit seeds, K against the cutoff, and the held-out
 * checks of three model variants. */
#include "pools.h"
#include "fit.h"
#include "stats/nl_stats.h"
#include "base/nl_parallel.h"

#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NRULE    2
#define NVAR     3
#define NCUT     48
#define MAXSEEDS C5_MAXSEEDS

/* clang-format off */
static const char *const gmm_cols[] = {
  "texture", "low_levels", "cutoff_rule", "pool", "excluded", "input_samples", "dim", "epsilon",
  "cutoff", "K_initial", "K_initial_sd", "K_final", "K_final_sd", "AIC", "AIC_sd", "BIC", "BIC_sd",
  "loglik", "seeds", "n_ok", "status", "seconds_gmm", "paper_samples", "paper_K_initial",
  "paper_K_final", "paper_cutoff", "paper_AIC"
};
static const char *const path_cols[] = {
  "texture", "low_levels", "cutoff_rule", "K", "AIC", "BIC", "loglik", "iterations", "converged"
};
static const char *const curve_cols[] = { "texture", "low_levels", "cutoff", "K" };
static const char *const pool_cols[] = {
  "texture", "low_levels", "run", "E_start", "E_best", "kept", "seconds"
};
static const char *const fit_cols[] = {
  "texture", "low_levels", "model", "K", "d", "n_train", "n_held", "n_compared", "ll_train",
  "ll_held", "ll_aic", "ks_median", "ks_reject", "p_bonf", "params"
};
static const char *const assess_cols[] = {
  "texture", "low_levels", "model", "K", "ll_train", "ll_held", "n_held", "ks_median", "ks_reject"
};
static const char *const orig_cols[] = {
  "texture", "pattern", "low_levels", "E_ks", "E_con", "E_R_original", "E_R_pool_best",
  "E_R_pool_median", "E_R_pool_max_gap", "n_low", "seconds_opt", "seconds_pool"
};
/* clang-format on */
static const char *const rules[NRULE] = { "thesis", "matched_K0" };
static const char *const variants[NVAR] = { "full_cossin", "diag_cossin", "full_unwrap" };

typedef struct {
  double k0[MAXSEEDS], k[MAXSEEDS], aic[MAXSEEDS], bic[MAXSEEDS], ll[MAXSEEDS], sec;
  int ok;
  const char *status;
} fits;

/* The model over the run's seeds (input subsample and k-means seed); the
 * first seed's model is returned. The seeds' fits are independent items on
 * the run's threads (each from its own seed, into its own slot; summed in
 * seed order afterwards). */
typedef struct {
  const nl_cheng_pool *pool;
  const nl_cheng_model_options *mo;
  unsigned long base;
  nl_cheng_model *first;
  double k0[MAXSEEDS], k[MAXSEEDS], aic[MAXSEEDS], bic[MAXSEEDS], ll[MAXSEEDS], sec[MAXSEEDS];
  nl_cheng_model_status status[MAXSEEDS];
  nl_status st[MAXSEEDS];
  nl_error err[MAXSEEDS];
} seeds_job;

static void seed_item(void *ctx, size_t s, int t)
{
  (void)t;
  seeds_job *j = ctx;
  nl_cheng_model_options o = *j->mo;
  o.gmm.seed = nl_seed_replicate(j->base, (int)s);
  nl_cheng_model *m;
  if ((j->st[s] = nl_cheng_model_fit(j->pool, &o, o.gmm.seed, &m, &j->err[s]))) return;
  j->k0[s] = (double)m->k0;
  j->k[s] = (double)m->k;
  j->aic[s] = m->gmm ? m->gmm->aic : NAN;
  j->bic[s] = m->gmm ? m->gmm->bic : NAN;
  j->ll[s] = m->gmm ? m->gmm->loglik : NAN;
  j->sec[s] = m->seconds_cluster + m->seconds_gmm;
  j->status[s] = m->status;
  /* The rows need the first seed's path and cutoff, not its mixture: its K
   * d^2 arrays go back to nl_gmm's cache now, for the next fit, instead of
   * fresh pages (C5 quick: 1.87 -> 1.50 GB first-touched). */
  nl_gmm_free(m->gmm);
  m->gmm = NULL;
  if (s == 0)
    j->first = m;
  else
    nl_cheng_model_free(m);
}

/* The seeds' results summed in seed order; the first seed's model returned. */
static nl_cheng_model *seeds_collect(nl_harness *r, seeds_job *j, int nseeds, fits *f)
{
  memset(f, 0, sizeof *f);
  f->status = "ok";
  for (int s = 0; s < nseeds; s++) {
    if (j->st[s]) nl_harness_die(r, 1, "%s", j->err[s].msg);
    f->k0[s] = j->k0[s];
    f->k[s] = j->k[s];
    f->aic[s] = j->aic[s];
    f->bic[s] = j->bic[s];
    f->ll[s] = j->ll[s];
    f->sec += j->sec[s];
    if (j->status[s] == NL_CHENG_MODEL_OK)
      f->ok++;
    else if (!strcmp(f->status, "ok"))
      f->status = nl_cheng_model_status_name(j->status[s]);
  }
  return j->first;
}

/* Pool rows: per run, and the original against the pool. */
static void pool_rows(c5_pools *T, const nl_study_cheng_thesis_gmm *th, int low,
                      const nl_study_cheng_repro *rp)
{
  const nl_cheng_pool *pool = rp->pool;
  double *be = nl_xmalloc((size_t)pool->runs * sizeof *be);      /* each run's best */
  double *es = nl_xmalloc((pool->n ? pool->n : 1) * sizeof *es); /* kept rows' E_R, sorted */
  size_t *kept = nl_xcalloc((size_t)pool->runs, sizeof *kept);
  double gap = 0;
  for (size_t i = 0; i < pool->n; i++) {
    es[i] = pool->e[i];
    kept[pool->run[i]]++;
    gap = fmax(gap, pool->e[i] - pool->run_best[pool->run[i]]);
  }
  for (int q = 0; q < pool->runs; q++) {
    be[q] = pool->run_best[q];
    nl_table_append(T->runs, "sdddddd", th->texture, (double)low, (double)q, pool->run_start[q],
                    pool->run_best[q], (double)kept[q], pool->run_seconds[q]);
  }
  gsl_sort(es, 1, pool->n);
  nl_table_append(T->orig, "ssdddddddddd", th->texture, th->pattern, (double)low, rp->ev.e_ks,
                  rp->ev.e_con, pool->e_opt, gsl_stats_min(be, 1, (size_t)pool->runs),
                  pool->n ? gsl_stats_median_from_sorted_data(es, 1, pool->n) : NAN, gap,
                  (double)pool->nlow, rp->seconds_opt, rp->seconds_pool);
  free(be);
  free(es);
  free(kept);
}

/* One cutoff rule: the row of Tables 4.2-4.4, its AIC path (first seed). */
static nl_cheng_model *rule_rows(nl_harness *r, c5_pools *T, const nl_study_cheng_thesis_gmm *th,
                                 int low, int ru, const nl_cheng_pool *pool, seeds_job *j,
                                 double eps, int nseeds)
{
  fits f;
  nl_cheng_model *m = seeds_collect(r, j, nseeds, &f);
  nl_table_append(
      T->gmm, "sdsdddddddddddddddddsdddddd", th->texture, (double)low, rules[ru], (double)pool->n,
      (double)pool->excluded, (double)m->n_in, (double)m->d, eps, m->cutoff,
      nl_stats_mean(f.k0, nseeds, NL_STATS_RUNNING), nl_stats_sd(f.k0, nseeds, NL_STATS_RUNNING),
      nl_stats_mean(f.k, nseeds, NL_STATS_RUNNING), nl_stats_sd(f.k, nseeds, NL_STATS_RUNNING),
      nl_stats_mean(f.aic, nseeds, NL_STATS_RUNNING), nl_stats_sd(f.aic, nseeds, NL_STATS_RUNNING),
      nl_stats_mean(f.bic, nseeds, NL_STATS_RUNNING), nl_stats_sd(f.bic, nseeds, NL_STATS_RUNNING),
      nl_stats_mean(f.ll, nseeds, NL_STATS_RUNNING), (double)nseeds, (double)f.ok, f.status, f.sec,
      (double)th->samples, (double)th->k0, (double)th->k, th->cutoff, th->aic);
  for (size_t q = 0; q < m->npath; q++)
    nl_table_append(T->path, "sdsdddddd", th->texture, (double)low, rules[ru], (double)m->path[q].k,
                    m->path[q].aic, m->path[q].bic, m->path[q].loglik,
                    (double)m->path[q].iterations, (double)m->path[q].converged);
  return m;
}

/* K against the cutoff, up to the largest possible chord 2 sqrt(n_low). */
static void curve_rows(nl_harness *r, c5_pools *T, const nl_study_cheng_thesis_gmm *th, int low,
                       const nl_cheng_pool *pool, const nl_cheng_model *m)
{
  double cut[NCUT];
  size_t kc[NCUT];
  nl_error err;
  if (m->n_in < 2) return;
  for (int q = 0; q < NCUT; q++) cut[q] = 2.0 * sqrt((double)pool->nlow) * (q + 1) / NCUT;
  if (nl_cheng_k_curve(pool, m, cut, NCUT, kc, &err)) nl_harness_die(r, 1, "%s", err.msg);
  for (int q = 0; q < NCUT; q++)
    nl_table_append(T->curve, "sddd", th->texture, (double)low, cut[q], (double)kc[q]);
}

/* Beyond the paper: the matched-K0 model in three variants against the pool
 * (independent items on the run's threads; rows appended in variant order). */
typedef struct {
  nl_harness *r;
  const nl_study_cheng_thesis_gmm *th;
  const nl_cheng_pool *pool;
  const nl_cheng_model_options *mo;
  nl_cheng_model_check ck[NVAR];
  c5_fit fit;          /* variant 0, the thesis's full mixture (fit.h) */
  double d, n_in;      /* its dimension and input rows */
  double k[NVAR];
  nl_status st[NVAR];
  nl_error err[NVAR];
} assess_job;

static void assess_item(void *ctx, size_t v, int t)
{
  (void)t;
  assess_job *j = ctx;
  nl_cheng_model_options o = *j->mo;
  if (v == 1) o.gmm.covariance = NL_GMM_DIAG;
  if (v == 2) o.rep = NL_CHENG_REP_UNWRAP;
  o.cutoff = -1; /* the cutoff that gives the thesis's initial K */
  o.target_k = (size_t)j->th->k0;
  o.gmm.seed = nl_harness_seed(j->r);
  nl_cheng_model *m;
  j->ck[v] = (nl_cheng_model_check){ NAN, NAN, 0, NAN, NAN };
  if ((j->st[v] = nl_cheng_model_fit(j->pool, &o, o.gmm.seed, &m, &j->err[v]))) return;
  j->k[v] = (double)m->k;
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(nl_harness_seed(j->r), "c5.held_out", 0));
  if (m->gmm)
    j->st[v] = nl_cheng_model_assess(j->pool, m, C5_ASSESS_DRAWS, rng, &j->ck[v], &j->err[v]);
  if (v == 0 && !j->st[v]) {
    gsl_rng_set(rng, nl_seed_stream(nl_harness_seed(j->r), "c5.fit_check", 0));
    j->d = (double)m->d;
    j->n_in = (double)m->n_in;
    j->st[v] = c5_fit_check(j->pool, m, C5_ASSESS_DRAWS, rng, &j->fit, &j->err[v]);
  }
  gsl_rng_free(rng);
  nl_cheng_model_free(m);
}

static void assess_rows(nl_harness *r, c5_pools *T, const nl_study_cheng_thesis_gmm *th, int low,
                        const assess_job *j)
{
  for (int v = 0; v < NVAR; v++) {
    if (j->st[v]) nl_harness_die(r, 1, "%s", j->err[v].msg);
    const nl_cheng_model_check *ck = &j->ck[v];
    nl_table_append(T->assess, "sdsdddddd", th->texture, (double)low, variants[v], j->k[v],
                    ck->ll_train, ck->ll_held, (double)ck->n_held, ck->ks_median, ck->ks_reject);
  }
  /* AIC's own estimate of the held-out mean log-likelihood: the training
   * mean less the parameters per input row (AIC = -2 L + 2 m, eq. 3.19) */
  const c5_fit *f = &j->fit;
  double ll_aic = j->ck[0].ll_train - j->k[0] * c5_params_per_component(j->d) / j->n_in;
  nl_table_append(T->fit, "sdsdddddddddddd", th->texture, (double)low, "mixture", j->k[0], j->d,
                  j->n_in, (double)f->n_held, (double)f->n_compared, j->ck[0].ll_train,
                  j->ck[0].ll_held, ll_aic, f->ks_median, f->ks_reject, f->p_bonf,
                  j->k[0] * c5_params_per_component(j->d));
  nl_table_append(T->fit, "sdsdddddsssdddd", th->texture, (double)low, "uniform", 0.0, j->d,
                  j->n_in, (double)f->n_held, (double)f->n_compared, "n/a", "n/a", "n/a",
                  f->ks_median_uniform, f->ks_reject_uniform, f->p_bonf_uniform, 0.0);
}

/* Both rules' seeds and the assessment's variants: one region of
 * independent items, the longest paths first (the variants, then the
 * matched-K0 rule's seeds, then the thesis cutoff's smaller K): the threads
 * end together, and arrays allocated for a large K serve the smaller ones
 * from nl_gmm's cache. C5 quick, four runs each, idle: 5.10 -> 4.78 s wall. */
typedef struct {
  seeds_job *sj[NRULE];
  assess_job *aj;
  size_t nseeds, nassess;
} case_job;

static void case_item(void *ctx, size_t i, int t)
{
  case_job *c = ctx;
  if (i < c->nassess)
    assess_item(c->aj, i, t);
  else
    seed_item(c->sj[NRULE - 1 - (i - c->nassess) / c->nseeds], (i - c->nassess) % c->nseeds, t);
}

void c5_pools_alloc(c5_pools *T)
{
  T->gmm = nl_table_alloc(sizeof gmm_cols / sizeof *gmm_cols, gmm_cols);
  T->path = nl_table_alloc(sizeof path_cols / sizeof *path_cols, path_cols);
  T->curve = nl_table_alloc(sizeof curve_cols / sizeof *curve_cols, curve_cols);
  T->runs = nl_table_alloc(sizeof pool_cols / sizeof *pool_cols, pool_cols);
  T->assess = nl_table_alloc(sizeof assess_cols / sizeof *assess_cols, assess_cols);
  T->fit = nl_table_alloc(sizeof fit_cols / sizeof *fit_cols, fit_cols);
  T->orig = nl_table_alloc(sizeof orig_cols / sizeof *orig_cols, orig_cols);
}

void c5_pools_write(nl_harness *r, const c5_pools *T)
{
  nl_harness_time_column(r, "original.tsv", "seconds_opt"); /* times: times.tsv */
  nl_harness_time_column(r, "original.tsv", "seconds_pool");
  nl_harness_time_column(r, "pool_runs.tsv", "seconds");
  nl_harness_time_column(r, "gmm.tsv", "seconds_gmm");
  nl_harness_write_table(r, T->orig, "original.tsv");
  nl_harness_write_table(r, T->gmm, "gmm.tsv");
  nl_harness_write_table(r, T->path, "aic_path.tsv");
  nl_harness_write_table(r, T->curve, "cutoff_k.tsv");
  nl_harness_write_table(r, T->runs, "pool_runs.tsv");
  nl_harness_write_table(r, T->assess, "assess.tsv");
  nl_harness_write_table(r, T->fit, "fit.tsv");
}

static const char *const pools_keys[7] = { "gmm", "path", "curve", "runs", "assess", "fit", "orig" };

void c5_pools_put(nl_harness *r, const c5_pools *T)
{
  const nl_table *t[7] = { T->gmm, T->path, T->curve, T->runs, T->assess, T->fit, T->orig };
  for (int i = 0; i < 7; i++) nl_harness_unit_put_table(r, pools_keys[i], t[i]);
}

void c5_pools_get(nl_harness *r, long u, c5_pools *T)
{
  nl_table *t[7] = { T->gmm, T->path, T->curve, T->runs, T->assess, T->fit, T->orig };
  for (int i = 0; i < 7; i++) nl_harness_unit_get_rows(r, u, pools_keys[i], t[i]);
}

void c5_pools_free(c5_pools *T)
{
  nl_table_free(T->gmm);
  nl_table_free(T->path);
  nl_table_free(T->curve);
  nl_table_free(T->runs);
  nl_table_free(T->assess);
  nl_table_free(T->fit);
  nl_table_free(T->orig);
}

/* The texture th on s's setting: its pattern (returned; caller frees), *c =
 * s's config with th's control term, the original and its pool in *rp.
 * Exit 1 on error. */
static nl_cheng_pattern *repro_open(const nl_study_cheng *s, const nl_study_cheng_thesis_gmm *th,
                                    const nl_cheng_pool_options *po, nl_cheng_config *c,
                                    nl_study_cheng_repro *rp)
{
  nl_cheng_pattern *pat = nl_study_cheng_pattern(s, th->pattern);
  nl_error err;
  *c = s->c;
  c->con = th->con;
  if (nl_study_cheng_repro_original(c, pat, nl_harness_seed(s->r), rp, &err) ||
      nl_study_cheng_repro_pool(rp, c, pat, po, nl_harness_seed(s->r), &err))
    nl_harness_die(s->r, 1, "%s: %s", th->texture, err.msg);
  return pat;
}

/* One texture at one low/high split: original, pool, both rules, curve, checks. */
void c5_pool_case(const nl_study_cheng *s, c5_pools *T, const nl_study_cheng_thesis_gmm *th,
                  const nl_cheng_pool_options *pop, const nl_cheng_model_options *mo, int nseeds,
                  int full)
{
  nl_cheng_config c;
  nl_study_cheng_repro rp;
  nl_cheng_pattern *pat = repro_open(s, th, pop, &c, &rp);
  c5_pool_case_with(s, T, th, pop, mo, nseeds, full, &rp);
  nl_study_cheng_repro_clear(&rp);
  nl_cheng_pattern_free(pat);
}

void c5_pool_case_with(const nl_study_cheng *s, c5_pools *T, const nl_study_cheng_thesis_gmm *th,
                       const nl_cheng_pool_options *pop, const nl_cheng_model_options *mo,
                       int nseeds, int full, nl_study_cheng_repro *rpp)
{
  nl_harness *r = s->r;
  nl_cheng_pool_options po = *pop;
  nl_study_cheng_repro rp = *rpp;
  pool_rows(T, th, po.low_levels, &rp);
  char key[64];
  snprintf(key, sizeof key, "pool_bytes_%s_low%d", th->texture, po.low_levels);
  nl_harness_note(r, key, "%zu (%zu solutions x %zu angles)", nl_cheng_pool_bytes(rp.pool),
                  rp.pool->n, rp.pool->nlow);
  nl_cheng_model_options o[NRULE];
  case_job cj = { .nseeds = (size_t)nseeds, .nassess = full ? NVAR : 0 };
  for (int ru = 0; ru < NRULE; ru++) {
    o[ru] = *mo;
    if (ru == 0)
      o[ru].cutoff = th->cutoff;
    else {
      o[ru].cutoff = -1;
      o[ru].target_k = (size_t)th->k0;
    }
    cj.sj[ru] = nl_xcalloc(1, sizeof *cj.sj[ru]);
    *cj.sj[ru] = (seeds_job){ .pool = rp.pool, .mo = &o[ru], .base = nl_harness_seed(r) };
  }
  if (full) {
    cj.aj = nl_xcalloc(1, sizeof *cj.aj);
    *cj.aj = (assess_job){ .r = r, .th = th, .pool = rp.pool, .mo = mo };
  }
  nl_parallel_for(cj.nassess + NRULE * cj.nseeds, mo->gmm.threads, case_item, &cj);
  for (int ru = 0; ru < NRULE; ru++) {
    nl_cheng_model *m =
        rule_rows(r, T, th, po.low_levels, ru, rp.pool, cj.sj[ru], po.epsilon, nseeds);
    if (ru == 1) {
      curve_rows(r, T, th, po.low_levels, rp.pool, m);
      snprintf(key, sizeof key, "cluster_bytes_%s_low%d", th->texture, po.low_levels);
      nl_harness_note(r, key, "%zu (condensed distances of %zu samples + linkage)",
                      m->cluster_bytes, m->n_in);
    }
    nl_cheng_model_free(m);
    free(cj.sj[ru]);
  }
  if (full) assess_rows(r, T, th, po.low_levels, cj.aj);
  free(cj.aj);
}
