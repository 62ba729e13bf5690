/* sweep.h - L2's error against image size (sweep.c): beyond the paper,
 * how far each estimator's weights fall from the true ones as the image
 * grows, over seeds. */
#ifndef L2_SWEEP_H
#define L2_SWEEP_H

#include "report.h"
#include "harness/nl_harness.h"
#include "table/nl_table.h"

/* Sides 64, 128, ... <= sw->maxsize; at each, a transfer matrix from
 * sw->tseeds noises of a tile of period `tile` (taper sw->frac) and
 * sw->seeds Fig. 4 trials (seeds from seed0's stream "l2.size_trial").
 * Returns estimators.tsv (size, bands, estimator, err_mean, err_sd,
 * err_fine_mean, err_fine_sd, power_ratio, p_vs_eq12, p_fine_vs_eq12: paired
 * by seed against eq. 12, seeds); *bands gets bands.tsv (size, band,
 * estimator, rmse, bias). Fills the rest of *sw (nsizes, m, v, below, bbelow,
 * p_last, pmax, pf) for the report. */
nl_table *l2_size_sweep(nl_harness *r, int tile, unsigned long seed0, l2_sweep *sw,
                        nl_table **bands);

#endif
