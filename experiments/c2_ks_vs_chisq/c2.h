/* c2.h - C2's angle histograms (hist.c) and report prose (report.c).
 *
 * Cheng 2009 sec. 4.2 (Fig 4.5, 4.6) optimises the same patterns with the KS
 * term (eq. 3.7) and the chi-square term (eq. 3.4); C2 adds Kuiper's V. The
 * summary table holds one row per (pattern, objective), objectives in the
 * order ks, chisq, kuiper, chisq_raw (eq. 3.4's chi2 entered unscaled), so
 * a pattern's rows are i NOBJ + 0, 1, 2, 3.
 */
#ifndef C2_H
#define C2_H

#include "study/nl_study_cheng.h"

#include <stdio.h>

/* Histogram of each table's angles in `bins` equal bins over [0, 2 pi):
 * columns theta (bin centre) and NAME (counts) per table, n <= 15. */
nl_table *c2_hist_table(const nl_noise_grad2 *const *tables, const char *const *names, int n,
                        size_t bins);

/* The own-statistic table: pattern, statistic (a summary column: E_ks,
 * chi2, V_kuiper), objective, seeds, value, value_sd (the column's mean and
 * sd over seeds). Two of the thesis's three claims compare an objective with
 * another on the objective's own statistic; the same comparison for the
 * Kuiper objective on V is their control (no evidence if it passes too). */
nl_table *c2_own_alloc(void);
/* Appends summary row `row`'s statistic (column name) under `objective`;
 * returns the new row. */
size_t c2_own_add(nl_table *own, const nl_table *sum, size_t row, const char *pattern,
                  const char *objective, const char *statistic);
/* Pattern p's own-statistic verdicts, each followed by its Kuiper control,
 * from summary rows ks, chi and ku (the KS, chi-square and Kuiper
 * objectives); appends their rows to own. */
void c2_own_verdicts(nl_harness *r, nl_table *own, const nl_table *sum, const char *p, size_t ks,
                     size_t chi, size_t ku);

/* The thesis's claim, our setting and the summary table. */
void c2_intro_text(nl_harness *r, const nl_table *sum, const char *const *pats,
                   const nl_cheng_config *c, int grid);
/* One pattern's comparison: rows row_ks (KS objective) and row_chi
 * (chi-square objective) of sum, with the Welch p of E_KS (pk), chi2 (px)
 * and E_Con (pc) between them. */
void c2_pattern_text(nl_harness *r, const nl_table *sum, const char *pat, size_t row_ks,
                     size_t row_chi, double pk, double px, double pc);
/* The raw chi-square objective (summary row raw) beside the Cramer's V one
 * (chi) and the KS one (ks): chi2, E_KS and E_Con. */
void c2_raw_text(nl_harness *r, const nl_table *sum, const char *pat, size_t ks, size_t chi,
                 size_t raw, const nl_cheng_config *c);
/* The Welch table's caption. */
void c2_tests_text(nl_harness *r, const nl_table *wt);
/* "E_Con close in both" (equiv.tsv, c2_equiv_add): the margin and its rule,
 * the table, and one equivalence verdict (TOST) per row whose b is not
 * "random", each with the next row (b = "random": the KS objective against
 * its random start tables) as its negative control. */
void c2_equiv_text(nl_harness *r, const nl_table *eq);
/* The seam ratio's range over the summary's rows, in one sentence. */
void c2_seam_text(nl_harness *r, const nl_table *sum);
/* Whether uniformity is preserved, then how regular the optimised tables
 * are: P(D <= E_KS) for a random table per objective (rows 0..nobj-1: the
 * first pattern), and the chi-square objective's bins holding exactly one
 * angle (`single`, first pattern, first seed) against a random table's. */
void c2_regularity_text(nl_harness *r, const nl_table *sum, const char *const *onames, int nobj,
                        const nl_cheng_config *c, const char *pat, int single);
/* The figures: noise_PAT.png per pattern, cdf.png, hist.png. */
void c2_figures_text(nl_harness *r, const char *const *pats, int npat, const nl_cheng_config *c);

#endif
