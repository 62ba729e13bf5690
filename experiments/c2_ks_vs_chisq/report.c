/* C2's report prose (Cheng 2009 sec. 4.2, Fig 4.5-4.6): every number
 * formatted from the summary table or the run's setting. */
#include "c2.h"
#include "harness/nl_harness.h"
#include "stats/nl_stats.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void c2_intro_text(nl_harness *r, const nl_table *sum, const char *const *pats,
                   const nl_cheng_config *c, int grid)
{
  nl_harness_text(r,
                  "**Thesis:** two patterns optimised with the KS term (eq. 3.7) and with the "
                  "chi-square term (eq. 3.4, 512 angles in 500 bins): the KS CDF lies closer to "
                  "the ideal line, the chi-square error is lower under the chi-square objective, "
                  "and E_Con is close in both (numbers not printed). **Ours:** patterns %s and %s "
                  "on a %d x %d control grid, thesis setting (M = %zu, F = %d, f1 = %g, a1 = %g, "
                  "w1 = %g, w2 = %g), %d seeds each; the chi-square term enters E as Cramer's V = "
                  "sqrt(chi2 / (n (K - 1))) so the thesis weights keep their balance "
                  "(nl_cheng.h). Kuiper's V is a third objective. Statistics are over all %zu "
                  "angles.\n",
                  pats[0], pats[1], grid, grid, c->m, c->octaves, c->f1, c->a1, c->w1, c->w2,
                  nl_harness_seeds(r), c->m);
  nl_harness_report_columns(r, sum, "summary.tsv", "pattern,objective,seeds," NL_STUDY_CHENG_STORY,
                            "Mean (sd, min p) over seeds per pattern and objective; uniform_* = "
                            "fraction of runs not rejected as non-uniform at alpha = 0.05",
                            4);
}

void c2_pattern_text(nl_harness *r, const nl_table *sum, const char *pat, size_t row_ks,
                     size_t row_chi, double pk, double px, double pc)
{
  double ks_ks = nl_table_value(sum, row_ks, "E_ks");
  double ks_chi = nl_table_value(sum, row_chi, "E_ks");
  double chi_ks = nl_table_value(sum, row_ks, "chi2");
  double chi_chi = nl_table_value(sum, row_chi, "chi2");
  double con_ks = nl_table_value(sum, row_ks, "E_con");
  double con_chi = nl_table_value(sum, row_chi, "E_con");
  const char *ks_verdict = "NOT closer";
  if (ks_ks < ks_chi)
    ks_verdict = pk < 0.05 ? "closer to the ideal line, as in the thesis"
                           : "closer to the ideal line, but not significantly at alpha = 0.05";
  const char *con_verdict =
      pc < 0.05 ? "the two objectives' E_Con differ at alpha = 0.05, so \"close\" holds only as "
                  "the size of the gap, not as no difference"
                : "no difference detected at alpha = 0.05, which alone does not show \"close\" "
                  "(the equivalence test below does)";
  nl_harness_text(r,
                  "%s: E_KS %.4g (KS objective) vs %.4g (chi-square objective), Welch p = %.3g: "
                  "KS CDF %s. chi2 %.4g vs %.4g, p = %.3g: chi-square error %s under the "
                  "chi-square objective. E_Con %.4g vs %.4g (%.1f%% apart), Welch p = %.3g: %s.\n",
                  pat, ks_ks, ks_chi, pk, ks_verdict, chi_ks, chi_chi, px,
                  chi_chi < chi_ks ? "lower" : "NOT lower", con_ks, con_chi,
                  100 * fabs(con_ks - con_chi) / con_chi, pc, con_verdict);
}

void c2_tests_text(nl_harness *r, const nl_table *wt)
{
  nl_harness_report_table(r, wt,
                          "Between-objective tests per pattern: Welch's t-test on the means and "
                          "sds over seeds",
                          4);
}

void c2_regularity_text(nl_harness *r, const nl_table *sum, const char *const *onames, int nobj,
                        const nl_cheng_config *c, const char *pat, int single)
{
  double worst_ks = nl_study_column_min(sum, "uniform_ks");
  double worst_ku = nl_study_column_min(sum, "uniform_kuiper");
  nl_harness_text(r,
                  "Uniformity preserved? The smallest fraction of runs not rejected at alpha = "
                  "0.05 is %.2f by KS and %.2f by Kuiper%s\n",
                  worst_ks, worst_ku,
                  worst_ks == 1 && worst_ku == 1
                      ? ": every optimised table is indistinguishable from uniform."
                      : ": some optimised tables are rejected (see p_*_min).");
  /* How regular is "uniform"? P(D_n <= d) under the null: the chance that a
   * truly random table of M angles is at least this close to the ideal line. */
  for (int o = 0; o < nobj; o++) {
    double d = nl_table_value(sum, (size_t)o, "E_ks");
    nl_harness_text(r,
                    "%s objective (%s): mean E_KS %.4g; a random table of %zu uniform angles has "
                    "P(D <= %.4g) = %.3g (median D about %.4g).\n",
                    onames[o], pat, d, c->m, d, nl_stats_ks_cdf(c->m, d, NULL),
                    nl_cheng_ks_median(c->m));
  }
  /* In a random table of M angles in K bins, a bin holds exactly one with
   * probability (M / K) (1 - 1/K)^(M - 1) (binomial). */
  double k = (double)c->chisq_bins;
  double random_single = 100.0 * (double)c->m / k * pow(1.0 - 1.0 / k, (double)c->m - 1);
  nl_harness_text(r,
                  "So p-values near 1 do not mean \"typical uniform\": the statistic terms drive "
                  "the angles to a more-regular-than-random set (under the chi-square objective "
                  "%d of %zu bins hold exactly one angle on %s, first seed; in a random table "
                  "about %.0f%% do), which no test at alpha = 0.05 rejects but which a random "
                  "table would almost never produce.\n",
                  single, c->chisq_bins, pat, random_single);
}

void c2_figures_text(nl_harness *r, const char *const *pats, int npat, const nl_cheng_config *c)
{
  for (int i = 0; i < npat; i++) {
    char f[64], cap[128];
    snprintf(f, sizeof f, "noise_%s.png", pats[i]);
    snprintf(cap, sizeof cap, "%s: pattern and the controlled value per objective (first seed)",
             pats[i]);
    nl_harness_figure(r, f, cap);
  }
  nl_harness_figure(r, "cdf.png",
                    "CDF of the optimised angles (first seed) as its deviation from the ideal "
                    "line, per objective (Fig 4.5, 4.6 left)");
  char cap[128];
  snprintf(cap, sizeof cap, "Histograms of the optimised angles, %zu bins (Fig 4.5, 4.6 right)",
           c->chisq_bins);
  nl_harness_figure(r, "hist.png", cap);
}

void c2_equiv_text(nl_harness *r, const nl_table *eq)
{
  nl_harness_text(r,
                  "**\"E_Con close in both\"** is a claim of equality, so it is decided by an "
                  "equivalence test, not by a Welch test that fails to reject: two one-sided "
                  "tests (TOST) reject a difference of the margin or more. The margin follows a "
                  "rule written before the run (docs/experiments.md, Equivalence margins): the "
                  "thesis compares one run per objective, so \"close\" is read as closer than "
                  "one seed-to-seed sd of a single run's E_Con, pooled over the two objectives. "
                  "Negative control: the KS objective against its own random start tables, at "
                  "the same margin.\n");
  nl_harness_report_table(r, eq,
                          "E_Con, KS objective against each chi-square reading and against its "
                          "random start tables: difference, its standard error, the margin, "
                          "Welch p (equal means) and TOST p (equal within the margin)",
                          4);
  for (size_t q = 0; q + 1 < eq->nrows; q++) {
    if (!strcmp(nl_table_text(eq, q, "b"), "random")) continue;
    char quantity[96], rule[64];
    const char *pat = nl_table_text(eq, q, "pattern");
    int raw = !strcmp(nl_table_text(eq, q, "b"), "chisq_raw");
    snprintf(quantity, sizeof quantity, "E_Con close, KS vs %schi-square objective, %s",
             raw ? "raw " : "", pat);
    snprintf(rule, sizeof rule, "equiv abs %.6g 0.05 0.2", nl_table_value(eq, q, "margin"));
    nl_harness_verdict_equiv(r, "equiv.tsv", eq, q, quantity, "no_diff", "diff", "se", "n_eff",
                             rule, "independent",
                             raw ? "margin: one pooled seed-to-seed sd of E_Con; chi2 entered "
                                   "unscaled as eq. 3.4 prints it"
                                 : "margin: one pooled seed-to-seed sd of E_Con; chi2 entered "
                                   "as Cramer's V");
    nl_harness_verdict_control(r, "the KS objective against its random start tables",
                               "equiv.tsv", eq, q + 1);
  }
}

void c2_raw_text(nl_harness *r, const nl_table *sum, const char *pat, size_t ks, size_t chi,
                 size_t raw, const nl_cheng_config *c)
{
  nl_harness_text(r,
                  "%s, chi2 as printed (eq. 3.4, raw) against Cramer's V: under the raw term "
                  "chi2 %.4g (Cramer's V objective %.4g, KS objective %.4g), E_KS %.4g (%.4g, "
                  "%.4g), E_Con %.4g (%.4g, %.4g; random start tables %.4g). With w1 = %.4g the "
                  "raw chi2 (about K for a random table) outweighs w2 E_Con.\n",
                  pat, nl_table_value(sum, raw, "chi2"), nl_table_value(sum, chi, "chi2"),
                  nl_table_value(sum, ks, "chi2"), nl_table_value(sum, raw, "E_ks"),
                  nl_table_value(sum, chi, "E_ks"), nl_table_value(sum, ks, "E_ks"),
                  nl_table_value(sum, raw, "E_con"), nl_table_value(sum, chi, "E_con"),
                  nl_table_value(sum, ks, "E_con"), nl_table_value(sum, ks, "E_con_random"),
                  c->w1);
}

void c2_seam_text(nl_harness *r, const nl_table *sum)
{
  double lo = INFINITY, hi = -INFINITY, sd = 0;
  for (size_t q = 0; q < sum->nrows; q++) {
    lo = fmin(lo, nl_table_value(sum, q, "seam_ratio"));
    hi = fmax(hi, nl_table_value(sum, q, "seam_ratio"));
    sd = fmax(sd, nl_table_value(sum, q, "seam_ratio_sd"));
  }
  nl_harness_text(r,
                  "Seams: the seam ratio of the optimised values (largest mean |step| across one "
                  "column or row boundary of a 128^2 raster over the mean of all boundaries, "
                  "summary.tsv seam_ratio) is %.2f..%.2f over the %zu rows (sd over seeds at "
                  "most %.2f).\n",
                  lo, hi, sum->nrows, sd);
}
