/* C2 - Cheng 2009 Fig 4.5-4.6 (sec. 4.2): the same patterns optimised with the
 * KS term, the chi-square term (500 bins) and, added here, the Kuiper term;
 * CDF of the optimised angles against the ideal line, histograms, and every
 * statistic with its p-value over seeds. */
#include "study/nl_study_cheng.h"
#include "harness/nl_harness.h"
#include "stats/nl_stats.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define NPAT 2

#define NOBJ 3

int main(int argc, char **argv)
{
  nl_study_cheng s;
  nl_study_cheng_open(&s, "c2_ks_vs_chisq", "C2 - KS term vs chi-square term (Fig 4.5, 4.6)", &argc, argv);
  nl_study_cheng_ready(&s);
  nl_harness *r = s.r;
  const nl_cheng_config base = s.c;
  int grid = s.grid, k = nl_harness_seeds(r);
  const char *pats[NPAT] = {"flower", "x"};
  const nl_cheng_stat objs[NOBJ] = {NL_CHENG_STAT_KS, NL_CHENG_STAT_CHISQ, NL_CHENG_STAT_KUIPER};
  const char *onames[NOBJ] = {"ks", "chisq", "kuiper"};
  const char *labels[] = {"pattern", "objective"};
  nl_table *sum = nl_study_cheng_summary_alloc(2, labels);
  int single[NPAT] = {0};   /* bins holding exactly one angle, chi-square objective, first seed */
  /* Every (pattern, objective) case over the seeds as one set of independent
   * runs on the run's threads (nl_study_cheng_runs); rows in case order. */
  nl_cheng_pattern *pat[NPAT];
  const nl_cheng_pattern *pp[NPAT * NOBJ];
  nl_cheng_config cs[NPAT * NOBJ];
  nl_noise_grad2 *firsts[NPAT * NOBJ];
  for (int q = 0; q < NPAT * NOBJ; q++) {
    if (q % NOBJ == 0) pat[q / NOBJ] = nl_study_cheng_pattern(&s, pats[q / NOBJ]);
    cs[q] = base;
    cs[q].stat = objs[q % NOBJ];
    pp[q] = pat[q / NOBJ];
  }
  nl_cheng_eval *evs = nl_study_cheng_runs(&s, NPAT * NOBJ, cs, pp, firsts);
  for (int q = 0; q < NPAT * NOBJ; q++) {
    const char *lab[2] = {pats[q / NOBJ], onames[q % NOBJ]};
    nl_study_cheng_rows_add(&s, sum, 2, lab, evs + (size_t)q * k);
  }
  free(evs);
  for (int i = 0; i < NPAT; i++) {
    nl_noise_grad2 **first = firsts + NOBJ * i;
    nl_harness_progress(r, (i + 1.0) / NPAT, pats[i]);
    char file[64];
    nl_table *cdf = nl_study_cheng_cdf_table((const nl_noise_grad2 *const *)first, onames, NOBJ);
    snprintf(file, sizeof file, "cdf_%s.tsv", pats[i]);
    nl_harness_write_table(r, cdf, file);
    nl_table *hist = nl_study_cheng_hist_table((const nl_noise_grad2 *const *)first, onames, NOBJ, base.chisq_bins);
    for (size_t b = 0; b < hist->nrows; b++) single[i] += nl_table_value(hist, b, "chisq") == 1.0;
    snprintf(file, sizeof file, "hist_%s.tsv", pats[i]);
    nl_harness_write_table(r, hist, file);
    nl_image *panels[NOBJ + 1];
    const char *plab[NOBJ + 1] = {"pattern", "KS term", "chi-square term", "Kuiper term"};
    panels[0] = nl_study_cheng_pattern_panel(pat[i], 192);
    for (int o = 0; o < NOBJ; o++) panels[o + 1] = nl_study_cheng_value_image(first[o], &base, 192);
    snprintf(file, sizeof file, "noise_%s.png", pats[i]);
    nl_study_cheng_montage(r, panels, plab, NOBJ + 1, NOBJ + 1, pats[i], file);
    for (int o = 0; o < NOBJ; o++) nl_noise_grad2_free(first[o]);
    nl_table_free(cdf);
    nl_table_free(hist);
    nl_cheng_pattern_free(pat[i]);
  }
  nl_harness_write_table(r, sum, "summary.tsv");

  nl_harness_text(r, "**Thesis:** two patterns optimised with the KS term (eq. 3.7) and with the "
                     "chi-square term (eq. 3.4, 512 angles in 500 bins): the KS CDF lies closer to the "
                     "ideal line, the chi-square error is lower under the chi-square objective, and E_Con "
                     "is close in both (numbers not printed). **Ours:** patterns %s and %s on a %d x %d "
                     "control grid, thesis setting (M = 512, F = 4, f1 = %g, a1 = %g, w1 = %g, w2 = %g), "
                     "%d seeds each; the chi-square term enters E as Cramer's V = sqrt(chi2 / (n (K - 1))) "
                     "so the thesis weights keep their balance (nl_cheng.h). Kuiper's V is a third "
                     "objective. Statistics are over all 512 angles.\n",
                 pats[0], pats[1], grid, grid, base.f1, base.a1, base.w1, base.w2, k);
  nl_harness_report_columns(r, sum, "summary.tsv", "pattern,objective,seeds," NL_STUDY_CHENG_STORY, "Mean (sd, min p) over seeds per pattern and objective; uniform_* = fraction of "
                          "runs not rejected as non-uniform at alpha = 0.05", 4);
  nl_table *wt = nl_study_cheng_welch_alloc();
  for (int i = 0; i < NPAT; i++) {
    size_t row_ks = (size_t)i * NOBJ, row_chi = row_ks + 1;
    double ks_ks = nl_table_value(sum, row_ks, "E_ks"), ks_chi = nl_table_value(sum, row_chi, "E_ks");
    double chi_ks = nl_table_value(sum, row_ks, "chi2"), chi_chi = nl_table_value(sum, row_chi, "chi2");
    double con_ks = nl_table_value(sum, row_ks, "E_con"), con_chi = nl_table_value(sum, row_chi, "E_con");
    /* Between-objective tests (Welch over seeds): is E_Con "close" or different? */
    double pc = nl_study_cheng_welch_add(wt, sum, row_ks, row_chi, "E_con", pats[i], "ks", "chisq");
    nl_study_cheng_welch_add(wt, sum, row_ks, row_ks + 2, "E_con", pats[i], "ks", "kuiper");
    nl_study_cheng_welch_add(wt, sum, row_chi, row_ks + 2, "E_con", pats[i], "chisq", "kuiper");
    double pk = nl_study_cheng_welch_add(wt, sum, row_ks, row_chi, "E_ks", pats[i], "ks", "chisq");
    double px = nl_study_cheng_welch_add(wt, sum, row_chi, row_ks, "chi2", pats[i], "chisq", "ks");
    nl_harness_text(r, "%s: E_KS %.4g (KS objective) vs %.4g (chi-square objective), Welch p = %.3g: KS CDF %s. "
                       "chi2 %.4g vs %.4g, p = %.3g: chi-square error %s under the chi-square objective. "
                       "E_Con %.4g vs %.4g (%.1f%% apart), Welch p = %.3g: %s.\n",
                   pats[i], ks_ks, ks_chi, pk, ks_ks >= ks_chi ? "NOT closer" : pk < 0.05 ? "closer to the ideal line, as in the thesis"
                                                  : "closer to the ideal line, but not significantly at alpha = 0.05",
                   chi_ks, chi_chi, px, chi_chi < chi_ks ? "lower" : "NOT lower", con_ks, con_chi,
                   100 * fabs(con_ks - con_chi) / con_chi, pc,
                   pc < 0.05 ? "the two objectives' E_Con differ at alpha = 0.05, so \"close\" holds only as the size of the gap, not as no difference"
                             : "no difference detected at alpha = 0.05 (the thesis's \"close\")");
    char q[2][64];
    snprintf(q[0], sizeof q[0], "E_KS, KS vs chi-square objective, %s", pats[i]);
    snprintf(q[1], sizeof q[1], "chi2, chi-square vs KS objective, %s", pats[i]);
    nl_harness_verdict_less(r, "summary.tsv", sum, row_ks, row_chi, q[0], "KS CDF closer to ideal", "E_ks", "E_ks_sd", "seeds", 0.05);
    nl_harness_verdict_less(r, "summary.tsv", sum, row_chi, row_ks, q[1], "chi2 lower under its objective", "chi2", "chi2_sd", "seeds", 0.05);
  }
  nl_harness_write_table(r, wt, "tests.tsv");
  nl_harness_report_table(r, wt, "Between-objective tests per pattern: Welch's t-test on the means and sds over seeds", 4);
  nl_study_cheng_control_text(r, sum, 2);
  nl_table_free(wt);
  double worst_ks = nl_study_column_min(sum, "uniform_ks"), worst_ku = nl_study_column_min(sum, "uniform_kuiper");
  nl_harness_text(r, "Uniformity preserved? The smallest fraction of runs not rejected at alpha = 0.05 "
                     "is %.2f by KS and %.2f by Kuiper%s\n", worst_ks, worst_ku,
                 worst_ks == 1 && worst_ku == 1 ? ": every optimised table is indistinguishable from uniform."
                                                : ": some optimised tables are rejected (see p_*_min).");
  /* How regular is "uniform"? P(D_n <= d) under the null: the chance that a
   * truly random table of M angles is at least this close to the ideal line. */
  for (int o = 0; o < NOBJ; o++) {
    double d = nl_table_value(sum, (size_t)o, "E_ks");
    nl_harness_text(r, "%s objective (flower): mean E_KS %.4g; a random table of %zu uniform angles has "
                       "P(D <= %.4g) = %.3g (median D about %.4g).\n", onames[o], d, base.m, d,
                   nl_stats_ks_cdf(base.m, d, NULL), nl_cheng_ks_median(base.m));
  }
  nl_harness_text(r, "So p-values near 1 do not mean \"typical uniform\": the statistic terms drive the angles "
                     "to a more-regular-than-random set (under the chi-square objective %d of %zu bins hold exactly "
                     "one angle on %s, first seed; in a random table about %.0f%% do), which no test at "
                     "alpha = 0.05 rejects but which a random table would almost never produce.\n",
                 single[0], base.chisq_bins, pats[0],
                 100.0 * (double)base.m / base.chisq_bins * pow(1.0 - 1.0 / base.chisq_bins, (double)base.m - 1));
  for (int i = 0; i < NPAT; i++) {
    char f[64], cap[128];
    snprintf(f, sizeof f, "noise_%s.png", pats[i]);
    snprintf(cap, sizeof cap, "%s: pattern and the controlled value per objective (first seed)", pats[i]);
    nl_harness_figure(r, f, cap);
  }
  nl_harness_figure(r, "cdf.png", "CDF of the optimised angles (first seed) as its deviation from the ideal line, per objective (Fig 4.5, 4.6 left)");
  nl_harness_figure(r, "hist.png", "Histograms of the optimised angles, 500 bins (Fig 4.5, 4.6 right)");
  nl_table_free(sum);
  nl_harness_check_measured(r, "*", 100);   /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
