/* L2's report (report.c): the prose beside weights.tsv, estimators.tsv and
 * photos.tsv and the figures' captions, every number formatted from the run. */
#ifndef L2_REPORT_H
#define L2_REPORT_H

#include "byexample/nl_byexample_leak.h"
#include "harness/nl_harness.h"
#include "table/nl_table.h"

#define L2_PAPER_SIGMA2 0.265 /* the paper's sigma_N^2 (sec. 4.3) */

/* Fig. 4 at one size and seed: nb bands, relative weight error e and power
 * ratio pw per estimator (nl_byexample_trial). */
typedef struct {
  int size, nb, tile;
  unsigned long seed;
  double e[NL_BYEXAMPLE_ESTIMATORS], pw[NL_BYEXAMPLE_ESTIMATORS];
} l2_fig4;

/* The error-against-size sweep: nsizes sizes up to maxsize, seeds per size,
 * tseeds noises per transfer matrix, taper fraction frac; m and v the mean
 * and sd of [0] the error, [1] the error over the `fine` finest bands, [2]
 * the power ratio, at maxsize; below: sizes where the corrected estimator's
 * mean error is below eq. 12's; bbelow: bands at maxsize where its RMS
 * error is; p_last, pmax: its paired p against eq. 12 at maxsize and the
 * largest over sizes; pf: the same over the finest bands at maxsize;
 * sizes: the sides; err_all, err_fine: eq. 12's error per side and seed
 * (err[i * seeds + s]; all bands, the fine finest bands), owned by the caller
 * after the sweep (free). */
typedef struct {
  int nsizes, maxsize, seeds, tseeds, fine, below, bbelow;
  int sizes[16];
  double *err_all, *err_fine;
  double frac;
  double m[3][NL_BYEXAMPLE_ESTIMATORS], v[3][NL_BYEXAMPLE_ESTIMATORS];
  double p_last, pmax, pf;
} l2_sweep;

/* The whole report: Fig. 4 (weights table wt), the sweep (estimators table
 * et), the verdict tables (st: similar.tsv, tt: trend.tsv, l2_claims), and
 * the photographs (pt; nphotos in exdir, cropped to pmax, pseeds
 * syntheses each). */
void l2_report(nl_harness *r, const l2_fig4 *f, const l2_sweep *s, const nl_table *wt,
               const nl_table *et, const nl_table *st, const nl_table *tt, const nl_table *pt,
               int nphotos, const char *exdir, int pmax, int pseeds);

#endif
