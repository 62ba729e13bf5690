/* synthesis.h - L3's syntheses over seeds and the Gaussian self-match of a
 * histogram representation (synthesis.c). Both run on `threads` threads
 * (nl_parallel_for); each seed writes only its own slots and the sums are
 * taken in seed order afterwards, so the results do not depend on the thread
 * count. */
#ifndef L3_SYNTHESIS_H
#define L3_SYNTHESIS_H

#include "byexample/nl_byexample.h"
#include "harness/nl_harness.h"

/* K syntheses of p, size x size, seeds nl_seed_replicate(seed0, s), each
 * against the exemplar ex: ks[s] = nl_study_ks_channels (per channel in
 * per[3 s .. 3 s + 2]), ce[s] = nl_byexample_correlation_error. Returns seed
 * 0's synthesis (caller frees); NULL and err (the first failing seed's) if a
 * synthesis fails. */
nl_image *l3_synth_seeds(const nl_byexample_params *p, const nl_byexample_synth_options *so,
                         const nl_image *ex, int size, int K, unsigned long seed0, int threads,
                         double *ks, double *per, double *ce, nl_error *err);

/* The Gaussian self-match of the paper's (paper10) and the Gaussian-knot
 * (gauss33) representation over K seeds: n N(0, 1) values as the exemplar
 * channel, n fresh N(0, 1) values matched to its histogram (sigma 1,
 * steffen); the KS distance between the two samples and the matched values'
 * fraction beyond 2.5 sd of the exemplar. Columns representation, n,
 * ks_mean, ks_sd, tail_mean, tail_sd, tail_gauss (the Gaussian's own
 * 2 Q(2.5) = 1.24%); rows paper10, gauss33. Caller frees. */
nl_table *l3_gauss_table(size_t n, int K, unsigned long seed0, int threads);

/* The largest |a - b| over every sample of two images of one shape. */
double l3_max_abs_diff(const nl_image *a, const nl_image *b);

/* The radial spectra of the luminance of the exemplar and of the syntheses
 * with and without histogram matching (columns exemplar, synthesis,
 * synthesis_nohist; nl_study_radial_table), written as table `name`. */
void l3_write_spectra(nl_harness *r, const char *name, const nl_image *ex,
                      const nl_image *syn, const nl_image *nohist);

/* The variants of synthesis.c's exemplars, in ks.tsv's order: pca_hist (the
 * paper's), pca_nohist, rgb_hist, pca_hist_fc, pca_hist_gauss33. */
#define L3_NVAR 5
/* Exemplar ex's variant v (kind names it) over the run's seeds: one row of
 * kt (ks.tsv); returns the synthesis of the first seed (variants.c). */
nl_image *l3_variant(nl_harness *r, nl_table *kt, const char *kind, int v, const nl_image *ex,
                     int size);

#endif
