/* nl_byexample_leak.h - weights of a wavelet-noise sum from an exemplar,
 * corrected for leakage between bands (beyond Lagae et al. 2010).
 *
 * Eq. 12 reads band k's weight from band k's power alone, w_k^2 = P_k /
 * sigma_N^2. Two things move power between eq. 13's bands:
 *   - the noise itself: wavelet band i is not band-limited to octave i and
 *     puts part of its power into octave i-1 and i+1 (L1 measures it);
 *   - the DFT of a non-periodic exemplar: the edge discontinuity of its
 *     periodic extension spreads power ~1/f^2 into every finer band.
 * The corrected estimator undoes both:
 *   1. transfer matrix A[i * nbands + j]: the expected power in band j of a
 *      noise whose only non-zero weight is w_i = 1, measured on the noise at
 *      the exemplar's size (mean over tiles and offsets); so the expected
 *      band powers of a sum are p_j = sum_i w_i^2 A[i][j];
 *   2. band powers of the tapered exemplar (nl_spectrum_taper2: a Tukey
 *      window, frac 1 is Hann), with A measured through the same taper.
 *      Hann removes the most edge leakage but weights the image down to an
 *      effective quarter of its samples; a taper of 1/4 of each axis keeps
 *      most of them (L2 measures both);
 *   3. w^2 from non-negative least squares, min |A^T w2 - p|, w2 >= 0
 *      (Lawson & Hanson 1974, ch. 23), w = sqrt(w2).
 * The estimators, for comparison (nl_byexample_estimator_names):
 *   eq12       eq. 12 on the raw DFT (the paper)
 *   eq12_taper eq. 12 on the tapered exemplar (step 2 only)
 *   nnls_raw   steps 1 and 3 on the raw DFT
 *   corrected  steps 1-3
 *
 *   nl_byexample_transfer T;
 *   nl_byexample_transfer_measure(&T, NL_BYEXAMPLE_TILE, w, h, nbands, 0.25, 8, seed, threads, &err);
 *   nl_byexample_estimate(&T, NL_BYEXAMPLE_CORRECTED, img, wts);
 */
#ifndef NL_BYEXAMPLE_LEAK_H
#define NL_BYEXAMPLE_LEAK_H

#include "byexample/nl_byexample.h"

#ifdef __cplusplus
extern "C" {
#endif

enum { NL_BYEXAMPLE_EQ12, NL_BYEXAMPLE_EQ12_TAPER, NL_BYEXAMPLE_NNLS_RAW, NL_BYEXAMPLE_CORRECTED, NL_BYEXAMPLE_ESTIMATORS };
extern const char *const nl_byexample_estimator_names[NL_BYEXAMPLE_ESTIMATORS];

enum { NL_BYEXAMPLE_RAW = 0, NL_BYEXAMPLE_TAPER = 1 };   /* how band powers are measured */

typedef struct {
  int w, h, nbands, tile;
  double frac;     /* taper fraction of the tapered powers (1: Hann) */
  double sigma2;   /* eq. 12's sigma_N^2 (nl_byexample_sigma2(tile)) */
  /* A[taper][i * nbands + j]: power in band j from unit weight on band i */
  double A[2][NL_WAVELET_MAX_BANDS * NL_WAVELET_MAX_BANDS];
} nl_byexample_transfer;

/* Eq. 13 band powers of img, raw (frac 0: nl_byexample_band_power) or
 * tapered (nl_spectrum_taper2 with frac in (0, 1]; 1 is Hann). */
NL_MUST_CHECK nl_status nl_byexample_band_power_taper(const double *img, int w, int h, int nbands, double frac,
                                        double *power, nl_error *err);

/* Measures A (raw and tapered by frac) on w x h noise: replicate s seeds the tile
 * (period `tile`) and the band offsets from nl_seed_stream(seed,
 * "byexample.transfer", s), s < nseeds. The (replicate, band) renders run
 * on `threads` threads (nl_parallel_for; summed in order afterwards, so A
 * does not depend on the thread count). NL_EINVAL, nothing measured, for a
 * size nl_spectrum_check_size refuses: the functions taking T then never
 * transform a refused size. */
NL_MUST_CHECK nl_status nl_byexample_transfer_measure(nl_byexample_transfer *T, int tile, int w, int h, int nbands,
                                        double frac, int nseeds, unsigned long seed, int threads,
                                        nl_error *err);

/* The weights of estimator `kind` (NL_BYEX_*) from a T->w x T->h image. */
void nl_byexample_estimate(const nl_byexample_transfer *T, int kind, const double *img, double *wts);

/* Lawson-Hanson NNLS: x >= 0 minimising |M x - b|, M row-major m x n
 * (n <= NL_WAVELET_MAX_BANDS, m >= 1). Returns |M x - b| (the residual norm,
 * as scipy.optimize.nnls), or -1 if the iteration limit 3n was reached. */
double nl_byexample_nnls(const double *M, int m, int n, const double *b, double *x);

/* The range of a Fig. 4 trial's true band weights (uniform): the paper
 * does not say how it draws them. */
#define NL_BYEXAMPLE_TRUE_WEIGHT_MIN 0.1
#define NL_BYEXAMPLE_TRUE_WEIGHT_MAX 1.0

/* One Fig. 4 trial at T's size with every estimator: the tile t is seeded
 * with `seed`, true weights uniform in [NL_BYEXAMPLE_TRUE_WEIGHT_MIN,
 * NL_BYEXAMPLE_TRUE_WEIGHT_MAX] from nl_seed_stream(seed,
 * "byexample.true_weights", 0), band offsets from seed; img receives the
 * noise. est[kind * nbands + k]; err[kind] = |est - truth| / |truth|,
 * fine[kind] the same over bands k < nfine, power[kind] = sum est^2 / sum
 * truth^2. */
void nl_byexample_trial(const nl_byexample_transfer *T, nl_wavelet_tile *t, unsigned long seed, int nfine,
                        double *truth, double *est, double *img, double *err, double *fine, double *power);

/* n trials (nl_byexample_trial with seeds[k], each on its own tile of period
 * T->tile) into E[(c * NL_BYEXAMPLE_ESTIMATORS + kind) * n + k], c = 0 err, 1
 * fine, 2 power; per band (may be NULL) the RMS error rms[kind * nbands + k]
 * and mean error bias[...] over the trials. The trials run on `threads`
 * threads (nl_parallel_for; sums in trial order, so the results do not
 * depend on the thread count). */
void nl_byexample_trials(const nl_byexample_transfer *T, const unsigned long *seeds, int n,
                         int nfine, double *E, double *rms, double *bias, int threads);

/* How well weights reproduce an image's band powers: the band powers of the
 * noise of weights wts, averaged over nsyn syntheses (tile and offsets from
 * nl_seed_stream(seed, "byexample.resynth", s)), against the image's, both
 * measured raw (resid[NL_BYEXAMPLE_RAW]) and tapered (resid[NL_BYEXAMPLE_TAPER]): the
 * RMS over bands of (p_syn - p_img) / p_img (bands with p_img = 0 skipped). */
void nl_byexample_fit_residual(const nl_byexample_transfer *T, const double *wts, const double *img,
                               int nsyn, unsigned long seed, double resid[2]);

/* An image's fit by every estimator: A measured at the image's size
 * (nseeds noises from tseed), weights of each estimator, and their
 * nl_byexample_fit_residual (nsyn syntheses from rseed) into
 * resid[kind][taper]. Returns the band count, or -1 (nothing measured) for
 * a size nl_spectrum_check_size refuses. */
int nl_byexample_fit_all(const double *img, int w, int h, int tile, double frac, int nseeds, unsigned long tseed,
                         int nsyn, unsigned long rseed, double resid[NL_BYEXAMPLE_ESTIMATORS][2]);

/* Two-sided p-value of the paired t-test of a[i] - b[i], i < n (n >= 2;
 * 1 when every difference is 0). */
double nl_byexample_paired_p(const double *a, const double *b, int n);

#ifdef __cplusplus
}
#endif

#endif
