/* l3.h - L3's report prose (report.c). */
#ifndef L3_H
#define L3_H

#include "harness/nl_harness.h"

/* The procedural exemplars: how they are made and measured, the readings of
 * sec. 5, the KS table kt (ks.tsv), the spline table ft (spline.tsv), the
 * synthesis montages of the `nkinds` exemplars `kinds` and the spectra
 * figure; size x size, K seeds. */
void l3_report_exemplars(nl_harness *r, const nl_table *kt, const nl_table *ft,
                         const char *const *kinds, int nkinds, int size, int K);

/* The Gaussian self-match (gt, K seeds, l3_gauss_table), the procedural
 * `wavelet` exemplar's KS per variant (kt, columns kind, variant, ks_mean)
 * and the photographs (pt, l3_photos: synthesised at size, seeds from seed,
 * judged by min_share, max_ratio, max_ks) and the verdict rows (ct, claims.tsv,
 * l3_verdicts). */
void l3_report_photos(nl_harness *r, const nl_table *kt, const nl_table *gt, const nl_table *pt,
                      const nl_table *ct, int K, int size, unsigned long seed, double min_share,
                      double max_ratio, double max_ks);

#endif
