/* s2.h - S2's report prose (report.c). */
#ifndef S2_H
#define S2_H

#include "harness/nl_harness.h"

/* What the absolute value does to each octave, after the series. */
void s2_report(nl_harness *r);

#endif
