/* verdicts.h - L3's verdict rows (verdicts.c): the paper's method on the
 * photographs, the calibrated synthesis beside it, the photographs'
 * structure, and the 66 parameters. */
#ifndef L3_VERDICTS_H
#define L3_VERDICTS_H

#include "harness/nl_harness.h"
#include "table/nl_table.h"

#define L3_PAPER_PARAMS 66 /* sec. 5: 9 matrix + 30 histogram + 27 weights at 512 x 512 */

/* Writes claims.tsv (quantity, representation, paper, ours, passes,
 * syntheses) from photos_mean.tsv (pt) and declares its verdicts:
 *   0 syntheses of the paper's method (paper10) passing the band and KS
 *     criteria, against "all" (paper 1): independent;
 *   1 the same for the calibrated synthesis: fitted (its gains are fitted to
 *     the photo's band powers on the realisation, its histogram matched by
 *     rank: the criteria's own quantities);
 *   2 paper10 syntheses keeping the photo's structure (coherence ratio
 *     within the band criterion's factor, structure.h): independent;
 *   3 the parameter count of a 512 x 512 RGB texture: by construction.
 * Rows 4 and 5, the controls of 0 and 2: another photograph (the next in
 * name order, its top-left square) in place of photo i's synthesis, judged
 * by the same criteria (nl_study_example_compare, coherence ratio within
 * max_ratio). psize: the syntheses' side. Returns claims.tsv (caller
 * frees). */
nl_table *l3_verdicts(nl_harness *r, const nl_table *pt, int psize, nl_image *const *photos,
                      char (*names)[64], int np, double min_share, double max_ratio,
                      double max_ks);

/* Fig. 5 and 6 from ks.tsv (kt: kind, variant, ks_mean, ks_sd, corr_err,
 * corr_err_sd, seeds), by Welch's test at 5%:
 *   Fig. 5, per exemplar kind: the colour-correlation error of PCA
 *     synthesis (pca_hist) below RGB's (rgb_hist); control: the same on
 *     the exemplar with independent channels (kind "KIND, channels
 *     independent");
 *   Fig. 6, per non-Gaussian kind (every kind but `wavelet`): the KS of
 *     histogram matching (pca_hist) below that without (pca_nohist);
 *     control: the same on the `wavelet` exemplar, whose channels are
 *     Gaussian. All independent. */
void l3_figure_verdicts(nl_harness *r, const nl_table *kt, const char *const *kinds, int nkinds);

#endif
