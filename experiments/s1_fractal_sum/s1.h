/* s1.h - S1's report prose (report.c). */
#ifndef S1_H
#define S1_H

#include "harness/nl_harness.h"

/* What the octaves do to the spectrum, the sd and the bound, from the
 * distribution table d of nl_study_octave_series (rows 1, 2, 3, 8 octaves)
 * and the sd law table law (nl_study_sd_law_table). */
void s1_report(nl_harness *r, const nl_table *d, const nl_table *law);

#endif
