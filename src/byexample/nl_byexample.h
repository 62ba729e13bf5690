/* nl_byexample.h - procedural noise by example (Lagae, Vangorp, Lenaerts &
 * Dutre 2010): the weights of a multiresolution wavelet noise from an
 * exemplar's spectrum, and texture synthesis by analysis for isotropic
 * stochastic textures.
 *
 * Weights (sec. 4). Band i of an exemplar holds the Fourier coefficients whose
 * frequency (f_x, f_y), in cycles per pixel times 2 (Nyquist = 1), has
 *   i = int(min(log2 1/|f_x|, log2 1/|f_y|)) + 1                  (eq. 13)
 * i.e. max(|f_x|, |f_y|) in (2^-(i+1), 2^-i] cycles per pixel; the DC term
 * belongs to no band. Our band k = i - 1 (k = 0 finest), the index of
 * nl_wavelet_bands. With P_k the Parseval-normalised power of band k
 * (nl_spectrum_power2: the powers sum to the mean square minus the DC),
 *   w_k = sqrt(P_k / sigma_N^2)                                   (eq. 12)
 * where sigma_N^2 is the band variance of our wavelet noise, measured
 * (nl_byexample_sigma2), not the paper's 0.265. A 512 x 512 image has
 * floor(log2 512) = 9 bands (nl_byexample_band_count).
 *
 * Synthesis by analysis (sec. 5.3), per exemplar:
 *   analysis  1. PCA: mean and 3x3 orthonormal matrix M (rows = principal
 *                axes by decreasing variance, each oriented so its entries
 *                sum >= 0, the last flipped if needed so det M = +1: a
 *                rotation, which morphing interpolates as a quaternion);
 *                c = M (rgb - mean) (sec. 5.1);
 *             2. per channel, the inverse cumulative histogram sampled at
 *                p_j = j / 9, j = 0..9 (10 values, min to max), then a
 *                Gaussian histogram imposed by rank: c <- Phi^-1((r + 1/2)/n)
 *                (sec. 5.2);
 *             3. per channel, eq. 12-13 weights.
 *   synthesis 1. per channel, M_c(x) = sum_k w_k N(2^-k x + o_k);
 *             2. c = Q(Phi(M_c / sigma_M)), sigma_M^2 = sigma_N^2 sum_k w_k^2
 *                (eq. 14 prints sum w_i: for independent bands the variance
 *                adds the squares), Q the monotone cubic (GSL's steffen)
 *                through (p_j, hist_j);
 *             3. rgb = mean + M^T c.
 * Parameters: 9 (matrix) + 3 x 10 (histograms) + 3 x 9 (weights) = 66 for a
 * 512^2 RGB exemplar, as in the paper; we also keep the 3 means (needed
 * when histogram matching is off), sigma_N^2, the tile period and flags.
 * Grey images have 1 channel, M = [1]. Alpha is dropped.
 *
 * Histogram representations (nl_byexample_hist_kind). NL_HIST_PAPER is the
 * paper's reading above: 10 quantiles at p = j/9 and a cubic in p. Its knots
 * p = 1/9 and 8/9 are z = -/+1.22 sd from the median and the next ones are the
 * sample min and max, so the spline spreads the tails linearly in p out to the
 * extremes: a Gaussian channel matched to itself gets ~10x its tail mass
 * beyond 2.5 sd (L3's photos table measures it). NL_HIST_GAUSS stores 33
 * quantiles at p = Phi(z_j), z_j = -4 + j/4 (every quarter sd; p below
 * 0.5/n or above 1 - 0.5/n reads the min or max), and matches by a monotone
 * cubic in z: c = Q(M_c / sigma_M), no Phi step. A Gaussian channel is then a
 * straight line through the knots and comes back as itself, and the tails are
 * sampled where they are rather than between the 8/9 quantile and the max.
 *
 * Monotone splines: GSL's steffen (Steffen 1990) sets the slope at a knot
 * to (sign s_l + sign s_r) min(|s_l|, |s_r|, |p|/2), p the slope of the
 * parabola through the 3 knots: monotone, no overshoot, slope 0 at local
 * extrema, by construction. Fritsch & Carlson (1980), which the paper cites,
 * starts from other slopes (PCHIP's weighted harmonic mean, Fritsch-Butland
 * 1984) and limits them to their monotonicity region (alpha^2 + beta^2 <= 9).
 * Both are provided (nl_byexample_spline) so the difference can be measured.
 *
 * Calibrated synthesis (options.calibrate > 0; the `example` command's
 * default with NL_BYEXAMPLE_CALIBRATE rounds, gauss33; params file version 3;
 * not the paper's method). The paper's synthesis does not reproduce a
 * photo's per-octave power within x1.3 on the photos of data/exemplars (L3's
 * photos table: gauss33 and paper10 rows). Causes found by measurement:
 *  - per-band channel correlation: the PCA decorrelates the channels over all
 *    bands together, not per band; in `craters` the first two decorrelated
 *    channels correlate +0.81 in band 0 and -0.85 in band 5 (corr01 of its
 *    params file), so independent noise per channel changes the luminance
 *    power per band (the cross terms vanish);
 *  - synthesising larger than the photo adds noise bands coarser than the
 *    photo's lowest frequency (the wavelet's coarsest bands leak into them),
 *    power the photo does not have;
 *  - each wavelet noise band leaks power into its neighbouring eq. 13 bands and
 *    the histogram matching redistributes power across bands, so correcting
 *    each weight by its own band's ratio (multiplicative) converges slowly.
 * What it does. Analysis also stores, per channel, the eq. 13 band powers of
 * the decorrelated channel before gaussianisation (target), and for 3
 * channels the per-band correlation of each channel pair (corr01, corr02,
 * corr12; by polarisation, shrunk until each band's 3x3 matrix is positive
 * definite). Synthesis (2D, scale 1, histogram on) draws every channel's
 * noise bands B_k once (all of them held at the output size: an output whose
 * bands do not fit in the memory available is refused with NL_ENOMEM, never
 * synthesized uncalibrated); when the output is larger than the
 * photo, removes from the 3 coarsest bands the frequencies below the photo's
 * lowest band (and the DC); mixes each band across channels by the Cholesky
 * factor of its correlation; measures the leakage matrix A[k][j] = eq. 13
 * power of B_k in band j on this realisation; then `calibrate` rounds of: sum
 * with gains g, match the histogram by rank (Heeger & Bergen 1995), measure
 * the band powers P, and solve by NNLS A^T g^2 = target * S / P (S = A^T g^2,
 * the predicted power before matching): the gains the sum needs for the
 * matched image to land on the target. The last sum, matched, is the output.
 * The whole leakage matrix (not one ratio per band) is why a few rounds
 * suffice. `--no-calibration` (calibrate = 0) is the paper's synthesis and
 * writes version 2 files, unchanged. The result depends on the output size
 * and seed (calibrated on the realisation), and morphing keeps it only
 * between two calibrated files.
 *
 *   nl_byexample_params p;
 *   nl_byexample_analyse(img, NULL, &p, &err);          // defaults: PCA + histogram
 *   nl_byexample_params_save(&p, "wood.params", &err);
 *   nl_image *out;
 *   nl_byexample_synthesize(&p, 1024, 1024, seed, NULL, &out, &err);
 */
#ifndef NL_BYEXAMPLE_H
#define NL_BYEXAMPLE_H

#include "image/nl_image.h"
#include "wavelet/nl_wavelet.h"

#ifdef __cplusplus
extern "C" {
#endif

#define NL_BYEXAMPLE_HIST 10       /* the paper's reading: quantiles at p = j/9 */
#define NL_BYEXAMPLE_HIST_MAX 33   /* knots of the widest representation */
#define NL_BYEXAMPLE_TILE 256      /* default 2D tile period */
#define NL_BYEXAMPLE_TILE3 64      /* 3D tile period for solid synthesis */
#define NL_BYEXAMPLE_MIN_SIZE 16   /* smaller exemplars are rejected */
#define NL_BYEXAMPLE_CALIBRATE 4   /* the `example` command's calibration iterations */
/* What synthesis and morphing accept (nl_byexample_synth_check,
 * nl_byexample_morph_check): the `example` command's --size, --height,
 * --scale, --z and --t, and the Python binding, refuse the same values. */
#define NL_BYEXAMPLE_MAX_SIDE 32768    /* pixels per side of a synthesis */
#define NL_BYEXAMPLE_SCALE_MIN 1e-6    /* pixel size in exemplar pixels */
#define NL_BYEXAMPLE_SCALE_MAX 1e6
#define NL_BYEXAMPLE_Z_MAX 1e9         /* |z| of a solid slice */

typedef enum { NL_HIST_PAPER = 0, NL_HIST_GAUSS = 1 } nl_byexample_hist_kind;

typedef struct {
  int channels;                          /* 1 or 3 */
  int nbands;
  int tile;                              /* 2D tile period for synthesis */
  int histogram;                         /* 1: sec. 5.2 histogram matching */
  double sigma2;                         /* sigma_N^2 used by eq. 12 and 14 */
  double mean[3];
  double matrix[3][3];                   /* c = M (rgb - mean) */
  nl_byexample_hist_kind hist_kind;      /* which quantiles hist holds */
  int nhist;                             /* their count (nl_byexample_hist_knots) */
  double hist[3][NL_BYEXAMPLE_HIST_MAX];   /* channel quantiles at the kind's knots */
  double w[3][NL_WAVELET_MAX_BANDS];     /* w[c][0]: finest band */
  int calibrate;                         /* > 0: iterations of the synthesis-time calibration */
  double target[3][NL_WAVELET_MAX_BANDS];   /* with calibrate: eq. 13 band powers of channel c */
  double corr[3][NL_WAVELET_MAX_BANDS];     /* with calibrate: band correlation of channels 01, 02, 12 */
} nl_byexample_params;

typedef struct {
  int decorrelate;    /* PCA (1) or plain RGB channels (0) */
  int histogram;      /* histogram matching (1) or Gaussian noise as is (0) */
  double sigma2;      /* 0: nl_byexample_sigma2(tile) */
  int tile;           /* 0: NL_BYEXAMPLE_TILE */
  nl_byexample_hist_kind hist_kind;   /* 0: the paper's 10 quantiles */
  int calibrate;      /* 0: the paper; > 0: store band targets, calibrate in synthesis (NL_BYEXAMPLE_CALIBRATE) */
} nl_byexample_options;

typedef enum { NL_SPLINE_STEFFEN = 0, NL_SPLINE_FRITSCH_CARLSON = 1 } nl_byexample_spline_kind;

typedef struct {
  double scale;       /* pixel size in exemplar pixels, NL_BYEXAMPLE_SCALE_MIN..MAX */
  int solid;          /* 1: slice z of 3D wavelet noise (solid extrapolation) */
  double z;
  nl_byexample_spline_kind spline;
} nl_byexample_synth_options;

/* ---- noise by example (sec. 4) ---------------------------------------- */

int nl_byexample_band_count(int w, int h);
/* power[k], k < nbands: eq. 13 band power of a w x h image (DC excluded).
 * These and the functions below that transform an image return NL_EINVAL
 * (NULL for an image) for a size nl_spectrum_check_size refuses. */
NL_MUST_CHECK nl_status nl_byexample_band_power(const double *img, int w, int h, int nbands, double *power,
                                  nl_error *err);
/* Eq. 12. */
NL_MUST_CHECK nl_status nl_byexample_weights(const double *img, int w, int h, int nbands, double sigma2, double *wts,
                               nl_error *err);
/* How single wavelet-noise bands spread over eq. 13's bands: for k <
 * nbands, a size x size image of N(2^-k x + o_k) (offsets from seed) has
 * total power var[k] (DC excluded), of which share[k * nbands + j] falls
 * in band j. Ideal orthogonal bands (eq. 7) would give the identity. */
NL_MUST_CHECK nl_status nl_byexample_band_leakage(const nl_wavelet_tile *t, int size, int nbands, unsigned long seed,
                                    double *share, double *var, nl_error *err);
/* Band variance of our 2D wavelet noise for tile period n: the mean of
 * nl_wavelet_tile_variance(t, 4) over tiles seeded 1..4 (cached). */
double nl_byexample_sigma2(int n);

/* ---- colour and histograms (sec. 5.1-5.2) ----------------------------- */

/* Mean and PCA matrix of the first min(3, channels) channels. */
nl_status nl_byexample_pca(const nl_image *im, double mean[3], double matrix[3][3], nl_error *err);
/* plane[c][i] = (M (px_i - mean))_c for nch channels; inverse of recorrelate. */
void nl_byexample_decorrelate(const nl_image *im, int nch, const double mean[3],
                              const double matrix[3][3], double **plane);
void nl_byexample_recorrelate(double *const *plane, int nch, const double mean[3],
                              const double matrix[3][3], nl_image *out);
/* q[j] = quantile of v at p = j/(NL_BYEXAMPLE_HIST-1), linear between order statistics. */
void nl_byexample_quantiles(const double *v, size_t n, double *q);
/* v <- Phi^-1((rank + 1/2) / n), ties in index order. */
void nl_byexample_gaussianize(double *v, size_t n);
/* v <- Q(Phi(v / sigma)), Q the monotone cubic through (j/9, q[j]). */
void nl_byexample_match(double *v, size_t n, double sigma, const double *q, nl_byexample_spline_kind kind);
/* The knots of a representation: x[j] (p = j/9 for NL_HIST_PAPER, z = -4 + j/4
 * for NL_HIST_GAUSS) and the probability p[j] of each (either may be NULL);
 * returns the count (10 or 33), 0 for an unknown kind. */
int nl_byexample_hist_knots(nl_byexample_hist_kind kind, double *x, double *p);
/* q[j] = quantile of v at the kind's probabilities p[j] (as nl_byexample_quantiles). */
void nl_byexample_hist(const double *v, size_t n, nl_byexample_hist_kind kind, double *q);
/* Histogram matching by the kind's reading: NL_HIST_PAPER is nl_byexample_match;
 * NL_HIST_GAUSS is v <- Q(v / sigma), Q the monotone cubic through (z_j, q[j]). */
void nl_byexample_match_kind(double *v, size_t n, double sigma, nl_byexample_hist_kind hk, const double *q,
                             nl_byexample_spline_kind kind);
const char *nl_byexample_hist_name(nl_byexample_hist_kind kind);   /* "paper10", "gauss33" */
/* The monotone cubic through (x[j], y[j]), j < n, x increasing, at xs[i]. */
void nl_byexample_spline(const double *x, const double *y, int n, nl_byexample_spline_kind kind,
                         const double *xs, double *ys, size_t m);

/* ---- analysis, synthesis, parameters ---------------------------------- */

nl_status nl_byexample_analyse(const nl_image *im, const nl_byexample_options *opt,
                               nl_byexample_params *p, nl_error *err);
nl_status nl_byexample_synthesize(const nl_byexample_params *p, int w, int h, unsigned long seed,
                                  const nl_byexample_synth_options *opt, nl_image **out,
                                  nl_error *err);
/* nl_byexample_synthesize refuses (NL_EINVAL, naming the input as the
 * command line spells it: "--size: 0 is outside [1, 32768]") a side outside
 * 1..NL_BYEXAMPLE_MAX_SIDE and options that nl_byexample_synth_check
 * refuses. That check, which the `example` command also calls before it
 * reads a file: with opt (NULL: scale 1, plane z = 0) a finite scale in
 * [NL_BYEXAMPLE_SCALE_MIN, NL_BYEXAMPLE_SCALE_MAX] and a finite z,
 * |z| <= NL_BYEXAMPLE_Z_MAX. A NaN scale would make every pixel NaN, an
 * infinite one a constant image, 0 or a negative one a degenerate or
 * mirrored grid ("--scale: nan is not a finite number"). */
nl_status nl_byexample_synth_check(const nl_byexample_synth_options *opt, nl_error *err);
/* One decorrelated channel, before histogram matching and recorrelation:
 * the multiresolution noise of weights gain * w[c], offsets from seed and c. */
void nl_byexample_channel_noise(const nl_byexample_params *p, int c, const nl_wavelet_tile *t,
                                double gain, int w, int h, unsigned long seed,
                                const nl_byexample_synth_options *opt, double *out);
/* The lower Cholesky factor of band k's channel correlation matrix (corr);
 * 1 if it is not positive definite. */
int nl_byexample_band_cholesky(const nl_byexample_params *p, int k, double L[3][3]);
/* The number of parameters the paper counts: channels^2 + channels * (nhist + bands). */
int nl_byexample_param_count(const nl_byexample_params *p);

nl_status nl_byexample_params_save(const nl_byexample_params *p, const char *path, nl_error *err);
nl_status nl_byexample_params_load(const char *path, nl_byexample_params *p, nl_error *err);

/* Everything linear except the matrix, which follows the quaternion slerp
 * between the two rotations (the paper's Fig. 12). Exemplars of different
 * sizes have different band counts; band k is the same scale (2^k pixels,
 * k = 0 finest) in both, so the result keeps the bands both have, and the
 * larger exemplar's coarsest bands are dropped (out->nbands is the smaller
 * count). Errors on different channel counts, histogram kinds or one
 * calibrated file and one not, and on a t that nl_byexample_morph_check
 * refuses. */
nl_status nl_byexample_morph(const nl_byexample_params *a, const nl_byexample_params *b, double t,
                             nl_byexample_params *out, nl_error *err);
/* t finite in [0, 1]: outside, the linear parts extrapolate (negative
 * weights, histograms out of order) and the slerp leaves the arc between
 * the two rotations; NaN makes every parameter NaN. NL_EINVAL, "--t: ...". */
nl_status nl_byexample_morph_check(double t, nl_error *err);
/* Frequency-based editing (Fig. 10c): w[c][k] *= factor for the `nfine`
 * finest bands of every channel. */
void nl_byexample_attenuate(nl_byexample_params *p, int nfine, double factor);

/* Pearson correlation between the first min(3, channels) channels (1 on the
 * diagonal; 0 where a channel is constant): the colour statistics that
 * independent RGB synthesis loses (Fig. 5). */
void nl_byexample_correlation(const nl_image *im, double corr[3][3]);
/* Channel c of an image as doubles (n = width * height values). */
void nl_byexample_channel(const nl_image *im, int c, double *out);
/* The image's luminance (nl_image_convert to one channel) as doubles. */
void nl_byexample_luminance(const nl_image *im, double *out);
/* Largest |difference| of the off-diagonal colour correlations of a and b
 * (nl_byexample_correlation): what independent RGB synthesis loses (Fig. 5). */
double nl_byexample_correlation_error(const nl_image *a, const nl_image *b);
/* det M and max |M M^T - I| of a 3 x 3 matrix: how far a morphed PCA
 * matrix is from a rotation (Fig. 12). */
void nl_byexample_rotation_error(const double M[3][3], double *det, double *orth);

/* log10 of the power spectrum (nl_spectrum_power2), DC at the centre, mapped from
 * [max - decades, max] to [0, 1]: a grey picture of a spectrum. */
nl_image *nl_byexample_spectrum_image(const double *img, int w, int h, double decades, nl_error *err);

/* ---- measures of a synthesis against its exemplar (L3's photos table) --- */

/* The fraction of x's values farther than k sd of ref from ref's mean (ref =
 * x for x's own tails; ref = the exemplar for a synthesis, so a widened
 * spread counts as tail mass). */
double nl_byexample_tail_mass(const double *x, size_t n, const double *ref, size_t nref, double k);
/* Saturation of a pixel: (max - min) / max of its R, G, B (0 for black or grey). */
double nl_byexample_saturation(const float *px, int channels);
/* Colour speckle: the fraction of syn's pixels more saturated than the
 * exemplar's 99th percentile of saturation (1% for a faithful synthesis). */
double nl_byexample_speckle(const nl_image *ex, const nl_image *syn);

/* Procedural exemplars for experiments and tests (photographs are in
 * data/exemplars; these are made on the fly with known statistics):
 * "wavelet" (coloured multiresolution noise, Gaussian histogram), "clouds"
 * (fBm through a sky ramp, clipped: skewed histogram), "granite"
 * (turbulence, 3 colours), "marble" (stripes: anisotropic, a failure case).
 * NULL for an unknown kind. */
nl_image *nl_byexample_exemplar(const char *kind, int size, unsigned long seed);

#ifdef __cplusplus
}
#endif

#endif
