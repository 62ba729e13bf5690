/* C6's report (report.c): the prose beside summary.tsv and the figures'
 * captions. */
#ifndef C6_REPORT_H
#define C6_REPORT_H

#include "harness/nl_harness.h"
#include "study/nl_study_cheng.h"

/* The thesis's claims against ours, per texture from summary.tsv (sum): its
 * original row, then the reproductions with and without the swap; nrep and
 * swap as run, po and c the pool's and the optimisation's settings. */
void c6_report(nl_harness *r, const nl_table *sum, int nrep, double swap,
               const nl_cheng_pool_options *po, const nl_cheng_config *c);

#endif
