/* Solution pools of Cheng sec. 3.5.1-3.5.2: E_R of eq. 3.16-3.18 re-annealed
 * over the low-frequency entries from Q random starts, N cold-tail states
 * kept per run (rules in nl_cheng_repro.h). Runs go to nl_parallel_for
 * (base/nl_parallel.h), but each run's result depends only on its stream
 * nl_seed_stream(seed, "cheng.pool.run", q) and lands in slot q, so the pool is the same for any number of threads. */
#include "cheng/nl_cheng_internal.h"
#include "base/nl_parallel.h"

#include <stdlib.h>
#include <string.h>

void nl_cheng_pool_options_default(nl_cheng_pool_options *o)
{
  *o = (nl_cheng_pool_options){.low_levels = 1, .runs = 100, .keep = 100, .epsilon = 10.0,
                               .threads = 2};
}

void nl_cheng_set_reproduction(nl_cheng_problem *p, int low_levels)
{
  nl_cheng_set_level(p, p->F);   /* E_Con over all F octaves (eq. 3.17); moves update all */
  p->nvars = p->nsample = 0;
  for (size_t k = 0; k < p->m; k++) {
    if (p->first_level[k] >= 1 && p->first_level[k] <= low_levels) p->vars[p->nvars++] = k;
    p->in_sample[k] = 1;         /* eq. 3.16: {X_opt high, X_rep low} = every entry */
    p->sample[p->nsample++] = k;
  }
  nl_cheng__stat_reset(&p->st, p->g->angle, p->m);
  p->e_stat = nl_cheng__stat_value(&p->st);
  nl_cheng_resum(p);
}

size_t *nl_cheng_low_entries(const nl_noise_grad2 *table, const nl_cheng_config *c,
                             const nl_cheng_pattern *pat, int low_levels, size_t *nlow,
                             nl_error *err)
{
  nl_noise_grad2 *g = nl_noise_grad2_alloc(table->m);
  nl_noise_grad2_copy(g, table);
  nl_cheng_problem *p = nl_cheng_problem_alloc(c, pat, g, err);
  size_t *low = NULL;
  if (p) {
    nl_cheng_set_reproduction(p, low_levels);
    const size_t *v = nl_cheng_vars(p, nlow);
    low = nl_xmalloc((*nlow ? *nlow : 1) * sizeof *low);
    memcpy(low, v, *nlow * sizeof *low);
  }
  nl_cheng_problem_free(p);
  nl_noise_grad2_free(g);
  return low;
}

typedef struct {
  const nl_noise_grad2 *opt;
  const nl_cheng_config *c;
  const nl_cheng_pattern *pat;
  const nl_cheng_pool_options *o;
  unsigned long seed;
  size_t nlow, keep;
  double *theta, *e;     /* Q x N x nlow, Q x N: slot q holds run q's tail */
  double *best, *start, *seconds;
  /* Per thread t of nl_parallel_for: a problem over its own table copy and
   * a generator, re-seeded by every run (scratch, not state across runs). */
  nl_cheng_problem **p;
  nl_noise_grad2 **g;
  gsl_rng **rng;
} pool_job;

/* The cold tail: N sweeps of n_low Metropolis moves at the final temperature
 * T, step pi/100 (nl_cheng_anneal's floor); the state after each sweep is a
 * solution. Returns the lowest E_R seen. */
static double cold_tail(nl_cheng_problem *p, gsl_rng *rng, double T, size_t keep, double *theta,
                        double *e)
{
  size_t nv;
  const size_t *vars = nl_cheng_vars(p, &nv);
  double lowest = p->e;
  for (size_t s = 0; s < keep; s++) {
    for (size_t m = 0; m < nv; m++) {
      size_t k = vars[gsl_rng_uniform_int(rng, nv)];
      double e0 = p->e;
      double th = nl_wrap_angle(p->g->angle[k] + 0.01 * NL_PI * (2 * gsl_rng_uniform(rng) - 1));
      double de = nl_cheng_move(p, k, th) - e0;
      if (!(de <= 0 || gsl_rng_uniform(rng) < exp(-de / T))) nl_cheng_undo(p);
    }
    nl_cheng_resum(p);
    for (size_t j = 0; j < nv; j++) theta[s * nv + j] = p->g->angle[vars[j]];
    e[s] = p->e;
    if (p->e < lowest) lowest = p->e;
  }
  return lowest;
}

/* Run q: random low entries from stream (seed, "cheng.pool.run", q), anneal
 * E_R, cold tail. The stream depends on q only, not on the thread. */
static void pool_run(pool_job *j, nl_cheng_problem *p, nl_noise_grad2 *g, gsl_rng *rng, int q)
{
  double t0 = nl_time_now();
  gsl_rng_set(rng, nl_seed_stream(j->seed, "cheng.pool.run", (unsigned long)q));
  nl_noise_grad2_copy(g, j->opt);
  nl_cheng_set_reproduction(p, j->o->low_levels);
  size_t nv;
  const size_t *vars = nl_cheng_vars(p, &nv);
  for (size_t v = 0; v < nv; v++)
    nl_noise_grad2_set_angle(g, vars[v], nl_wrap_angle(NL_TWO_PI * gsl_rng_uniform(rng)));
  nl_cheng_set_reproduction(p, j->o->low_levels);   /* recompute from the new start */
  j->start[q] = p->e;
  nl_cheng_level_stats st;
  nl_cheng_anneal(p, rng, &st);
  size_t slot = (size_t)q * j->keep;
  double tail = cold_tail(p, rng, st.t_end, j->keep, j->theta + slot * j->nlow, j->e + slot);
  j->best[q] = fmin(st.e_best, tail);
  j->seconds[q] = nl_time_now() - t0;
}

static void pool_item(void *ctx, size_t q, int t)
{
  pool_job *j = ctx;
  pool_run(j, j->p[t], j->g[t], j->rng[t], (int)q);
}

static nl_status check_pool_options(const nl_cheng_pool_options *o, const nl_cheng_config *c,
                                    nl_error *err)
{
  if (o->low_levels < 1 || o->low_levels >= c->octaves)
    return nl_fail(err, NL_EINVAL, "low_levels must be in 1..%d (some levels must stay high)", c->octaves - 1);
  if (o->runs < 1 || o->keep < 1) return nl_fail(err, NL_EINVAL, "runs (Q) and keep (N) must be >= 1");
  if (!(o->epsilon >= 0)) return nl_fail(err, NL_EINVAL, "epsilon must be >= 0");
  if (o->threads < 1 || o->threads > 64) return nl_fail(err, NL_EINVAL, "threads must be in 1..64");
  return NL_OK;
}

/* Keeps, run by run, the tail states within epsilon of the run's best. */
static void pool_compact(nl_cheng_pool *pool, const pool_job *j)
{
  size_t n = 0, nl = j->nlow;
  for (int q = 0; q < pool->runs; q++)
    for (size_t s = 0; s < j->keep; s++) {
      size_t from = (size_t)q * j->keep + s;
      if (!(j->e[from] <= j->best[q] + j->o->epsilon)) { pool->excluded++; continue; }
      memmove(pool->theta + n * nl, j->theta + from * nl, nl * sizeof *pool->theta);
      pool->e[n] = j->e[from];
      pool->run[n++] = q;
    }
  pool->n = n;
  size_t keep = n ? n : 1;
  pool->theta = nl_xrealloc(pool->theta, keep * nl * sizeof *pool->theta);
  pool->e = nl_xrealloc(pool->e, keep * sizeof *pool->e);
  pool->run = nl_xrealloc(pool->run, keep * sizeof *pool->run);
}

nl_status nl_cheng_pool_collect(const nl_noise_grad2 *opt, const nl_cheng_config *c,
                                const nl_cheng_pattern *pat, const nl_cheng_pool_options *o,
                                unsigned long seed, nl_cheng_pool **out, nl_error *err)
{
  *out = NULL;
  if (check_pool_options(o, c, err)) return NL_EINVAL;
  size_t nlow;
  size_t *low = nl_cheng_low_entries(opt, c, pat, o->low_levels, &nlow, err);
  if (!low) return NL_EINVAL;
  if (nlow == 0) { free(low); return nl_fail(err, NL_EINVAL, "no low-frequency entries"); }
  size_t total = (size_t)o->runs * (size_t)o->keep;
  nl_cheng_pool *pool = nl_xcalloc(1, sizeof *pool);
  *pool = (nl_cheng_pool){.nlow = nlow, .low = low, .runs = o->runs,
                          .theta = nl_xmalloc(total * nlow * sizeof(double)),
                          .e = nl_xmalloc(total * sizeof(double)), .run = nl_xmalloc(total * sizeof(int)),
                          .run_best = nl_xmalloc((size_t)o->runs * sizeof(double)),
                          .run_start = nl_xmalloc((size_t)o->runs * sizeof(double)),
                          .run_seconds = nl_xmalloc((size_t)o->runs * sizeof(double))};
  pool_job j = {.opt = opt, .c = c, .pat = pat, .o = o, .seed = seed, .nlow = nlow,
                .keep = (size_t)o->keep, .theta = pool->theta, .e = pool->e,
                .best = pool->run_best, .start = pool->run_start, .seconds = pool->run_seconds};
  int nt = nl_parallel_threads((size_t)o->runs, o->threads);
  nl_cheng_problem *tp[NL_PARALLEL_MAX] = {0};
  nl_noise_grad2 *tg[NL_PARALLEL_MAX];
  gsl_rng *tr[NL_PARALLEL_MAX];
  nl_status st = NL_OK;
  for (int t = 0; t < nt; t++) {
    tg[t] = nl_noise_grad2_alloc(opt->m);
    nl_noise_grad2_copy(tg[t], opt);
    tr[t] = gsl_rng_alloc(gsl_rng_mt19937);
    if (!st && !(tp[t] = nl_cheng_problem_alloc(c, pat, tg[t], err))) st = NL_EINVAL;
  }
  j.p = tp; j.g = tg; j.rng = tr;
  if (!st) nl_parallel_for((size_t)o->runs, nt, pool_item, &j);
  for (int t = 0; t < nt; t++) { nl_cheng_problem_free(tp[t]); nl_noise_grad2_free(tg[t]); gsl_rng_free(tr[t]); }
  if (st) { nl_cheng_pool_free(pool); return st; }
  pool_compact(pool, &j);   /* in place: slot order is run order, compaction only moves left */
  nl_noise_grad2 *g = nl_noise_grad2_alloc(opt->m);
  nl_noise_grad2_copy(g, opt);
  nl_cheng_problem *p = nl_cheng_problem_alloc(c, pat, g, err);
  nl_cheng_set_reproduction(p, o->low_levels);
  pool->e_opt = nl_cheng_energy(p, NULL, NULL);
  nl_cheng_problem_free(p);
  nl_noise_grad2_free(g);
  *out = pool;
  return NL_OK;
}

void nl_cheng_pool_free(nl_cheng_pool *p)
{
  if (!p) return;
  free(p->low); free(p->theta); free(p->e); free(p->run);
  free(p->run_best); free(p->run_start); free(p->run_seconds);
  free(p);
}

size_t nl_cheng_pool_bytes(const nl_cheng_pool *p)
{
  return p->n * (p->nlow * sizeof(double) + sizeof(double) + sizeof(int)) +
         p->nlow * sizeof(size_t) + 3 * (size_t)p->runs * sizeof(double);
}
