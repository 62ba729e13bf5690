/* C5's report (report.c): the prose beside the tables, every number formatted
 * from the run's tables or parameters. */
#ifndef C5_REPORT_H
#define C5_REPORT_H

#include "readings.h"

/* The readings' prose and verdicts: the headline's rows (best, from
 * c5_readings_write) against the thesis, the pools' effective sample size,
 * and C6's question under the headline's and C6's readings. */
void c5_readings_report(nl_harness *r, c5_readings *R, const char *best);
/* Tables 4.2-4.4 beside the thesis's, the other split, the original against
 * its pool and the held-out checks; then the figures' captions. */
void c5_report(nl_harness *r, const c5_pools *T, const nl_cheng_pool_options *po,
               const nl_cheng_model_options *mo, const nl_cheng_config *c, int grid, int nseeds);

#endif
