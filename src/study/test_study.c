/* test_study.c - the shared study code against hand-made tables and naive
 * references: the grouped mean of a per-seed table, the between-condition
 * Welch rows of the Cheng experiments (p against an independent numeric
 * integral of Student's t density), the controllability tests of C1 and C7
 * (r from one raster against nl_cheng_evaluate, the Monte-Carlo and t
 * p-values against closed forms), and the sampling lines of A3 and A4
 * against the sum of octaves evaluated point by point. */
#include "study/nl_study.h"
#include "study/nl_study_cheng.h"
#include "study/nl_study_lines.h"
#include "nl_test.h"

#include <math.h>
#include <stdlib.h>

NL_TEST(mean_where_groups_rows_and_counts_rejections)
{
  const char *cols[] = { "case", "E", "p" };
  nl_table *t = nl_table_alloc(3, cols);
  nl_table_append(t, "sdd", "a", 1.0, 0.01);
  nl_table_append(t, "sdd", "b", 10.0, 0.50);
  nl_table_append(t, "sdd", "a", 2.0, 0.20);
  nl_table_append(t, "sdd", "a", 6.0, 0.04);
  int below = -1;
  NL_CHECK(nl_study_mean_where(t, "case", "a", "E", "p", 0.05, &below) == 3.0);
  NL_CHECK(below == 2);   /* p = 0.01 and 0.04 are below 0.05; 0.20 is not */
  NL_CHECK(nl_study_mean_where(t, "case", "b", "E", NULL, 0.05, NULL) == 10.0);
  NL_CHECK(isnan(nl_study_mean_where(t, "case", "none", "E", "p", 0.05, &below)));
  NL_CHECK(below == 0);
  nl_table_free(t);
}

/* A summary table with the columns nl_study_cheng_welch_add reads. */
static nl_table *summary(void)
{
  const char *cols[] = { "case", "seeds", "E", "E_sd" };
  nl_table *s = nl_table_alloc(4, cols);
  nl_table_append(s, "sddd", "x", 10.0, 1.0, 1.0);
  nl_table_append(s, "sddd", "y", 8.0, 2.0, 2.0);
  nl_table_append(s, "sddd", "fixed", 4.0, 3.0, 0.0);
  nl_table_append(s, "sddd", "same", 4.0, 3.0, 0.0);
  nl_table_append(s, "sddd", "other", 4.0, 5.0, 0.0);
  return s;
}

NL_TEST(welch_rows_give_scipy_p_and_the_relative_difference)
{
  nl_table *s = summary(), *w = nl_study_cheng_welch_alloc();
  /* t = -1.2910, Welch-Satterthwaite df = 9.7759: 2 P(T > |t|) = 0.226398345773
   * by Simpson's rule on Student's t density from |t| to 400 (2e5 panels, in
   * Python's math module: independent of GSL); scipy's
   * ttest_ind_from_stats(1, 1, 10, 2, 2, 8, equal_var=False) is the same test. */
  double p = nl_study_cheng_welch_add(w, s, 0, 1, "E", "g", "x", "y");
  NL_CHECK_NEAR(p, 0.226398345773, 1e-9);
  NL_CHECK(nl_table_value(w, 0, "p_welch") == p);
  NL_CHECK_NEAR(nl_table_value(w, 0, "diff_pct"), 100 * (1.0 - 2.0) / 2.0, 1e-12);
  NL_CHECK(nl_table_value(w, 0, "mean_a") == 1.0 && nl_table_value(w, 0, "sd_b") == 2.0);
  /* Both sds 0: nothing to test, the values decide (equal: 1, else 0). */
  NL_CHECK(nl_study_cheng_welch_add(w, s, 2, 3, "E", "g", "fixed", "same") == 1.0);
  NL_CHECK(nl_study_cheng_welch_add(w, s, 2, 4, "E", "g", "fixed", "other") == 0.0);
  NL_CHECK(w->nrows == 3);
  nl_table_free(w);
  nl_table_free(s);
}

NL_TEST(pattern_r_is_the_evaluations_r_and_p_values_match_closed_forms)
{
  nl_image *im = nl_study_cheng_shape("star", 128);
  nl_cheng_pattern *pat;
  nl_error err;
  NL_CHECK(nl_study_cheng_pattern_from_image(im, 32, &pat, &err) == NL_OK);
  nl_cheng_config c = nl_cheng_config_default();
  nl_noise_grad2 *g = nl_noise_grad2_alloc(c.m);
  nl_noise_grad2_seed(g, 11);
  nl_cheng_eval ev;
  NL_CHECK(nl_cheng_evaluate(g, &c, pat, &ev, &err) == NL_OK);
  /* one raster at the cells' centres against the kernel point by point */
  NL_CHECK_NEAR(nl_study_cheng_pattern_r(g, &c, pat), ev.r_pattern, 1e-12);
  double null[4];
  nl_study_cheng_random_r(&c, pat, 5, 4, 2, null);
  for (int j = 0; j < 4; j++) NL_CHECK(fabs(null[j]) < 1);
  nl_study_cheng_seams sm;
  nl_study_cheng_seams_measure(g, &c, &sm);
  NL_CHECK(sm.quarter > 0 && sm.other > 0 && sm.border > 0);
  for (int l = 0; l < 4; l++) NL_CHECK(sm.octave_quarter[l] > 0);   /* F = 4 */
  NL_CHECK(fabs(sm.outward) <= 1);
  /* (1 + #{null >= obs}) / (n + 1): 2 of 4 at or above 0.5 */
  const double d[4] = { 0.1, 0.5, 0.7, 0.2 };
  NL_CHECK(nl_study_mc_p_greater(d, 4, 0.5) == 3.0 / 5.0);
  NL_CHECK(nl_study_mc_p_greater(d, 4, 0.9) == 1.0 / 5.0);
  /* Student's t with 2 df has F(t) = 1/2 + t / (2 sqrt(2 + t^2)): for
   * x = (1, 2, 3.5) against mu = 4, t = -2.52357, F = 0.0638216278550 (Python,
   * math module alone) */
  const double x[3] = { 1, 2, 3.5 }, flat[3] = { 2, 2, 2 };
  NL_CHECK_NEAR(nl_study_t_below_p(x, 3, 4), 0.0638216278550, 1e-10);
  NL_CHECK(nl_study_t_below_p(flat, 3, 4) == 0.0 && nl_study_t_below_p(flat, 3, 1) == 1.0);
  nl_noise_grad2_free(g);
  nl_cheng_pattern_free(pat);
  nl_image_free(im);
}

NL_TEST(line_samples_are_the_octave_sum_point_by_point)
{
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 7);
  nl_noise_octaves o = nl_noise_octaves_fbm(4, 0.5, 2.0);
  const double phi = (1 + sqrt(5)) / 2;
  /* A negative origin, and an oblique direction that crosses lattice planes. */
  nl_study_line l = { { -3.25, 17.7, -34.2 }, { 1, 1 / phi, 1 / (phi * phi) } };
  size_t n;
  double *x = nl_study_line_sample(&p, &o, &l, 12.5, 8.0, &n);
  NL_CHECK(n == 100);   /* llround(12.5 * 8) */
  for (size_t k = 0; k < n; k++) {
    double t = (double)k / 8.0, ref = 0;
    for (int i = 0; i < o.n; i++)
      ref += o.amp[i] * nl_noise_perm3_eval(&p, o.freq[i] * (l.origin[0] + t * l.dir[0]),
                                            o.freq[i] * (l.origin[1] + t * l.dir[1]),
                                            o.freq[i] * (l.origin[2] + t * l.dir[2]));
    NL_CHECK(x[k] == ref);
  }
  free(x);
}

int main(void) { return nl_test_run(); }
