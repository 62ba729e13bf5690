/* equiv.h - C2's test of "E_Con close in both": equivalence within a margin
 * fixed before the comparison (Schuirmann's two one-sided tests, TOST).
 *
 * A difference test (Welch) that fails to reject says only that 3 or 10
 * seeds cannot see a difference; "close" is a claim of equality, so its
 * test must reject "far apart". TOST rejects |mu_a - mu_b| >= margin when
 * both one-sided Welch tests reject at alpha:
 *   p = max(P(T > (d + margin) / se), P(T > (margin - d) / se)),
 * d = mean_a - mean_b, se = sqrt(sd_a^2 / n_a + sd_b^2 / n_b), T Welch's t
 * with the Welch-Satterthwaite df (nl_stats_welch_p, whose two-sided p of a
 * shifted difference gives each one-sided p).
 *
 *   double p;
 *   c2_tost_p(900.8, 17.9, 3, 896.4, 16.2, 3, 45.0, &p, &err);  // within +-45?
 */
#ifndef C2_EQUIV_H
#define C2_EQUIV_H

#include "study/nl_study_cheng.h"

#include <stddef.h>

/* NL_EINVAL when nl_stats_welch_p cannot test (n < 2, both sds 0, a
 * negative mean) or margin <= 0. */
nl_status c2_tost_p(double mean_a, double sd_a, size_t n_a, double mean_b, double sd_b, size_t n_b,
                    double margin, double *p, nl_error *err);

/* The equivalence table, one row per pair of conditions a, b of a pattern:
 * pattern, a, b, seeds (of a), mean_a, mean_b (E_Con), no_diff (0, the
 * claim "close"), diff (mean_b - mean_a), diff_pct (100 diff / mean_a), se
 * (sqrt(sd_a^2 / n_a + sd_b^2 / n_b)), n_eff (Welch-Satterthwaite df + 1,
 * the n the harness's TOST takes), margin, p_welch (two-sided, equal means)
 * and p_tost (equal within the margin, c2_tost_p). */
nl_table *c2_equiv_alloc(void);
/* C2's margin rule (docs/experiments.md, "Equivalence margins"), fixed
 * before the run: one sd over seeds of a single run's E_Con, pooled over
 * the two objectives, sqrt((sd_a^2 + sd_b^2) / 2). */
double c2_equiv_margin(double sd_a, double sd_b);
/* Appends the row of a (mean ma, sd sa over na seeds) against b; returns
 * it. Exit-free: an untestable pair (both sds 0) gets p_tost 0 when
 * |d| < margin, else 1. */
size_t c2_equiv_add(nl_table *t, const char *pattern, const char *a, const char *b, double ma,
                    double sa, size_t na, double mb, double sb, size_t nb, double margin);

#endif
