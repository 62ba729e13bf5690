/* C3's trend test (Cheng 2009 sec. 4.3.1, "lower starting frequency is
 * smoother"): Spearman's rho of roughness on f1 with a permutation p, for
 * the optimised tables and for random (unoptimised) tables, whose roughness
 * rises with f1 as well; the per-f1 table says what the optimisation adds. */
#include "c3.h"
#include "base/nl_parallel.h"
#include "stats/nl_stats.h"

#include <gsl/gsl_fit.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>

/* OLS slope of y on x */
static double slope(const double *x, const double *y, size_t n)
{
  double c0, c1, c00, c01, c11, ss;
  gsl_fit_linear(x, 1, y, 1, n, &c0, &c1, &c00, &c01, &c11, &ss);
  return c1;
}

nl_table *c3_trend_test_alloc(void)
{
  const char *cols[] = { "tables", "runs", "rho", "p_perm", "n_perm", "slope" };
  return nl_table_alloc(6, cols);
}

void c3_trend_test_add(nl_table *t, const char *tables, const double *f1, const double *rough,
                       size_t n, int nperm, unsigned long seed)
{
  double rho, p = nl_study_spearman_perm_p(f1, rough, n, nperm, seed, &rho);
  nl_table_append(t, "sddddd", tables, (double)n, rho, p, (double)nperm, slope(f1, rough, n));
}

typedef struct {
  const nl_cheng_config *c;
  const nl_cheng_pattern *pat;
  unsigned long seed;
  double *out;
} rough_job;

/* Item j: random table j's roughness (nl_cheng_evaluate), its own stream. */
static void rough_item(void *ctx, size_t j, int thread)
{
  (void)thread;
  rough_job *job = ctx;
  nl_noise_grad2 *g = nl_noise_grad2_alloc(job->c->m);
  nl_noise_grad2_seed(g, nl_seed_stream(job->seed, "c3.random_table", j));
  nl_cheng_eval ev;
  nl_error err;
  job->out[j] = nl_cheng_evaluate(g, job->c, job->pat, &ev, &err) ? NAN : ev.roughness;
  nl_noise_grad2_free(g);
}

void c3_random_roughness(const nl_cheng_config *c, const nl_cheng_pattern *pat, unsigned long seed,
                         int n, int threads, double *out)
{
  rough_job job = { c, pat, seed, out };
  nl_parallel_for((size_t)n, threads, rough_item, &job);
}

nl_table *c3_per_f1_alloc(void)
{
  const char *cols[] = { "f1",
                         "seeds",
                         "roughness",
                         "roughness_sd",
                         "n_random",
                         "roughness_random",
                         "roughness_random_sd",
                         "ratio",
                         "p_welch" };
  return nl_table_alloc(9, cols);
}

void c3_per_f1_add(nl_table *t, double f1, const double *opt, int k, const double *rnd, int n)
{
  double mo, so, mr, sr, p;
  nl_stats_mean_sd(opt, (size_t)k, NL_STATS_RUNNING, &mo, &so);
  nl_stats_mean_sd(rnd, (size_t)n, NL_STATS_RUNNING, &mr, &sr);
  nl_error err;
  if (nl_stats_welch_p(mo, so, (size_t)k, mr, sr, (size_t)n, &p, &err))
    p = mo == mr ? 1 : 0; /* no spread on either side: nothing to test */
  nl_table_append(t, "ddddddddd", f1, (double)k, mo, so, (double)n, mr, sr, mo / mr, p);
}

void c3_trend_tests(nl_table *t, const double *xo, const double *yo, size_t no, const double *xr,
                    const double *yr, size_t nr, int nperm, unsigned long seed)
{
  c3_trend_test_add(t, "optimised", xo, yo, no, nperm, nl_seed_stream(seed, "c3.trend", 0));
  c3_trend_test_add(t, "random", xr, yr, nr, nperm, nl_seed_stream(seed, "c3.trend", 1));
}
