/* synthesis.c - L3's syntheses over seeds (Lagae et al. 2010 sec. 5) and the
 * Gaussian self-match of a histogram representation, each on the run's
 * threads with every seed writing only its own slots. See synthesis.h. */
#include "synthesis.h"
#include "base/nl_parallel.h"
#include "stats/nl_stats.h"
#include "study/nl_study.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

typedef struct {
  const nl_byexample_params *p;
  const nl_byexample_synth_options *so;
  const nl_image *ex;
  int size;
  unsigned long seed0;
  double *ks, *per, *ce;
  nl_image *first;
  nl_status *st;
  nl_error *err;
} synth_job;

static void synth_item(void *ctx, size_t s, int thread)
{
  (void)thread;
  synth_job *j = ctx;
  nl_image *syn;
  unsigned long seed = nl_seed_replicate(j->seed0, (long)s);
  j->st[s] = nl_byexample_synthesize(j->p, j->size, j->size, seed, j->so, &syn, &j->err[s]);
  if (j->st[s]) return;
  j->ks[s] = nl_study_ks_channels(j->ex, syn, j->per + 3 * s);
  j->ce[s] = nl_byexample_correlation_error(j->ex, syn);
  if (s == 0)
    j->first = syn;
  else
    nl_image_free(syn);
}

nl_image *l3_synth_seeds(const nl_byexample_params *p, const nl_byexample_synth_options *so,
                         const nl_image *ex, int size, int K, unsigned long seed0, int threads,
                         double *ks, double *per, double *ce, nl_error *err)
{
  nl_status *st = nl_xcalloc((size_t)K, sizeof *st);
  nl_error *errs = nl_xmalloc((size_t)K * sizeof *errs);
  /* nl_byexample_sigma2 keeps its value in plain statics: filled before the threads start, so no
   * item writes them. */
  nl_byexample_sigma2(p->tile);
  synth_job j = { p, so, ex, size, seed0, ks, per, ce, NULL, st, errs };
  nl_parallel_for((size_t)K, threads, synth_item, &j);
  nl_image *first = j.first;
  for (int s = 0; s < K; s++)
    if (st[s]) {
      *err = errs[s];
      nl_image_free(first);
      first = NULL;
      break;
    }
  free(st);
  free(errs);
  return first;
}

static void gauss_self_match(size_t n, unsigned long seed, nl_byexample_hist_kind hk, double *ks,
                             double *tail)
{
  /* An exemplar channel of n N(0, 1) values and a fresh N(0, 1) noise of n
   * values matched to its histogram (sigma 1): what the representation does
   * to a channel that needs no change at all. */
  double *x = nl_xmalloc(n * sizeof *x);
  double *y = nl_xmalloc(n * sizeof *y);
  double q[NL_BYEXAMPLE_HIST_MAX];
  gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(g, nl_seed_stream(seed, "l3.gauss_exemplar", 0));
  for (size_t i = 0; i < n; i++) x[i] = gsl_ran_gaussian_ziggurat(g, 1.0);
  gsl_rng_set(g, nl_seed_stream(seed, "l3.gauss_noise", 0));
  for (size_t i = 0; i < n; i++) y[i] = gsl_ran_gaussian_ziggurat(g, 1.0);
  gsl_rng_free(g);
  nl_byexample_hist(x, n, hk, q);
  nl_byexample_match_kind(y, n, 1.0, hk, q, NL_SPLINE_STEFFEN);
  nl_stats_ks_result res;
  nl_stats_ks2_test(x, n, y, n, &res, NULL);
  *ks = res.d;
  *tail = nl_byexample_tail_mass(y, n, x, n, 2.5);
  free(x);
  free(y);
}

/* Item h K + s of l3_gauss_table: kind h, replicate s, into its own slots. */
typedef struct {
  size_t n;
  int K;
  unsigned long seed0;
  const nl_byexample_hist_kind *kinds;
  double *ks, *tail;
} gauss_job;

static void gauss_item(void *ctx, size_t i, int thread)
{
  (void)thread;
  gauss_job *j = ctx;
  int h = (int)(i / (size_t)j->K), s = (int)(i % (size_t)j->K);
  gauss_self_match(j->n, nl_seed_replicate(j->seed0, s), j->kinds[h], &j->ks[i], &j->tail[i]);
}

nl_table *l3_gauss_table(size_t n, int K, unsigned long seed0, int threads)
{
  static const char *cols[] = { "representation", "n",       "ks_mean",   "ks_sd",
                                "tail_mean",      "tail_sd", "tail_gauss" };
  nl_table *t = nl_table_alloc(7, cols);
  const nl_byexample_hist_kind kinds[2] = { NL_HIST_PAPER, NL_HIST_GAUSS };
  double *ks = nl_xmalloc(2 * (size_t)K * sizeof *ks);
  double *tail = nl_xmalloc(2 * (size_t)K * sizeof *tail);
  gauss_job j = { n, K, seed0, kinds, ks, tail };
  /* both kinds' replicates; rows in kind order */
  nl_parallel_for(2 * (size_t)K, threads, gauss_item, &j);
  for (int h = 0; h < 2; h++) {
    double km, ksd, tm, tsd;
    nl_stats_mean_sd(ks + (size_t)h * K, K, NL_STATS_SUMMED, &km, &ksd);
    nl_stats_mean_sd(tail + (size_t)h * K, K, NL_STATS_SUMMED, &tm, &tsd);
    nl_table_append(t, "siddddd", nl_byexample_hist_name(kinds[h]), (int)n, km, ksd, tm, tsd,
                    2 * gsl_cdf_ugaussian_Q(2.5));
  }
  free(ks);
  free(tail);
  return t;
}

double l3_max_abs_diff(const nl_image *a, const nl_image *b)
{
  size_t n = (size_t)a->width * a->height * (size_t)a->channels;
  double m = 0;
  /* A comparison, not fmax (a NaN is skipped by both): aarch64 gcc 12 stops
   * with an internal error vectorizing an fmax reduction. */
  for (size_t i = 0; i < n; i++) {
    double d = fabs(a->data[i] - b->data[i]);
    if (d > m) m = d;
  }
  return m;
}

void l3_write_spectra(nl_harness *r, const char *name, const nl_image *ex,
                      const nl_image *syn, const nl_image *nohist)
{
  const nl_image *src[3] = {ex, syn, nohist};
  const char *labels[3] = {"exemplar", "synthesis", "synthesis_nohist"};
  double *grey[3];
  for (int i = 0; i < 3; i++) {
    grey[i] = nl_xmalloc((size_t)ex->width * ex->height * sizeof *grey[i]);
    nl_byexample_luminance(src[i], grey[i]);
  }
  nl_table *t = nl_study_radial_table((const double *const *)grey, labels, 3, ex->width, 1);
  nl_harness_write_table(r, t, name);
  nl_table_free(t);
  for (int i = 0; i < 3; i++) free(grey[i]);
}
