/* fold.h - what the absolute value does to one octave (fold.c): S2's
 * turbulence folds noise at its zero set. */
#ifndef S2_FOLD_H
#define S2_FOLD_H

#include "study/nl_study.h"

/* One octave of improved noise at frequency 1 on win, and its absolute
 * value, over nseeds seeds from seed0: one row each ("noise", "|noise|")
 * with the mean of the values (mean, mean_sd over seeds), the DC term's
 * share of the power, mean^2 / mean(v^2) (dc_frac), and the share of the
 * rest of the power at frequencies above `cut` cycles per unit (above_frac,
 * above_frac_sd): the power folding moves above the octave's own band;
 * seeds, the number of seeds. A third row, "noise, other seeds", is noise
 * again on the seeds seed0 + nseeds... (replicates nseeds to 2 nseeds - 1):
 * an unfolded baseline independent of the first row. Caller frees. */
nl_table *s2_fold_table(const nl_noise_window *win, unsigned long seed0, int nseeds, double cut);

#endif
