/* editing.h - L4's replicates of frequency-based editing (editing.c). */
#ifndef L4_EDITING_H
#define L4_EDITING_H

#include "study/nl_study.h"
#include "wavelet/nl_wavelet.h"

/* ---- L4: frequency-based editing (Lagae et al. 2010 Fig. 10c, d) --------
 *
 * l4_edit_replicate analyses an exemplar with ([0]) and without ([1])
 * histogram matching, synthesises (seed) the original, the edit (the nfine
 * finest bands' weights times factor, nl_byexample_attenuate) and the removal
 * (factor 0), and records per eq. 13 band k the luminance band power of the
 * original, the ratios edited / original and removed / original (the floor:
 * power of the other bands that eq. 13 counts in band k), the share of a
 * single band k of the same 2D wavelet noise that falls in the nfine finest
 * bands (nl_byexample_band_leakage), and the KS distances per channel of the
 * 2D synthesis to a slice z = 0 of the solid synthesis and to the exemplar.
 * l4_edit_tables summarises K replicates (mean and sd over seeds):
 *   returned  band, power_b, ratio(_sd), ratio_nohist(_sd), floor(_nohist),
 *             predicted(_nohist) = floor + factor^2 (1 - floor), leak_fine,
 *             expected (factor^2 on edited bands, else 1);
 *   solid     channel, ks_2d_vs_slice(_sd), ks_2d_vs_exemplar(_sd);
 *   summary   one row: ranges over the edited bands of the mean
 *             ratio and floor (both histogram settings), the largest sd of
 *             a ratio, the largest per-seed |ratio - predicted|, the power of
 *             the unedited bands over that of the edited ones (no histogram
 *             matching), the aggregate floor of the edited bands, the same
 *             estimated from the leakage shares (sum_k P_k leak_k / sum_j P_j),
 *             and the largest band power over the finest band's. */
typedef struct {
  int nbands;
  double power[2][NL_WAVELET_MAX_BANDS]; /* luminance band power of the original */
  double ratio[2][NL_WAVELET_MAX_BANDS]; /* edited / original */
  double floor[2][NL_WAVELET_MAX_BANDS]; /* removed / original */
  double leak[NL_WAVELET_MAX_BANDS];     /* share of band k in the nfine finest */
  double ks_slice[3];                    /* KS per channel, 2D synthesis vs solid slice */
  double ks_exemplar[3];                 /* KS per channel, 2D synthesis vs exemplar */
} l4_edit;
nl_status l4_edit_replicate(const nl_image *ex, int nfine, double factor, unsigned long seed,
                            l4_edit *out, nl_error *err);
nl_table *l4_edit_tables(const l4_edit *rep, int K, int nfine, double factor, nl_table **solid,
                         nl_table **summary);

#endif
