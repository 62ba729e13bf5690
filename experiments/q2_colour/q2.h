/* q2.h - Q2's report prose (report.c). */
#ifndef Q2_H
#define Q2_H

#include "harness/nl_harness.h"
#include "noise/nl_noise.h"

/* Eq. 4 and our reading (the window of the GCTBF panels win, the Perlin
 * panel's pwin and frequency), the table t (values.tsv), the figure and its
 * qualitative verdict row. */
void q2_report(nl_harness *r, const nl_noise_window *win, const nl_noise_window *pwin,
               double perlin_freq, const nl_table *t, const nl_table *groups);

/* Worley's linear combinations among Fig. 2's five (F1, F2 - F1) */
#define NLIN 2
/* 1 for a linear combination of F_i (no product term), 0 for one with a
 * product F_iF_j, -1 for Perlin's panel. */
int q2_linear(const char *pattern);

/* spline_use.tsv from the per-seed table use (pattern, seed, clamped,
 * entropy; seeds rows per pattern) and ent (3 x seeds: the linear
 * patterns' mean entropy per seed, the non-linear ones', the linear ones'
 * on the next seeds) and clp (the same for the clamped share): first the
 * rows "linear", "non-linear" and "linear, other seeds" of the verdict and
 * its control (group "mean"), then one row per pattern (group
 * "pattern") with the mean and sd over seeds of clamped and entropy.
 * Caller frees. */
nl_table *q2_group_table(const nl_table *use, const double *ent, const double *clp, int seeds);

/* What eq. 4's clamp and spline make of n values v: *clamped the share
 * outside [0, 1] (flattened to an end colour), *entropy the Shannon entropy
 * in bits of clamp(v, 0, 1) over the spline's `spans` equal segments (0:
 * one segment, log2(spans): every segment alike), how many of the knots'
 * colours the pattern draws on. */
void q2_spline_use(const double *v, size_t n, int spans, double *clamped, double *entropy);

#endif
