/* nl_wavelet.h - wavelet noise (Cook & DeRose 2005) and multiresolution
 * sums of it (Lagae et al. 2010 eq. 1-2).
 *
 * A tile is an n^d array (d = 2 or 3, n even) of noise coefficients made
 * once from a seed, as in Cook & DeRose's appendix:
 *   1. fill with unit Gaussian values (GSL MT19937 + ziggurat);
 *   2. along each axis, downsample (32-tap analysis filter) and upsample
 *      (filter 1/4 3/4 3/4 1/4): the coarse-scale part of the tile;
 *   3. subtract it, which leaves the finest octave;
 *   4. add a copy shifted by an odd offset (n/2, made odd) along every axis,
 *      so that even and odd lattice points get the same variance.
 * Evaluation is a quadratic B-spline through the 3^d nearest coefficients
 * (periodic: the noise tiles with period n on every axis):
 *   N(p) = sum_{f in {-1,0,1}^d} prod_axis w_axis[f] * tile[mid + f],
 *   mid = ceil(p - 1/2), t = mid - (p - 1/2), w = {t^2/2, 1 - ..., (1-t)^2/2}.
 * The noise is band limited to about 1/4 .. 1/2 cycles per unit.
 *
 * Corrections to the appendix's code, on purpose:
 *  - its downsampling loop runs k <= 2i + 16 and reads one coefficient past
 *    the 32-entry array; we run k < 2i + 16 (the 32 taps -16..15), as
 *    Blender's port does;
 *  - the printed filter is not exactly symmetric (0.003545 vs 0.003546); we
 *    use the first 16 values mirrored;
 *  - its odd-shift loop writes temp[ix*n*n + iy*n + iz] from
 *    noise[(ix+o) + (iy+o)*n + (iz+o)*n*n], i.e. a transposed copy; we add
 *    the copy shifted along each axis without transposing.
 *
 *   nl_wavelet_tile *t = nl_wavelet_tile_alloc(2, 256);
 *   nl_wavelet_tile_seed(t, 1);
 *   double v = nl_wavelet_eval2(t, 3.7, 12.1);
 *
 * Multiresolution noise (nl_wavelet_bands): B bands, band k (k = 0 finest)
 *   M(x) = sum_k w[k] N(2^-k s x + o_k)
 * for pixel coordinates x (pixel centres, s = scale, 1 by default): band 0
 * puts the noise's octave at 1/4 .. 1/2 cycles per pixel, band k at
 * 2^-(k+2) .. 2^-(k+1), which is Lagae's eq. 13 band i = k + 1. (Their eq. 2
 * numbers bands the other way, coarsest first; the sum is the same.) The
 * offsets o_k are uniform in [0, n) per axis, from a seed, and decorrelate
 * the bands (eq. 2). Typical start: 256^2 tile in 2D, 64^3 in 3D, 9 bands for
 * 512^2 images, w[k] = 2^(k/2) for a 1/f^2-like spectrum.
 *
 * Variance: a tile's band variance sigma_N^2 = <N^2> over positions is
 * measured by nl_wavelet_tile_variance (the mean of N^2 on a grid of
 * `per_unit` samples per unit and axis, over one period): ~0.275 in 2D and
 * ~0.195 in 3D here (L1). Lagae et al. quote
 * 0.265; Cook & DeRose's code normalises with 0.296 and 0.210. The sum of
 * bands has variance sigma_N^2 sum_k w[k]^2 when the bands are orthogonal.
 */
#ifndef NL_WAVELET_H
#define NL_WAVELET_H

#include "base/nl_base.h"
#include "noise/nl_noise.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  int dim;        /* 2 or 3 */
  int n;          /* period per axis, even */
  float *data;    /* n^dim coefficients, x fastest */
} nl_wavelet_tile;

/* n even and >= 8 (the analysis filter spans 32 taps, so tiles below 32
 * wrap it: allowed, but not the noise of the paper). NULL on bad arguments. */
nl_wavelet_tile *nl_wavelet_tile_alloc(int dim, int n);
void nl_wavelet_tile_free(nl_wavelet_tile *t);
/* Steps 1-4 above; the same seed gives the same tile bit for bit. */
void nl_wavelet_tile_seed(nl_wavelet_tile *t, unsigned long seed);
/* The same with the appendix's odd-shift loop taken literally: the copy added
 * in step 4 is shifted and transposed (x and z exchanged; x and y in 2D). */
void nl_wavelet_tile_seed_transposed(nl_wavelet_tile *t, unsigned long seed);

/* Steps 2-3 on one line of n values (stride apart): the coarse part, i.e.
 * upsample(downsample(line)), written to coarse (stride 1). Exposed for tests:
 * a constant line is reproduced (the filters preserve DC). */
void nl_wavelet_coarse_line(const float *line, size_t stride, int n, double *coarse);

double nl_wavelet_eval2(const nl_wavelet_tile *t, double x, double y);
double nl_wavelet_eval3(const nl_wavelet_tile *t, double x, double y, double z);
/* out[k] = nl_wavelet_eval3(t, x[k], y[k], z[k]) (2D tiles: eval2; z may be
 * NULL), k < n: arbitrary points in one call. */
void nl_wavelet_points(const nl_wavelet_tile *t, const double *x, const double *y, const double *z,
                       size_t n, double *out);
/* out[k] += weight * N(x0 + k dx, y[, z]), k < count. 2D tiles ignore z. */
void nl_wavelet_row(const nl_wavelet_tile *t, double x0, double dx, double y, double z,
                    size_t count, double weight, double *out);

/* The tile as a basis for sums of octaves and rendering (nl_noise.h). Its
 * bound is max |coefficient|: quadratic B-spline weights are non-negative
 * and sum to 1. The tile must outlive the basis. */
nl_noise_basis nl_wavelet_basis(const nl_wavelet_tile *t);

/* <N^2> on a grid of per_unit samples per unit and axis over one period
 * (midpoints, (i + 1/2) / per_unit). Wavelet noise is not stationary: its
 * variance depends on the position inside the lattice cell (at lattice
 * points the B-spline weights 1/8 3/4 1/8 keep more variance than 1/2 1/2
 * at half-integers), so per_unit must sample the cell: 4 is within 0.1% of
 * the continuous mean, 1 samples only half-integers and is ~35% low. */
double nl_wavelet_tile_variance(const nl_wavelet_tile *t, int per_unit);
/* Readings of sigma_N^2 other than the volume mean (L1 measures which one
 * Cook & DeRose's 0.210 is):
 *  slice      <N^2> on the plane z (3D; 2D tiles ignore z), per_unit samples
 *             per unit on x and y over one period; *mean (if not NULL) gets <N>;
 *  point      <N^2> at `count` uniform random points of the period (seed);
 *  multiband  Cook & DeRose's WMultibandNoise with w_b = 1 and no per-band
 *             offsets: <(sum_{b < nbands} N(2^-b p))^2> / nbands on the plane
 *             z, p on the slice grid: the cross-band covariance of one tile
 *             included. */
double nl_wavelet_slice_variance(const nl_wavelet_tile *t, double z, int per_unit, double *mean);
double nl_wavelet_point_variance(const nl_wavelet_tile *t, size_t count, unsigned long seed);
double nl_wavelet_multiband_variance(const nl_wavelet_tile *t, int nbands, double z, int per_unit);
/* <N^2> over the lattice shifted by frac on every axis: (i + frac, j + frac). */
double nl_wavelet_lattice_variance(const nl_wavelet_tile *t, double frac);

/* ---- multiresolution noise ------------------------------------------ */

#define NL_WAVELET_MAX_BANDS 16

typedef struct {
  int nbands;
  double w[NL_WAVELET_MAX_BANDS];        /* w[0]: finest band */
  double off[NL_WAVELET_MAX_BANDS][3];   /* per-band offsets, tile units */
} nl_wavelet_bands;

/* nbands weights (1..NL_WAVELET_MAX_BANDS) and offsets drawn from seed
 * for a tile of period n. Returns NL_EINVAL on a bad band count. */
nl_status nl_wavelet_bands_init(nl_wavelet_bands *b, int nbands, const double *w,
                                int n, unsigned long seed, nl_error *err);

/* A w x h image of M at pixel centres, plane z (ignored by 2D tiles):
 * out[y*w + x] = sum_k b->w[k] N(2^-k scale (x + 1/2, y + 1/2, z) + o_k). */
void nl_wavelet_bands_grid(const nl_wavelet_tile *t, const nl_wavelet_bands *b, int w, int h,
                           double z, double scale, double *out);

#ifdef __cplusplus
}
#endif

#endif
