/* weights.h - C4's readings of Table 4.1 and its grid sweep (weights.c). */
#ifndef C4_WEIGHTS_H
#define C4_WEIGHTS_H

#include "study/nl_study_cheng.h"

/* Which reading of Table 4.1's weight columns fits
 * all six rows: per reading (printed; swapped; (a) printed and (b)-(f)
 * swapped) Pearson r of log E_KS (and log E_Con), ours against the thesis's
 * over the rows, its exact one-sided permutation p (n! orderings), and the
 * rms of the centred log ratio (0: ours = the thesis's times one factor);
 * from nl_study_cheng_table41's table. */
nl_table *nl_study_cheng_table41_readings(const nl_table *cmp, const double (*thesis)[NL_STUDY_TABLE41_COLS], int npair);
/* The readings table in the report and its prose; returns the row of the
 * best-fitting reading (smallest rms_log_ks). */
size_t nl_study_cheng_table41_readings_text(nl_harness *r, const nl_table *rd);
/* C4's uniformity prose: over Table 4.1's runs (printed rows 0, 2, ...) and
 * the sweep (w1 / w2 = rhos[q]), the smallest fractions not rejected and the
 * smallest swept ratio from which every run passes. */
void nl_study_cheng_weights_uniformity_text(nl_harness *r, const nl_table *tab, const nl_table *sweep, const double *rhos,
                                            int npair);
/* Config c on `pattern` read at control grids gmin, 2 gmin, ... <= gmax over
 * s's seeds: grid, points, E_ks, E_ks_sd, E_con, E_con_sd, E_con_per_point,
 * paper_E_con, r_pattern, con_vs_const. */
nl_table *nl_study_cheng_grid_sweep(const nl_study_cheng *s, const nl_cheng_config *c, const char *pattern,
                                    int gmin, int gmax, double paper_e_con);

#endif
