/* c3.h - C3's report prose (report.c), trend test (trend.c) and
 * first-seed tables (tables.c).
 *
 * Cheng 2009 sec. 4.3.1 (Fig 4.7) optimises the controlled fractal sum at
 * starting frequencies f1 = 2, 4, 6, 8 (eq. 3.10: f_l = f1 2^(l-1)) and says
 * "the appearance of lower starting frequency is smoother". C3's summary
 * holds one row per f1, in the order of the f1s given here.
 */
#ifndef C3_H
#define C3_H

#include "study/nl_study_cheng.h"

/* The thesis's claim, our setting on pattern `pattern`, the figure and the
 * summary table. */
void c3_intro_text(nl_harness *r, const nl_study_cheng *s, const char *pattern, const double *f1s,
                   int n, const nl_table *sum);
/* Roughness and E_Con per f1 (summary rows 0..n-1): whether roughness rises
 * strictly with f1 (lower f1 smoother) and where E_Con is lowest. */
void c3_result_text(nl_harness *r, const nl_table *sum, const double *f1s, int n);

/* Columns tables, runs, rho, p_perm, n_perm, slope (OLS of roughness on
 * f1); _add: one row from n runs' (f1, roughness). */
nl_table *c3_trend_test_alloc(void);
void c3_trend_test_add(nl_table *t, const char *tables, const double *f1, const double *rough,
                       size_t n, int nperm, unsigned long seed);
/* Both rows: the optimised runs' no (f1, roughness) pairs (xo, yo) and the
 * random tables' nr (xr, yr), each permuted from its own stream "c3.trend"
 * of the run's seed. */
void c3_trend_tests(nl_table *t, const double *xo, const double *yo, size_t no, const double *xr,
                    const double *yr, size_t nr, int nperm, unsigned long seed);
/* Roughness (nl_cheng_evaluate) of n random tables under config c, table j
 * seeded nl_seed_stream(seed, "c3.random_table", j), on `threads`. */
void c3_random_roughness(const nl_cheng_config *c, const nl_cheng_pattern *pat, unsigned long seed,
                         int n, int threads, double *out);
/* Per f1: f1, seeds, roughness, roughness_sd (optimised, over the seeds),
 * n_random, roughness_random, roughness_random_sd (random tables), ratio
 * (optimised over random) and p_welch (two-sided Welch, the two means). */
nl_table *c3_per_f1_alloc(void);
void c3_per_f1_add(nl_table *t, double f1, const double *opt, int k, const double *rnd, int n);
/* The trend tests (optimised and random tables, trend_test.tsv), the per-f1
 * comparison (trend.tsv) and the verdict: what the optimisation adds to the
 * trend every table has. */
void c3_trend_text(nl_harness *r, const nl_table *tt, const nl_table *per_f1);

/* "We can even control the lower frequency appearance": the lowest f1's
 * control table row 0 (r against random tables, E_Con against the flat
 * image) and its negative controls (bl rows 0: the pattern shuffled, 1: the
 * start tables), two verdicts. */
void c3_low_text(nl_harness *r, const nl_table *ctl, const nl_table *bl);

/* tables.c. Writes tables.tsv: the n first-seed tables, one per f1s[i]
 * (tests/oracle_cheng.c reads them). */
void c3_tables_write(nl_harness *r, const double *f1s, nl_noise_grad2 *const *firsts, int n);
/* Appends the seams rows (f1, "optimised") of the n tables firsts[i] under
 * cs[i] on pat, then frees the tables. */
void c3_seams_add(nl_table *seams, const double *f1s, const nl_cheng_config *cs,
                  nl_noise_grad2 **firsts, int n, const nl_cheng_pattern *pat);
/* The control row (ctl) and negative controls (bl) of the lowest f1's runs
 * evs (config c, its k tables `tables`) against nrand random tables, seeded
 * from the stream "c3.random_r". */
void c3_low_control(const nl_study_cheng *s, nl_table *ctl, nl_table *bl, const nl_cheng_config *c,
                    const nl_cheng_pattern *pat, const nl_cheng_eval *evs,
                    nl_noise_grad2 *const *tables, int nrand, double f1);

#endif
