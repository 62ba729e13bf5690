/* c3.h - C3's report prose (report.c).
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
void c3_intro_text(nl_harness *r, const nl_study_cheng *s, const char *pattern,
                   const double *f1s, int n, const nl_table *sum);
/* Roughness and E_Con per f1 (summary rows 0..n-1): whether roughness rises
 * strictly with f1 (lower f1 smoother) and where E_Con is lowest. */
void c3_result_text(nl_harness *r, const nl_table *sum, const double *f1s, int n);

#endif
