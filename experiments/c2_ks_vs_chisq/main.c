/* C2 - Cheng 2009 Fig 4.5-4.6 (sec. 4.2): the same patterns optimised with the
 * KS term (eq. 3.7), the chi-square term (eq. 3.4, 500 bins; as Cramer's V,
 * the headline, and unscaled as printed) and, added here, the Kuiper term;
 * CDF of the optimised angles against the ideal line, histograms, and every
 * statistic with its p-value over seeds. */
#include "c2.h"
#include "equiv.h"
#include "study/nl_study_cheng.h"
#include "harness/nl_harness.h"

#include <stdio.h>
#include <stdlib.h>

#define NPAT  2
#define NOBJ  4
#define PANEL 192 /* side in pixels of the value images */

static const char *const pats[NPAT] = { "flower", "x" };
static const nl_cheng_stat objs[NOBJ] = { NL_CHENG_STAT_KS, NL_CHENG_STAT_CHISQ,
                                          NL_CHENG_STAT_KUIPER, NL_CHENG_STAT_CHISQ_RAW };
static const char *const onames[NOBJ] = { "ks", "chisq", "kuiper", "chisq_raw" };

int main(int argc, char **argv)
{
  nl_study_cheng s;
  nl_study_cheng_open(&s, "c2_ks_vs_chisq", "C2 - KS term vs chi-square term (Fig 4.5, 4.6)", &argc,
                      argv);
  nl_harness *r = s.r;
  nl_study_cheng_ready(&s);
  const nl_cheng_config base = s.c;
  int k = nl_harness_seeds(r);
  const char *labels[] = { "pattern", "objective" };
  nl_table *sum = nl_study_cheng_summary_alloc(2, labels);

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
    const char *lab[2] = { pats[q / NOBJ], onames[q % NOBJ] };
    nl_study_cheng_rows_add(&s, sum, 2, lab, evs + (size_t)q * k);
  }
  free(evs);

  /* Per pattern, the first seed: CDF (Fig 4.5, 4.6 left), histogram (right)
   * and the controlled value per objective. */
  int single[NPAT] = { 0 }; /* bins holding exactly one angle, chi-square objective */
  for (int i = 0; i < NPAT; i++) {
    const nl_noise_grad2 *const *first = (const nl_noise_grad2 *const *)firsts + NOBJ * i;
    char file[64];
    nl_harness_progress(r, (i + 1.0) / NPAT, pats[i]);
    nl_table *cdf = nl_study_cheng_cdf_table(first, onames, NOBJ);
    snprintf(file, sizeof file, "cdf_%s.tsv", pats[i]);
    nl_harness_write_table(r, cdf, file);
    nl_table *hist = c2_hist_table(first, onames, NOBJ, base.chisq_bins);
    for (size_t b = 0; b < hist->nrows; b++) single[i] += nl_table_value(hist, b, "chisq") == 1.0;
    snprintf(file, sizeof file, "hist_%s.tsv", pats[i]);
    nl_harness_write_table(r, hist, file);
    nl_image *panels[NOBJ + 1];
    const char *plab[NOBJ + 1] = { "pattern", "KS term", "chi-square term", "Kuiper term",
                                   "raw chi-square term" };
    panels[0] = nl_study_cheng_pattern_panel(pat[i], PANEL);
    for (int o = 0; o < NOBJ; o++)
      panels[o + 1] = nl_study_cheng_value_image(first[o], &base, PANEL);
    snprintf(file, sizeof file, "noise_%s.png", pats[i]);
    nl_study_cheng_montage(r, panels, plab, NOBJ + 1, NOBJ + 1, pats[i], file);
    for (int o = 0; o < NOBJ; o++) nl_noise_grad2_free(firsts[NOBJ * i + o]);
    nl_table_free(cdf);
    nl_table_free(hist);
    nl_cheng_pattern_free(pat[i]);
  }
  nl_harness_write_table(r, sum, "summary.tsv");
  c2_intro_text(r, sum, pats, &base, s.grid);

  /* Per pattern, the KS objective (row ks) against the chi-square one (row
   * ks + 1, raw: ks + 3) and both against Kuiper (ks + 2): Welch's t-test
   * over seeds. */
  nl_table *wt = nl_study_cheng_welch_alloc();
  nl_table *eq = c2_equiv_alloc();
  nl_table *own = c2_own_alloc();
  for (int i = 0; i < NPAT; i++) {
    const char *p = pats[i];
    size_t ks = (size_t)i * NOBJ, chi = ks + 1, ku = ks + 2, raw = ks + 3;
    double pc = nl_study_cheng_welch_add(wt, sum, ks, chi, "E_con", p, "ks", "chisq");
    nl_study_cheng_welch_add(wt, sum, ks, ku, "E_con", p, "ks", "kuiper");
    nl_study_cheng_welch_add(wt, sum, chi, ku, "E_con", p, "chisq", "kuiper");
    nl_study_cheng_welch_add(wt, sum, ks, raw, "E_con", p, "ks", "chisq_raw");
    double pk = nl_study_cheng_welch_add(wt, sum, ks, chi, "E_ks", p, "ks", "chisq");
    double px = nl_study_cheng_welch_add(wt, sum, chi, ks, "chi2", p, "chisq", "ks");
    nl_study_cheng_welch_add(wt, sum, ks, raw, "E_ks", p, "ks", "chisq_raw");
    nl_study_cheng_welch_add(wt, sum, raw, ks, "chi2", p, "chisq_raw", "ks");
    c2_pattern_text(r, sum, p, ks, chi, pk, px, pc);
    c2_raw_text(r, sum, p, ks, chi, raw, &base);
    /* "E_Con close": each chi-square reading against the KS objective, then
     * the KS objective against its own random start tables (the control),
     * all at the verdict pair's margin (docs/experiments.md). */
    const size_t other[2] = { chi, raw };
    for (int j = 0; j < 2; j++) {
      size_t b = other[j];
      size_t n = (size_t)nl_table_value(sum, ks, "seeds");
      double m = c2_equiv_margin(nl_table_value(sum, ks, "E_con_sd"),
                                 nl_table_value(sum, b, "E_con_sd"));
      c2_equiv_add(eq, p, "ks", onames[b - ks], nl_table_value(sum, ks, "E_con"),
                   nl_table_value(sum, ks, "E_con_sd"), n, nl_table_value(sum, b, "E_con"),
                   nl_table_value(sum, b, "E_con_sd"), n, m);
      c2_equiv_add(eq, p, "ks", "random", nl_table_value(sum, ks, "E_con"),
                   nl_table_value(sum, ks, "E_con_sd"), n, nl_table_value(sum, ks, "E_con_random"),
                   nl_table_value(sum, ks, "E_con_random_sd"), n, m);
    }
    c2_own_verdicts(r, own, sum, p, ks, chi, ku);
  }
  nl_harness_write_table(r, own, "own.tsv");
  nl_harness_write_table(r, wt, "tests.tsv");
  nl_harness_write_table(r, eq, "equiv.tsv");
  c2_tests_text(r, wt);
  c2_equiv_text(r, eq);
  nl_study_cheng_control_text(r, sum, 2);
  c2_seam_text(r, sum);
  nl_table_free(wt);
  nl_table_free(eq);
  nl_table_free(own);
  c2_regularity_text(r, sum, onames, NOBJ, &base, pats[0], single[0]);
  c2_figures_text(r, pats, NPAT, &base);
  nl_table_free(sum);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
