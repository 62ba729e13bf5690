/* nl_bounds.h - Arnerin 2009: bounds of fractal noise, incremental bounding
 * in a ray-marcher, and the spectral bandwidth [F_inf, F_sup] of a 1D signal.
 *
 * Octave and fractal bounds (chapter 4.2.1). With |noise| <= 1 the i-th
 * octave b_i(x) = noise(2^i x) / 2^i obeys |b_i| <= 2^-i (eq. 4.1), and the
 * fractal sum of n octaves, i = 0..n-1, obeys |Fnoise_n| <= S_{n-1} (eq. 4.2)
 * with S_n = 2 - 2^-n, the sum of 2^-i for i = 0..n:
 *   nl_bounds_octave(i) = 2^-i,  nl_bounds_series(n) = S_n,
 *   nl_bounds_fractal(n) = S_{n-1}  (0 for n = 0).
 * Perlin's improved 3D noise does not satisfy |noise| <= 1 (its analytic bound
 * is NL_NOISE3_BOUND ~ 1.2247, observed maxima are near 1.03), so the general
 * functions take the basis bound B and any nl_noise_octaves:
 *   nl_bounds_remainders(o, B, rem)   rem[k] = B sum_{l >= k} |amp_l|, k = 0..n
 * rem[0] is the fractal bound, rem[n] = 0.
 *
 * Incremental bounding (chapter 5.1, eq. 5.1-5.4). After the first k terms
 * of the sum have been added into `partial`, the full sum lies in
 * [partial - rem[k], partial + rem[k]] (eq. 5.4 written as an interval; the
 * paper's |Fnoise_n + S_{Nmax-1} - S_n| is its upper end). If a pattern is
 * constant on that interval, the remaining terms need not be evaluated.
 * nl_bounds_clamped_fractal() evaluates CLAMP(base + Fnoise(p)) this way;
 * with incremental = 0 it evaluates every term and clamps, so both results
 * are identical whenever the bound B holds (same additions in the same order).
 *
 * The smoke ball (Table 5.1, Fig. 5.1-5.3). Density
 *   distNoise(p) = CLAMP(a |p| + 1 + Fnoise(f0 p)),  a < 0,
 * in the unit cube [-1/2, 1/2]^3, viewed orthographically along +z; each
 * pixel marches from z = -1/2 with step h and absorbs by Beer-Lambert,
 *   T <- T exp(-kappa density h),  colour += (T_before - T_after) (white smoke),
 * and stops when the opacity 1 - T reaches stop_opacity (0.99) or the ray
 * leaves the cube. nl_bounds_smoke_render() fills a w x h grey image in
 * [0, 1] and counts samples and noise evaluations;
 * nl_bounds_smoke_decision_map() is Fig. 5.3: in the plane z, how many
 * terms were evaluated before the value was decided (n + 1 = never
 * decided: the pixel needs the whole sum). The render marches blocks of
 * rays in step and sends each octave of their samples through
 * nl_noise_perm3_points_sum, or with incremental bounding through
 * nl_noise_perm3_points_bounded (term, eq. 5.4 check and packing of the
 * undecided in one pass, still per sample): the images, counts and max
 * |noise| are the bits of a ray-by-ray march.
 *
 *   nl_bounds_smoke s = nl_bounds_smoke_default();   // 512 x 512, step 0.01, 99 %
 *   s.octaves = 11; s.incremental = 1;
 *   nl_bounds_smoke_stats st;
 *   nl_bounds_smoke_render(&perm, &s, img, &st, &err);
 *
 * Spectral bandwidth (chapter 5.2). For samples x[0..n-1] at `rate` samples
 * per unit: the one-sided periodogram P[k] at f[k] = k rate / n, k = 0..n/2,
 * scaled so sum_k P[k] = mean(x^2) (Parseval, eq. 4.4; P[0] = mean^2), the
 * tail energy Gamma(f[k]) = sum_{j >= k} P[j] (the integral from lambda up,
 * lambda's own bin included), and its inverse Gamma^-1(E) = the smallest f[k]
 * with Gamma(f[k]) <= E. Then, with T = (2/255)^2 and sigma the standard
 * deviation of x,
 *   F_sup = Gamma^-1(T),   F_inf = Gamma^-1((sigma - sqrt T)^2).
 * The paper's remark "int(PSD) = mean^2 + var" allows a second reading with
 * sigma = sqrt(mean^2 + var), the RMS (f_inf_rms): with a mean far from 0
 * (a shader storing (noise + 1)/2) it puts F_inf on the first bin.
 * The frequency resolution is rate / n = 1 / (length in units): the paper's
 * F_inf = 0.0019531 = 1/512 suggests 512 units.
 *
 *   nl_bounds_bandwidth bw;
 *   nl_bounds_bandwidth_1d(x, n, rate, NL_BOUNDS_T, &bw, &err);   // bw.f_inf, bw.f_sup
 *
 * nl_bounds_sample_line() gives such a sample of a fractal sum of improved
 * noise along a line, point by point (any direction, so the 256-periodicity
 * of the noise along an axis can be avoided). The paper says neither which
 * line nor how long: the caller chooses both.
 */
#ifndef NL_BOUNDS_H
#define NL_BOUNDS_H

#include "base/nl_base.h"
#include "noise/nl_noise.h"
#include "spectrum/nl_spectrum.h"   /* nl_spectrum_psd1: bounds sits above spectrum */

#ifdef __cplusplus
extern "C" {
#endif

/* ---- fractal bounds (eq. 4.1-4.3) ------------------------------------ */

double nl_bounds_octave(int i);      /* 2^-i */
double nl_bounds_series(int n);      /* S_n = 2 - 2^-n */
double nl_bounds_fractal(int n);     /* S_{n-1}: bound of an n-octave sum */
/* rem[k] = basis_bound * sum_{l=k}^{n-1} |amp_l| for k = 0..o->n; rem holds n + 1. */
void nl_bounds_remainders(const nl_noise_octaves *o, double basis_bound, double *rem);

/* ---- incremental bounding (eq. 5.1-5.4) ------------------------------ */

typedef struct { double lo, hi; } nl_bounds_interval;
/* Where the full sum can still go: [partial - remainder, partial + remainder]. */
nl_bounds_interval nl_bounds_incremental(double partial, double remainder);

/* CLAMP(base + sum_l amp_l noise(freq_l p)) to [0, 1]. rem from
 * nl_bounds_remainders. incremental: stop once eq. 5.4 decides the clamp.
 * *terms (may be NULL) receives the number of noise evaluations; *max_abs
 * (may be NULL) is raised to the largest |noise| seen. */
double nl_bounds_clamped_fractal(const nl_noise_perm3 *p, const nl_noise_octaves *o,
                                 const double *rem, double base, const double *xyz, int incremental,
                                 int *terms, double *max_abs);

/* Checks eq. 4.2 and 5.4 on npoints points uniform in [-100, 100)^3 (MT19937
 * from seed): the largest |Fnoise| and |noise| seen, and how many points
 * leave the fractal bound rem[0] or, for some k, the incremental interval
 * [partial_k - rem[k], partial_k + rem[k]] (rem from basis_bound). */
typedef struct {
  long points;
  double max_abs_sum, max_abs_noise;
  long over_fractal, over_incremental;
} nl_bounds_check;
void nl_bounds_check_random(const nl_noise_perm3 *p, const nl_noise_octaves *o, double basis_bound,
                            long npoints, unsigned long seed, nl_bounds_check *out);

/* ---- the smoke ball (Table 5.1, Fig. 5.1-5.3) ------------------------ */

typedef struct {
  int width, height;     /* 512 x 512 in the paper */
  double step;           /* integration step h, 0.01 */
  double stop_opacity;   /* 0.99 */
  double slope;          /* a < 0 in CLAMP(a d + 1 + Fnoise) */
  double freq;           /* f0, frequency of the first octave */
  double kappa;          /* extinction per unit density and unit length */
  double octave_bound;   /* assumed sup |noise| per octave (Arnerin: 1) */
  int octaves;           /* number of terms of Fnoise, 0..NL_MAX_OCTAVES */
  int incremental;       /* 1: incremental bounding */
} nl_bounds_smoke;

typedef struct {
  long samples;          /* density evaluations */
  long noise_evals;      /* noise() calls */
  double max_abs_noise;  /* largest |noise| over those calls */
} nl_bounds_smoke_stats;

/* The paper's 512 x 512, step 0.01, stop at 99 %; slope -4, f0 = 4,
 * kappa = 30 (the paper gives none of these three: A2 fits them),
 * octave_bound = NL_NOISE3_BOUND, 1 octave, plain evaluation. */
nl_bounds_smoke nl_bounds_smoke_default(void);
/* img: width * height doubles, row 0 at y = -1/2. */
nl_status nl_bounds_smoke_render(const nl_noise_perm3 *p, const nl_bounds_smoke *s, double *img,
                                 nl_bounds_smoke_stats *st, nl_error *err);
/* Fig. 5.3: terms[y * width + x] = number of terms evaluated before the
 * incremental bound decided the density in the plane z; octaves + 1 when
 * it never did. */
nl_status nl_bounds_smoke_decision_map(const nl_noise_perm3 *p, const nl_bounds_smoke *s, double z,
                                       int *terms, nl_error *err);

/* ---- spectral bandwidth (sec. 4.2.2, 5.2) ---------------------------- */

#define NL_BOUNDS_T (4.0 / (255.0 * 255.0))   /* (2/255)^2 */

/* The one-sided PSD of a line sample is nl_spectrum_psd1 (spectrum/nl_spectrum.h):
 * every FFT of the project is wrapped once, in the spectrum module. */
/* gamma[k] = sum_{j >= k} P[j], k < m. */
void nl_bounds_psd1_tail(const double *P, size_t m, double *gamma);
/* Smallest f[k] with gamma[k] <= e (f[m-1] if none). */
double nl_bounds_psd1_tail_inverse(const double *f, const double *gamma, size_t m, double e);

typedef struct {
  double f_inf, f_sup;   /* the relevant band */
  double f_inf_rms;      /* F_inf with sigma = RMS instead of sd */
  double mean, sigma;    /* of the sample */
  double resolution;     /* rate / n */
  double nyquist;        /* rate / 2 */
} nl_bounds_bandwidth;
nl_status nl_bounds_bandwidth_1d(const double *x, size_t n, double rate, double T,
                                 nl_bounds_bandwidth *bw, nl_error *err);
/* The estimator's readings where the paper leaves them open (sec. 5.2.2;
 * A3 sweeps them): all 0 is nl_bounds_bandwidth_1d bit for bit.
 *   window       NL_SPECTRUM_RECT (none) or NL_SPECTRUM_HANN
 *   two_sided    Gamma integrates the positive half of the two-sided PSD
 *                (half the energy of each f > 0)
 *   sigma_rms    sigma of F_inf is the RMS (the DC in sigma), not the sd
 *   no_dc        the DC bin left out of Gamma
 *   bin_edge     a bin's frequency is its lower edge f - res/2, not its centre
 *   radians      frequencies times 2 pi
 *   nl_bounds_bandwidth_options o = {.window = NL_SPECTRUM_HANN, .two_sided = 1};
 *   nl_bounds_bandwidth_1d_with(x, n, rate, NL_BOUNDS_T, &o, &bw, &err); */
typedef struct {
  int window, two_sided, sigma_rms, no_dc, bin_edge, radians;
} nl_bounds_bandwidth_options;
nl_status nl_bounds_bandwidth_1d_with(const double *x, size_t n, double rate, double T,
                                      const nl_bounds_bandwidth_options *o,
                                      nl_bounds_bandwidth *bw, nl_error *err);
/* The mean and the sigma of F_inf: sigma^2 = sum_k (x[k] - mean)^2 / n (over
 * n, not n - 1), both summed in index order (the bits of
 * nl_bounds_bandwidth_1d's bw->mean and bw->sigma). For an estimator that
 * builds its own PSD and Gamma from nl_bounds_psd1_tail. */
void nl_bounds_moments(const double *x, size_t n, double *mean, double *sigma);
/* Energy above frequency f as a fraction of the variance: what aliases
 * when the signal is sampled with Nyquist frequency f. */
nl_status nl_bounds_psd1_fraction_above(const double *x, size_t n, double rate, double f,
                                        double *fraction, nl_error *err);

/* out[k] = sum_l amp_l noise(freq_l (origin + (k / rate) dir)), k < n. */
void nl_bounds_sample_line(const nl_noise_perm3 *p, const nl_noise_octaves *o,
                           const double *origin, const double *dir, double rate, size_t n,
                           double *out);

#ifdef __cplusplus
}
#endif

#endif
