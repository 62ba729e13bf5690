/* s2.h - S2's report prose (report.c). */
#ifndef S2_H
#define S2_H

#include "harness/nl_harness.h"

/* What the absolute value does to one octave, from the table of
 * s2_fold_table (fold.h) with its cut in cycles per unit. */
void s2_report(nl_harness *r, const nl_table *fold, double cut);

#endif
