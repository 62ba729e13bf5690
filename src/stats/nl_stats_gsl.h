/* nl_stats_gsl.h - private to src/stats: GSL's error handler off while a
 * caller runs GSL code that may meet a domain error (a fit's singular
 * matrix, a CDF at an extreme shape such as t with df = 5e-324). GSL's
 * default handler aborts the process; with it off, the function returns
 * NaN or an error code, which the caller turns into a status.
 *
 * The handler is one process-wide variable and callers may run on several
 * threads at once: the first begin turns it off, the last end restores it. */
#ifndef NL_STATS_GSL_H
#define NL_STATS_GSL_H

void nl_stats_gsl_quiet_begin(void);
void nl_stats_gsl_quiet_end(void);

#endif
