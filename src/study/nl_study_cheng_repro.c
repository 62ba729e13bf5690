/* What C5 and C6 share (noise reproduction): the thesis's Tables 4.2-4.4,
 * the --set parameters, the chain original -> pool -> model, and C5's tables
 * (one texture at one low/high split per nl_study_cheng_pool_case). */
#include "study/nl_study_cheng.h"
#include "stats/nl_stats.h"
#include "base/nl_parallel.h"

#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const nl_study_cheng_thesis_gmm nl_study_cheng_thesis_gmm_tables[3] = {
  {"erosion", "disc", NL_CHENG_CON_ABS, "Table 4.2", 1000, 10.0, 30, 36, 18.6, -15079449.0743},
  {"marble", "rings", NL_CHENG_CON_SIN, "Table 4.3", 1000, 10.0, 39, 42, 19.5, -25353476.4511},
  {"cloud", "flower", NL_CHENG_CON_PLAIN, "Table 4.4", 1000, 10.0, 20, 24, 15.5, -20163091.2097},
};

void nl_study_cheng_repro_params(nl_harness *r, nl_cheng_pool_options *po, nl_cheng_model_options *mo)
{
  int q = nl_harness_quick(r);
  nl_cheng_pool_options_default(po);
  nl_cheng_model_options_default(mo);
  po->runs = (int)nl_harness_param_int(r, "runs", q ? 6 : po->runs, 1, 100000,
        "Q: annealing runs in the solution pool (Cheng sec. 3.5.2; quick 6)");          /* Q */
  po->keep = (int)nl_harness_param_int(r, "keep", q ? 20 : po->keep, 1, 100000,
        "N: solutions kept per run in the pool (Cheng sec. 3.5.2; quick 20)");         /* N */
  po->epsilon = nl_harness_param(r, "epsilon", po->epsilon, 0, 1e300,
        "error bound on E_R: pool solutions above the run's best by more than this are left out");
  po->low_levels = (int)nl_harness_param_int(r, "low_levels", po->low_levels, 1, NL_CHENG_MAX_OCTAVES - 1,
        "levels 1..low_levels hold the shared low-frequency gradients that are reproduced");
  /* Threads for the pool runs, the fits and EM's steps: the run's --threads
   * (a speed setting, not a parameter: no table depends on it). */
  po->threads = nl_harness_threads(r);
  mo->samples = (size_t)nl_harness_param_int(r, "samples", q ? 100 : (long)mo->samples, 0, 1000000,
        "input samples drawn from the pool for clustering and the mixture, 0 = all (quick 100)");
  mo->threshold = nl_harness_param(r, "T", mo->threshold, 0, 1e300,
        "AIC threshold T: a mixture component is added only if AIC falls by at least T");
  mo->k_extra = (size_t)nl_harness_param_int(r, "k_extra", (long)mo->k_extra, 0, 100000,
        "the GMM growth path is capped at K0 + k_extra components");
  mo->rep = (nl_cheng_rep)nl_harness_param_int(r, "unwrap", mo->rep == NL_CHENG_REP_UNWRAP, 0, 1,
        "1: angles unwrapped to a line before the mixture; 0: each angle as (cos, sin)");
  mo->gmm.covariance = nl_harness_param_int(r, "diag", 0, 0, 1,
        "1: diagonal GMM covariances; 0: full covariances") ? NL_GMM_DIAG : NL_GMM_FULL;
  mo->gmm.max_iter = (size_t)nl_harness_param_int(r, "max_iter", (long)mo->gmm.max_iter, 1, 1000000,
        "EM iterations allowed per mixture fit before it counts as not converged");
  mo->gmm.threads = po->threads;   /* EM's steps; fits run by a threaded caller run theirs serially */
}

nl_status nl_study_cheng_repro_original(const nl_cheng_config *c, const nl_cheng_pattern *pat,
                                        unsigned long seed, nl_study_cheng_repro *out, nl_error *err)
{
  memset(out, 0, sizeof *out);
  double t0 = nl_time_now();
  nl_status st = nl_cheng_run(c, pat, seed, &out->ev, NULL, &out->opt, err);
  out->seconds_opt = nl_time_now() - t0;
  return st;
}

nl_status nl_study_cheng_repro_pool(nl_study_cheng_repro *rp, const nl_cheng_config *c, const nl_cheng_pattern *pat,
                                    const nl_cheng_pool_options *po, unsigned long seed, nl_error *err)
{
  double t0 = nl_time_now();
  nl_status st = nl_cheng_pool_collect(rp->opt, c, pat, po, seed, &rp->pool, err);
  rp->seconds_pool = nl_time_now() - t0;
  return st;
}

void nl_study_cheng_repro_clear(nl_study_cheng_repro *rp)
{
  nl_noise_grad2_free(rp->opt);
  nl_cheng_pool_free(rp->pool);
  memset(rp, 0, sizeof *rp);
}

/* ---- C5's tables -------------------------------------------------------- */

#define NRULE 2
#define NVAR 3
#define NCUT 48
#define MAXSEEDS NL_STUDY_CHENG_MAXSEEDS

static const char *const gmm_cols[] = {
  "texture", "low_levels", "cutoff_rule", "pool", "excluded", "input_samples", "dim", "epsilon", "cutoff",
  "K_initial", "K_initial_sd", "K_final", "K_final_sd", "AIC", "AIC_sd", "BIC", "BIC_sd", "loglik",
  "seeds", "n_ok", "status", "seconds_gmm",
  "paper_samples", "paper_K_initial", "paper_K_final", "paper_cutoff", "paper_AIC"};
static const char *const path_cols[] = {"texture", "low_levels", "cutoff_rule", "K", "AIC", "BIC", "loglik", "iterations", "converged"};
static const char *const curve_cols[] = {"texture", "low_levels", "cutoff", "K"};
static const char *const pool_cols[] = {"texture", "low_levels", "run", "E_start", "E_best", "kept", "seconds"};
static const char *const assess_cols[] = {"texture", "low_levels", "model", "K", "ll_train", "ll_held", "n_held", "ks_median", "ks_reject"};
static const char *const orig_cols[] = {"texture", "pattern", "low_levels", "E_ks", "E_con", "E_R_original", "E_R_pool_best",
                                        "E_R_pool_median", "E_R_pool_max_gap", "n_low", "seconds_opt", "seconds_pool"};
static const char *const rules[NRULE] = {"thesis", "matched_K0"};
static const char *const variants[NVAR] = {"full_cossin", "diag_cossin", "full_unwrap"};

typedef struct { double k0[MAXSEEDS], k[MAXSEEDS], aic[MAXSEEDS], bic[MAXSEEDS], ll[MAXSEEDS], sec; int ok; const char *status; } fits;

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
  j->k0[s] = (double)m->k0; j->k[s] = (double)m->k;
  j->aic[s] = m->gmm ? m->gmm->aic : NAN; j->bic[s] = m->gmm ? m->gmm->bic : NAN;
  j->ll[s] = m->gmm ? m->gmm->loglik : NAN;
  j->sec[s] = m->seconds_cluster + m->seconds_gmm;
  j->status[s] = m->status;
  /* The rows need the first seed's path and cutoff, not its mixture: its K
   * d^2 arrays go back to nl_gmm's cache now, for the next fit, instead of
   * fresh pages (C5 quick: 1.87 -> 1.50 GB first-touched). */
  nl_gmm_free(m->gmm);
  m->gmm = NULL;
  if (s == 0) j->first = m; else nl_cheng_model_free(m);
}

/* The seeds' results summed in seed order; the first seed's model returned. */
static nl_cheng_model *seeds_collect(nl_harness *r, seeds_job *j, int nseeds, fits *f)
{
  memset(f, 0, sizeof *f);
  f->status = "ok";
  for (int s = 0; s < nseeds; s++) {
    if (j->st[s]) nl_harness_die(r, 1, "%s", j->err[s].msg);
    f->k0[s] = j->k0[s]; f->k[s] = j->k[s]; f->aic[s] = j->aic[s]; f->bic[s] = j->bic[s]; f->ll[s] = j->ll[s];
    f->sec += j->sec[s];
    if (j->status[s] == NL_CHENG_MODEL_OK) f->ok++;
    else if (!strcmp(f->status, "ok")) f->status = nl_cheng_model_status_name(j->status[s]);
  }
  return j->first;
}

/* Pool rows: per run, and the original against the pool. */
static void pool_rows(nl_study_cheng_pools *T, const nl_study_cheng_thesis_gmm *th, int low, const nl_study_cheng_repro *rp)
{
  const nl_cheng_pool *pool = rp->pool;
  double *be = nl_xmalloc((size_t)pool->runs * sizeof *be), *es = nl_xmalloc((pool->n ? pool->n : 1) * sizeof *es);
  size_t *kept = nl_xcalloc((size_t)pool->runs, sizeof *kept);
  double gap = 0;
  for (size_t i = 0; i < pool->n; i++) {
    es[i] = pool->e[i];
    kept[pool->run[i]]++;
    gap = fmax(gap, pool->e[i] - pool->run_best[pool->run[i]]);
  }
  for (int q = 0; q < pool->runs; q++) {
    be[q] = pool->run_best[q];
    nl_table_append(T->runs, "sdddddd", th->texture, (double)low, (double)q, pool->run_start[q], pool->run_best[q],
                    (double)kept[q], pool->run_seconds[q]);
  }
  gsl_sort(es, 1, pool->n);
  nl_table_append(T->orig, "ssdddddddddd", th->texture, th->pattern, (double)low, rp->ev.e_ks, rp->ev.e_con, pool->e_opt,
                  gsl_stats_min(be, 1, (size_t)pool->runs), pool->n ? gsl_stats_median_from_sorted_data(es, 1, pool->n) : NAN,
                  gap, (double)pool->nlow, rp->seconds_opt, rp->seconds_pool);
  free(be); free(es); free(kept);
}

/* One cutoff rule: the row of Tables 4.2-4.4, its AIC path (first seed). */
static nl_cheng_model *rule_rows(nl_harness *r, nl_study_cheng_pools *T, const nl_study_cheng_thesis_gmm *th, int low, int ru,
                                 const nl_cheng_pool *pool, seeds_job *j, double eps, int nseeds)
{
  fits f;
  nl_cheng_model *m = seeds_collect(r, j, nseeds, &f);
  nl_table_append(T->gmm, "sdsdddddddddddddddddsdddddd", th->texture, (double)low, rules[ru], (double)pool->n,
                  (double)pool->excluded, (double)m->n_in, (double)m->d, eps, m->cutoff, nl_study_mean(f.k0, nseeds),
                  nl_study_sd(f.k0, nseeds), nl_study_mean(f.k, nseeds), nl_study_sd(f.k, nseeds), nl_study_mean(f.aic, nseeds),
                  nl_study_sd(f.aic, nseeds), nl_study_mean(f.bic, nseeds), nl_study_sd(f.bic, nseeds), nl_study_mean(f.ll, nseeds),
                  (double)nseeds, (double)f.ok, f.status, f.sec, (double)th->samples, (double)th->k0, (double)th->k,
                  th->cutoff, th->aic);
  for (size_t q = 0; q < m->npath; q++)
    nl_table_append(T->path, "sdsdddddd", th->texture, (double)low, rules[ru], (double)m->path[q].k, m->path[q].aic,
                    m->path[q].bic, m->path[q].loglik, (double)m->path[q].iterations, (double)m->path[q].converged);
  return m;
}

/* K against the cutoff, up to the largest possible chord 2 sqrt(n_low). */
static void curve_rows(nl_harness *r, nl_study_cheng_pools *T, const nl_study_cheng_thesis_gmm *th, int low, const nl_cheng_pool *pool,
                       const nl_cheng_model *m)
{
  double cut[NCUT];
  size_t kc[NCUT];
  nl_error err;
  if (m->n_in < 2) return;
  for (int q = 0; q < NCUT; q++) cut[q] = 2.0 * sqrt((double)pool->nlow) * (q + 1) / NCUT;
  if (nl_cheng_k_curve(pool, m, cut, NCUT, kc, &err)) nl_harness_die(r, 1, "%s", err.msg);
  for (int q = 0; q < NCUT; q++) nl_table_append(T->curve, "sddd", th->texture, (double)low, cut[q], (double)kc[q]);
}

/* Beyond the paper: the matched-K0 model in three variants against the pool
 * (independent items on the run's threads; rows appended in variant order). */
typedef struct {
  nl_harness *r;
  const nl_study_cheng_thesis_gmm *th;
  const nl_cheng_pool *pool;
  const nl_cheng_model_options *mo;
  nl_cheng_model_check ck[NVAR];
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
  o.cutoff = -1;   /* nl_study_cheng_matched_model's options */
  o.target_k = (size_t)j->th->k0;
  o.gmm.seed = nl_harness_seed(j->r);
  nl_cheng_model *m;
  j->ck[v] = (nl_cheng_model_check){NAN, NAN, 0, NAN, NAN};
  if ((j->st[v] = nl_cheng_model_fit(j->pool, &o, o.gmm.seed, &m, &j->err[v]))) return;
  j->k[v] = (double)m->k;
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(nl_harness_seed(j->r), "c5.held_out", 0));
  if (m->gmm) j->st[v] = nl_cheng_model_assess(j->pool, m, 1000, rng, &j->ck[v], &j->err[v]);
  gsl_rng_free(rng);
  nl_cheng_model_free(m);
}

static void assess_rows(nl_harness *r, nl_study_cheng_pools *T, const nl_study_cheng_thesis_gmm *th, int low, const assess_job *j)
{
  for (int v = 0; v < NVAR; v++) {
    if (j->st[v]) nl_harness_die(r, 1, "%s", j->err[v].msg);
    const nl_cheng_model_check *ck = &j->ck[v];
    nl_table_append(T->assess, "sdsdddddd", th->texture, (double)low, variants[v], j->k[v], ck->ll_train,
                    ck->ll_held, (double)ck->n_held, ck->ks_median, ck->ks_reject);
  }
}

/* Both rules' seeds and the assessment's variants: one region of
 * independent items, the longest paths first (the variants, then the
 * matched-K0 rule's seeds, then the thesis cutoff's smaller K): the threads
 * end together, and arrays allocated for a large K serve the smaller ones
 * from nl_gmm's cache. C5 quick, four runs each, idle: 5.10 -> 4.78 s wall. */
typedef struct { seeds_job *sj[NRULE]; assess_job *aj; size_t nseeds, nassess; } case_job;

static void case_item(void *ctx, size_t i, int t)
{
  case_job *c = ctx;
  if (i < c->nassess) assess_item(c->aj, i, t);
  else seed_item(c->sj[NRULE - 1 - (i - c->nassess) / c->nseeds], (i - c->nassess) % c->nseeds, t);
}

nl_cheng_pattern *nl_study_cheng_repro_open(const nl_study_cheng *s, const nl_study_cheng_thesis_gmm *th,
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

nl_cheng_model *nl_study_cheng_matched_model(nl_harness *r, const nl_cheng_pool *pool, const nl_study_cheng_thesis_gmm *th,
                                             const nl_cheng_model_options *mo)
{
  nl_cheng_model_options o = *mo;
  o.cutoff = -1;   /* the cutoff that gives the thesis's initial K */
  o.target_k = (size_t)th->k0;
  o.gmm.seed = nl_harness_seed(r);
  nl_cheng_model *m;
  nl_error err;
  if (nl_cheng_model_fit(pool, &o, nl_harness_seed(r), &m, &err)) nl_harness_die(r, 1, "%s", err.msg);
  return m;
}

void nl_study_cheng_pools_alloc(nl_study_cheng_pools *T)
{
  T->gmm = nl_table_alloc(sizeof gmm_cols / sizeof *gmm_cols, gmm_cols);
  T->path = nl_table_alloc(sizeof path_cols / sizeof *path_cols, path_cols);
  T->curve = nl_table_alloc(sizeof curve_cols / sizeof *curve_cols, curve_cols);
  T->runs = nl_table_alloc(sizeof pool_cols / sizeof *pool_cols, pool_cols);
  T->assess = nl_table_alloc(sizeof assess_cols / sizeof *assess_cols, assess_cols);
  T->orig = nl_table_alloc(sizeof orig_cols / sizeof *orig_cols, orig_cols);
}

void nl_study_cheng_pools_write(nl_harness *r, const nl_study_cheng_pools *T)
{
  nl_harness_write_table(r, T->orig, "original.tsv");
  nl_harness_write_table(r, T->gmm, "gmm.tsv");
  nl_harness_write_table(r, T->path, "aic_path.tsv");
  nl_harness_write_table(r, T->curve, "cutoff_k.tsv");
  nl_harness_write_table(r, T->runs, "pool_runs.tsv");
  nl_harness_write_table(r, T->assess, "assess.tsv");
  nl_harness_check(r, "original.tsv", "seconds_opt", "ignore");   /* times: never compared */
  nl_harness_check(r, "original.tsv", "seconds_pool", "ignore");
  nl_harness_check(r, "pool_runs.tsv", "seconds", "ignore");
  nl_harness_check(r, "gmm.tsv", "seconds_gmm", "ignore");
}

void nl_study_cheng_pools_free(nl_study_cheng_pools *T)
{
  nl_table_free(T->gmm); nl_table_free(T->path); nl_table_free(T->curve); nl_table_free(T->runs);
  nl_table_free(T->assess); nl_table_free(T->orig);
}

/* One texture at one low/high split: original, pool, both rules, curve, checks. */
void nl_study_cheng_pool_case(const nl_study_cheng *s, nl_study_cheng_pools *T, const nl_study_cheng_thesis_gmm *th,
                              const nl_cheng_pool_options *pop, const nl_cheng_model_options *mo, int nseeds,
                              int full)
{
  nl_cheng_config c;
  nl_study_cheng_repro rp;
  nl_cheng_pattern *pat = nl_study_cheng_repro_open(s, th, pop, &c, &rp);
  nl_study_cheng_pool_case_with(s, T, th, pop, mo, nseeds, full, &rp);
  nl_study_cheng_repro_clear(&rp);
  nl_cheng_pattern_free(pat);
}

void nl_study_cheng_pool_case_with(const nl_study_cheng *s, nl_study_cheng_pools *T, const nl_study_cheng_thesis_gmm *th,
                                   const nl_cheng_pool_options *pop, const nl_cheng_model_options *mo, int nseeds,
                                   int full, nl_study_cheng_repro *rpp)
{
  nl_harness *r = s->r;
  nl_cheng_pool_options po = *pop;
  nl_study_cheng_repro rp = *rpp;
  pool_rows(T, th, po.low_levels, &rp);
  char key[64];
  snprintf(key, sizeof key, "pool_bytes_%s_low%d", th->texture, po.low_levels);
  nl_harness_note(r, key, "%zu (%zu solutions x %zu angles)", nl_cheng_pool_bytes(rp.pool), rp.pool->n, rp.pool->nlow);
  nl_cheng_model_options o[NRULE];
  case_job cj = {.nseeds = (size_t)nseeds, .nassess = full ? NVAR : 0};
  for (int ru = 0; ru < NRULE; ru++) {
    o[ru] = *mo;
    if (ru == 0) o[ru].cutoff = th->cutoff;
    else { o[ru].cutoff = -1; o[ru].target_k = (size_t)th->k0; }
    cj.sj[ru] = nl_xcalloc(1, sizeof *cj.sj[ru]);
    *cj.sj[ru] = (seeds_job){.pool = rp.pool, .mo = &o[ru], .base = nl_harness_seed(r)};
  }
  if (full) {
    cj.aj = nl_xcalloc(1, sizeof *cj.aj);
    *cj.aj = (assess_job){.r = r, .th = th, .pool = rp.pool, .mo = mo};
  }
  nl_parallel_for(cj.nassess + NRULE * cj.nseeds, mo->gmm.threads, case_item, &cj);
  for (int ru = 0; ru < NRULE; ru++) {
    nl_cheng_model *m = rule_rows(r, T, th, po.low_levels, ru, rp.pool, cj.sj[ru], po.epsilon, nseeds);
    if (ru == 1) {
      curve_rows(r, T, th, po.low_levels, rp.pool, m);
      snprintf(key, sizeof key, "cluster_bytes_%s_low%d", th->texture, po.low_levels);
      nl_harness_note(r, key, "%zu (condensed distances of %zu samples + linkage)", m->cluster_bytes, m->n_in);
    }
    nl_cheng_model_free(m);
    free(cj.sj[ru]);
  }
  if (full) assess_rows(r, T, th, po.low_levels, cj.aj);
  free(cj.aj);
}

/* ---- C6's reproductions ------------------------------------------------- */

#define NSHOW 8   /* reproductions shown (montage, CDF) */

static const char *const c6_rep_cols[] = {"texture", "swap", "rep", "E_ks", "p_ks", "E_con", "ks2_D", "ms_reproduce", "ms_texture"};
static const char *const c6_sum_cols[] = {
  "texture", "kind", "n", "E_ks", "E_ks_sd", "E_con", "E_con_sd", "p_ks_min", "ks2_D", "ks2_D_sd",
  "below_ks", "below_con", "ms_reproduce", "ms_texture", "seconds_opt", "K",
  "r_pattern", "contrast", "E_con_random", "E_con_const"};   /* controllability (nl_study_cheng_control_text) */

typedef struct { double ks[4096], con[4096], p[4096], d[4096], ms[4096], mst[4096], rp[4096], ct[4096]; } samples;

/* One reproduction's evaluation, item i of a nl_parallel_for: the texture a
 * user waits for (its time added to the draw's), E_KS, E_Con and the
 * two-sample D against the original's angles, into slot i of s. The draws
 * themselves stay on the calling thread, in order, from the one generator
 * (nl_cheng_reproduce), so the tables are those of the serial loop. */
typedef struct {
  const nl_study_cheng_repro *rp;
  const nl_cheng_config *c;
  const nl_cheng_pattern *pat;
  nl_noise_grad2 **out;
  samples *s;
  nl_status *st;
  nl_error *err;
} reps_job;

static void evaluate_item(void *ctx, size_t i, int thread)
{
  (void)thread;
  reps_job *j = ctx;
  samples *s = j->s;
  double t0 = nl_time_now();
  nl_image *tex = nl_study_cheng_texture_image(j->out[i], j->c, 256);   /* what a user waits for: table + texture */
  s->mst[i] = s->ms[i] + 1e3 * (nl_time_now() - t0);
  nl_image_free(tex);
  nl_cheng_eval ev;
  nl_stats_ks_result ks;
  if ((j->st[i] = nl_cheng_evaluate(j->out[i], j->c, j->pat, &ev, &j->err[i])) ||
      (j->st[i] = nl_stats_ks2_test(j->out[i]->angle, j->out[i]->m, j->rp->opt->angle, j->rp->opt->m, &ks, &j->err[i])))
    return;
  s->ks[i] = ev.e_ks; s->con[i] = ev.e_con; s->p[i] = ev.p_ks; s->d[i] = ks.d;
  s->rp[i] = ev.r_pattern; s->ct[i] = ev.contrast;
}

/* nrep reproductions of rp's model m with the given swap into out[0..nrep-1]
 * and slots 0..nrep-1 of s: drawn in order on this thread, evaluated on the
 * run's threads. */
static void reproduce_all(nl_harness *r, const nl_study_cheng_repro *rp, const nl_cheng_model *m, const nl_cheng_config *c,
                          const nl_cheng_pattern *pat, double swap, gsl_rng *rng, nl_noise_grad2 **out, samples *s, int nrep)
{
  nl_error err;
  for (int i = 0; i < nrep; i++) {
    out[i] = nl_noise_grad2_alloc(rp->opt->m);
    double t0 = nl_time_now();
    if (nl_cheng_reproduce(rp->opt, m, swap, rng, out[i], &err)) nl_harness_die(r, 1, "%s", err.msg);
    s->ms[i] = 1e3 * (nl_time_now() - t0);
  }
  nl_status *st = nl_xcalloc((size_t)nrep, sizeof *st);
  nl_error *errs = nl_xmalloc((size_t)nrep * sizeof *errs);
  reps_job j = {rp, c, pat, out, s, st, errs};
  nl_parallel_for((size_t)nrep, nl_harness_threads(r), evaluate_item, &j);
  for (int i = 0; i < nrep; i++)   /* the first failure in order, as a serial loop met it */
    if (st[i]) nl_harness_die(r, 1, "%s", errs[i].msg);
  free(st);
  free(errs);
}

static double frac_below(const double *x, int n, double v) { int b = 0; for (int i = 0; i < n; i++) b += x[i] < v; return (double)b / n; }

static void summary_row(nl_table *t, const char *tex, const char *kind, const samples *s, int n,
                        const nl_study_cheng_repro *rp, size_t k)
{
  nl_table_append(t, "ssdddddddddddddddddd", tex, kind, (double)n, nl_study_mean(s->ks, n), nl_study_sd(s->ks, n),
                  nl_study_mean(s->con, n), nl_study_sd(s->con, n), nl_study_min(s->p, n), nl_study_mean(s->d, n), nl_study_sd(s->d, n),
                  frac_below(s->ks, n, rp->ev.e_ks), frac_below(s->con, n, rp->ev.e_con),
                  nl_study_mean(s->ms, n), nl_study_mean(s->mst, n), rp->seconds_opt, (double)k,
                  nl_study_mean(s->rp, n), nl_study_mean(s->ct, n), rp->ev.e_con_random, rp->ev.e_con_const);
}

/* Montage: the original texture and NSHOW reproductions, E_KS / E_Con under each. */
static void montage(nl_harness *r, const char *tex, const nl_cheng_config *c, nl_noise_grad2 *const *g, const samples *s,
                    const nl_study_cheng_repro *rp)
{
  nl_image *im[NSHOW + 1];
  char lab[NSHOW + 1][80], title[96], file[64];
  const char *labp[NSHOW + 1];
  for (int i = 0; i <= NSHOW; i++) {
    im[i] = nl_study_cheng_texture_image(i ? g[i - 1] : rp->opt, c, 192);
    if (i) snprintf(lab[i], sizeof lab[i], "r%d %.4f / %.0f", i, s->ks[i - 1], s->con[i - 1]);
    else snprintf(lab[i], sizeof lab[i], "orig %.4f / %.0f", rp->ev.e_ks, rp->ev.e_con);
    labp[i] = lab[i];
  }
  snprintf(title, sizeof title, "%s: E_KS / E_Con", tex);
  nl_image *m = nl_image_montage((const nl_image *const *)im, labp, NSHOW + 1, 3, title);
  snprintf(file, sizeof file, "textures_%s.png", tex);
  nl_harness_write_image(r, m, file);
  nl_image_free(m);
  for (int i = 0; i <= NSHOW; i++) nl_image_free(im[i]);
}

nl_table *nl_study_cheng_reps_alloc(void)
{
  return nl_table_alloc(sizeof c6_rep_cols / sizeof *c6_rep_cols, c6_rep_cols);
}

nl_table *nl_study_cheng_reps_summary_alloc(void)
{
  return nl_table_alloc(sizeof c6_sum_cols / sizeof *c6_sum_cols, c6_sum_cols);
}

/* Texture th from its original and pool (rp) on: mixture, reproductions,
 * rows, montage and CDF table. */
static void reproduce_from(const nl_study_cheng *st, nl_table *reps, nl_table *sum, const nl_study_cheng_thesis_gmm *th,
                           const nl_cheng_config *cp, const nl_cheng_pattern *pat, nl_study_cheng_repro *rp,
                           const nl_cheng_model_options *mo, int nrep, double swap)
{
  nl_harness *r = st->r;
  const nl_cheng_config c = *cp;
  samples *s = nl_xcalloc(1, sizeof *s);
  nl_cheng_model *m = nl_study_cheng_matched_model(r, rp->pool, th, mo);
  s->ks[0] = rp->ev.e_ks; s->con[0] = rp->ev.e_con; s->p[0] = rp->ev.p_ks;
  s->rp[0] = rp->ev.r_pattern; s->ct[0] = rp->ev.contrast;
  summary_row(sum, th->texture, "original", s, 1, rp, m->k);
  if (!m->gmm) {   /* degenerate model: reported, nothing to reproduce */
    nl_harness_text(r, "%s: no mixture (%s), no reproductions.\n", th->texture, m->msg);
  } else {
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, nl_seed_stream(nl_harness_seed(r), "c6.reproduce", 0));
    nl_noise_grad2 **g = nl_xmalloc((size_t)nrep * sizeof *g);
    const double swaps[2] = {swap, 0.0};   /* and without the swap, to separate the two effects */
    for (int w = 0; w < 2; w++) {
      reproduce_all(r, rp, m, &c, pat, swaps[w], rng, g, s, nrep);
      for (int i = 0; i < nrep; i++)
        nl_table_append(reps, "sdddddddd", th->texture, swaps[w], (double)i, s->ks[i], s->p[i], s->con[i], s->d[i], s->ms[i], s->mst[i]);
      char kind[48];
      snprintf(kind, sizeof kind, "reproduced_swap_%g", swaps[w]);
      summary_row(sum, th->texture, kind, s, nrep, rp, m->k);
      if (w == 0) {
        montage(r, th->texture, &c, g, s, rp);
        const nl_noise_grad2 *tabs[NSHOW + 1] = {rp->opt};
        const char *names[NSHOW + 1] = {"original", "r1", "r2", "r3", "r4", "r5", "r6", "r7", "r8"};
        for (int i = 0; i < NSHOW; i++) tabs[i + 1] = g[i];
        nl_table *cdf = nl_study_cheng_cdf_table(tabs, names, NSHOW + 1);
        char file[64];
        snprintf(file, sizeof file, "cdf_%s.tsv", th->texture);
        nl_harness_write_table(r, cdf, file);
        nl_table_free(cdf);
      }
      for (int i = 0; i < nrep; i++) nl_noise_grad2_free(g[i]);
    }
    free(g);
    gsl_rng_free(rng);
  }
  nl_cheng_model_free(m);
  free(s);
}

void nl_study_cheng_reproduce_case(const nl_study_cheng *st, nl_table *reps, nl_table *sum, const nl_study_cheng_thesis_gmm *th,
                                   const nl_cheng_pool_options *po, const nl_cheng_model_options *mo, int nrep,
                                   double swap)
{
  nl_cheng_config c;
  nl_study_cheng_repro rp;
  nl_cheng_pattern *pat = nl_study_cheng_repro_open(st, th, po, &c, &rp);
  reproduce_from(st, reps, sum, th, &c, pat, &rp, mo, nrep, swap);
  nl_study_cheng_repro_clear(&rp);
  nl_cheng_pattern_free(pat);
}

/* The n textures' originals (one multi-level run each, serial inside) as
 * items of one nl_parallel_for: each writes its own rp[i], st[i], err[i]. */
typedef struct {
  const nl_cheng_config *c;
  nl_cheng_pattern **pat;
  unsigned long seed;
  nl_study_cheng_repro *rp;
  nl_status *st;
  nl_error *err;
} originals_job;

static void original_item(void *ctx, size_t i, int thread)
{
  (void)thread;
  originals_job *j = ctx;
  j->st[i] = nl_study_cheng_repro_original(&j->c[i], j->pat[i], j->seed, &j->rp[i], &j->err[i]);
}

void nl_study_cheng_reproduce_cases(const nl_study_cheng *st, nl_table *reps, nl_table *sum, const nl_study_cheng_thesis_gmm *ths,
                                    int n, const nl_cheng_pool_options *po, const nl_cheng_model_options *mo, int nrep,
                                    double swap)
{
  nl_harness *r = st->r;
  nl_cheng_config *c = nl_xmalloc((size_t)n * sizeof *c);
  nl_cheng_pattern **pat = nl_xmalloc((size_t)n * sizeof *pat);
  nl_study_cheng_repro *rp = nl_xcalloc((size_t)n, sizeof *rp);
  nl_status *sts = nl_xcalloc((size_t)n, sizeof *sts);
  nl_error *errs = nl_xmalloc((size_t)n * sizeof *errs);
  for (int i = 0; i < n; i++) {   /* as nl_study_cheng_repro_open */
    pat[i] = nl_study_cheng_pattern(st, ths[i].pattern);
    c[i] = st->c;
    c[i].con = ths[i].con;
  }
  originals_job j = {c, pat, nl_harness_seed(r), rp, sts, errs};
  nl_parallel_for((size_t)n, nl_harness_threads(r), original_item, &j);
  for (int i = 0; i < n; i++) {
    nl_error err;
    if (sts[i]) nl_harness_die(r, 1, "%s: %s", ths[i].texture, errs[i].msg);
    if (nl_study_cheng_repro_pool(&rp[i], &c[i], pat[i], po, nl_harness_seed(r), &err))   /* Q runs on the run's threads */
      nl_harness_die(r, 1, "%s: %s", ths[i].texture, err.msg);
    reproduce_from(st, reps, sum, &ths[i], &c[i], pat[i], &rp[i], mo, nrep, swap);
    nl_study_cheng_repro_clear(&rp[i]);
    nl_cheng_pattern_free(pat[i]);
    nl_harness_progress(r, (i + 1.0) / n, ths[i].texture);
  }
  free(c); free(pat); free(rp); free(sts); free(errs);
}
