/* seeding.c - Q1: the count law under the paper's 16-bit cube seeds and
 * under a full hash, and the verdict on the paper's count rule. */
#include "seeding.h"

#include "study/nl_study.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>

void q1_full_hash_histogram(const nl_cellular *c, unsigned long seed, int side, double *hist)
{
  unsigned long long base = nl_seed_stream(seed, "q1.full_hash", 0);
  for (int m = 0; m <= c->M; m++) hist[m] = 0.0;
  for (long i = 0; i < side; i++)
    for (long j = 0; j < side; j++)
      for (long k = 0; k < side; k++) {
        unsigned long long h = nl_seed_mix(base ^ (unsigned long long)i);
        h = nl_seed_mix(h ^ (unsigned long long)j);
        h = nl_seed_mix(h ^ (unsigned long long)k);
        hist[nl_cellular_count_from_r(c, (double)(h >> 11) * 0x1.0p-53)] += 1.0;
      }
}

void q1_fixed_set_law(const nl_cellular *c, double *q)
{
  double *xyz = nl_xmalloc(3 * (size_t)(c->M + 1) * sizeof *xyz);
  for (int m = 0; m <= c->M; m++) q[m] = 0.0;
  for (long i = 0; i < NL_CELLULAR_PERM; i++)
    q[nl_cellular_cube(c, i, 0, 0, xyz)] += 1.0 / NL_CELLULAR_PERM;
  free(xyz);
}

/* Chi-square of the histogram h (counts) against Poisson; one row of t. */
static void law_row(nl_harness *r, const nl_cellular *c, nl_table *t, const char *rule,
                    const char *seeding, const double *h)
{
  nl_stats_chisq_result cs;
  nl_error err;
  double mean;
  double var;
  double n = 0;
  for (int m = 0; m <= c->M; m++) n += h[m];
  if (nl_cellular_count_chisq(c, h, &cs, &err)) nl_harness_die(r, 1, "%s", err.msg);
  nl_cellular_count_moments(h, c->M, &mean, &var);
  nl_table_append(t, "ssdddid", rule, seeding, n, mean, cs.chi2, (int)cs.df, cs.p);
}

static nl_cellular *make(nl_harness *r, const q1 *q, nl_cellular_count_rule rule,
                         unsigned long seed)
{
  nl_cellular *c;
  nl_error err;
  if (nl_cellular_alloc(q->lambda, q->M, rule, seed, &c, &err)) nl_harness_die(r, 2, "%s", err.msg);
  return c;
}

void q1_seeding(q1 *q, unsigned long seed0)
{
  nl_harness *r = q->r;
  double cubes = (double)q->side * q->side * q->side;
  double h[NL_CELLULAR_MAX_M + 1];
  double pooled[NL_CELLULAR_MAX_M + 1] = { 0 };
  const char *lcols[] = { "rule", "seeding", "cubes", "mean_count", "chi2", "df", "p" };
  nl_table *law = nl_table_alloc(7, lcols);
  nl_cellular *c = make(r, q, NL_COUNT_INVERSE_CDF, seed0);
  for (int rule = 0; rule < NRULE; rule++) {
    for (int m = 0; m <= q->M; m++) h[m] = q->hist[rule][m] * cubes * q->seeds;
    law_row(r, c, law, nl_cellular_count_rule_name((nl_cellular_count_rule)rule),
            "16-bit cube seed", h);
  }
  /* The check: inverse-CDF counts with r from a full hash, per seed. */
  const char *hcols[] = { "seed", "mean_count", "chi2", "chi2_p", "df" };
  nl_table *hc = nl_table_alloc(5, hcols);
  int rejects = 0;
  for (int k = 0; k < q->seeds; k++) {
    unsigned long seed = nl_seed_replicate(seed0, k);
    nl_stats_chisq_result cs;
    nl_error err;
    double mean;
    double var;
    q1_full_hash_histogram(c, seed, q->side, h);
    if (nl_cellular_count_chisq(c, h, &cs, &err)) nl_harness_die(r, 1, "%s", err.msg);
    nl_cellular_count_moments(h, q->M, &mean, &var);
    nl_table_append(hc, "idddi", (int)seed, mean, cs.chi2, cs.p, (int)cs.df);
    rejects += cs.p < 0.01;
    for (int m = 0; m <= q->M; m++) pooled[m] += h[m];
  }
  law_row(r, c, law, "inverse-cdf", "full hash", pooled);
  /* The negative control of the verdict below: no count law at all, every
   * cube holding the mean number of points, lambda rounded (a jittered
   * grid), as many cubes as the verdict's rows pool. */
  for (int m = 0; m <= q->M; m++) h[m] = 0;
  h[(int)fmin(q->M, floor(q->lambda + 0.5))] = cubes * q->seeds;
  law_row(r, c, law, "fixed count", "none", h);
  /* The fixed set of 2^16 first draws, and the chi-square its bias adds to
   * one table of side^3 cubes (Pearson's statistic of the expected counts:
   * the non-centrality). */
  double fq[NL_CELLULAR_MAX_M + 1];
  q1_fixed_set_law(c, fq);
  for (int m = 0; m <= q->M; m++) h[m] = fq[m] * NL_CELLULAR_PERM;
  const char *fcols[] = { "cube_seeds", "mean_count",      "chi2",       "df",
                          "p",          "cubes_per_table", "chi2_added", "df_per_table" };
  nl_table *fs = nl_table_alloc(8, fcols);
  nl_stats_chisq_result all;
  nl_stats_chisq_result per;
  nl_error err;
  double mean;
  double var;
  if (nl_cellular_count_chisq(c, h, &all, &err)) nl_harness_die(r, 1, "%s", err.msg);
  nl_cellular_count_moments(h, q->M, &mean, &var);
  for (int m = 0; m <= q->M; m++) h[m] = fq[m] * cubes;
  if (nl_cellular_count_chisq(c, h, &per, &err)) nl_harness_die(r, 1, "%s", err.msg);
  nl_table_append(fs, "iddidddi", NL_CELLULAR_PERM, mean, all.chi2, (int)all.df, all.p, cubes,
                  per.chi2, (int)per.df);
  nl_harness_write_table(r, law, "count_law.tsv");
  nl_harness_write_table(r, hc, "hash_check.tsv");
  nl_harness_write_table(r, fs, "fixed_set.tsv");
  /* The headline: the paper's rule with the paper's seeds, as written. */
  nl_harness_verdict_p(r, "count_law.tsv", law, 0, "count law of the paper's rule",
                       "counts Poisson(lambda) (the m whose p(m) is closest to r)", "chi2", "p",
                       "fit 0.01 0.001", "independent",
                       "Pearson chi-square of every seed's cubes, tail pooled");
  nl_harness_verdict_control(r, "every cube with lambda points, rounded (no count law)",
                             "count_law.tsv", law, 4);
  q1_report_seeding(q, law, hc, fs, rejects);
  nl_table_free(law);
  nl_table_free(hc);
  nl_table_free(fs);
  nl_cellular_free(c);
}
