/* below.h - C6's test of "reproduced errors ... often below the original's"
 * (Cheng 2009 sec. 4.4): a sign test per texture, error and swap.
 *
 * If a reproduction were as good as the original optimised table (the two
 * exchangeable), its error would fall below the original's with probability
 * 1/2; the count below out of n reproductions is then Binomial(n, 1/2). The
 * one-sided p = P(X <= below) is small when reproductions are below less
 * often than that: the claim is a law ("fit" rule), rejected by a small p.
 *
 *   nl_table *b = c6_below_alloc();
 *   c6_below_add(b, sum);                 // from summary.tsv's rows
 *   c6_below_text(r, b, 1.0);             // table, verdicts (swap 1), figures
 */
#ifndef C6_BELOW_H
#define C6_BELOW_H

#include "harness/nl_harness.h"
#include "table/nl_table.h"

/* Columns: texture, kind (reproduced_swap_S), error (E_ks | E_con), n,
 * below, frac_below, p_sign. */
nl_table *c6_below_alloc(void);
/* One row per reproduction row of the summary (c6_reps_summary_alloc) and
 * error, counts from its below_ks / below_con fractions and n. */
void c6_below_add(nl_table *b, const nl_table *sum);
/* P(X <= k) for X ~ Binomial(n, 1/2). */
double c6_sign_p(unsigned k, unsigned n);
/* The reading in one sentence, the table, a verdict per texture and error
 * for the rows of the thesis's swap (kind reproduced_swap_SWAP), each with
 * its negative control (the row of ctl, below_ctl.tsv, of the same texture
 * and error: random tables in place of reproductions), and the figures'
 * qualitative rows. */
void c6_below_text(nl_harness *r, const nl_table *b, double swap, const nl_table *ctl);

#endif
