/* nl_spectrum.h - 2D discrete Fourier transforms of images and their power
 * spectra, on GSL's mixed-radix FFT (any size, not only powers of two).
 *
 *   nl_spectrum_fft2(img, w, h, F, err)  F[2*(v*w + u) + {0,1}] = sum_xy img[y*w+x] e^{-2 pi i (ux/w + vy/h)}
 *   nl_spectrum_fft2_inverse(F, w, h, img, err)   the inverse, including the 1/(w h)
 *   nl_spectrum_power2(img, w, h, P, err) P[v*w+u] = |F|^2 / (w h)^2, so sum P = mean(img^2)
 *                               (Parseval); the DC term is P[0]
 *   nl_spectrum_radial(img, w, h, nbins, f, p, err)
 *       radially averaged power: bin b covers |k| in [b, b+1) * 0.5/nbins
 *       cycles per pixel (k folded to [-1/2, 1/2) per axis); f[b] is the
 *       bin centre, p[b] the mean of P over the bin's frequencies (0 if none).
 *       Frequencies past the Nyquist circle (corners) are not counted.
 * Frequencies are in cycles per pixel; multiply by the sampling rate for
 * cycles per unit. Each returns NL_EINVAL (err says why) for a size
 * nl_spectrum_check_size refuses, before any work.
 *
 * 1D (Arnerin's bandwidth, bounds/, and anything else sampled on a line):
 *   nl_spectrum_psd1(x, n, rate, f, P, err)
 *       one-sided power spectrum of n real samples taken at `rate` per unit
 *       (GSL's real mixed-radix FFT): f[k] = k rate / n cycles per unit and
 *       P[k] = |X_k|^2 / n^2, doubled for 0 < k < n/2 (folded to one side),
 *       k = 0..n/2, so that sum P = mean(x^2) (Parseval, Arnerin eq. 4.4).
 *   nl_spectrum_psd1_window(x, n, rate, window, f, P, err)
 *       the same with the samples multiplied by a window first:
 *       NL_SPECTRUM_RECT (none: nl_spectrum_psd1's bits) or NL_SPECTRUM_HANN
 *       (periodic Hann, w_j = (1 - cos(2 pi j / n)) / 2), divided by mean(w^2)
 *       = 3/8 so that sum P is still mean(x^2) for a stationary signal; the
 *       window trades the rectangular window's leakage (a tail ~ f^-2 from
 *       the jump between the ends) for a main lobe three bins wide.
 */
#ifndef NL_SPECTRUM_H
#define NL_SPECTRUM_H

#include "base/nl_base.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A plan for w x h real images: twiddles and buffers allocated once per
 * size, for transforming many images (GSL style: _alloc, use, _free).
 * nl_spectrum_rfft2 writes the half spectrum, numpy's rfft2 layout:
 * H[2*(v*(w/2+1) + u) + {0,1}] = F(u, v) for u = 0..w/2 (the rest is
 * F(u, v) = conj F(w-u, h-v)). Power-of-two sides take a real-input
 * radix-4 path (rows in pairs as one complex sequence, then only the
 * w/2+1 columns, gathered a block at a time); other sizes GSL's mixed-radix
 * complex transform, whose bits nl_spectrum_fft2 keeps for them. A plan is
 * not shared between threads (it holds work buffers).
 *
 * Every 2D transform goes through nl_spectrum_check_size (below): the plan
 * allocator returns NULL and the others NL_EINVAL, with its message, for a
 * size it refuses, before any work; a caller cannot skip it. */
typedef struct nl_spectrum_fft2_plan nl_spectrum_fft2_plan;
nl_spectrum_fft2_plan *nl_spectrum_fft2_plan_alloc(int w, int h, nl_error *err);
void nl_spectrum_fft2_plan_free(nl_spectrum_fft2_plan *p);
void nl_spectrum_rfft2(nl_spectrum_fft2_plan *p, const double *img, double *H);
NL_MUST_CHECK nl_status nl_spectrum_fft2(const double *img, int w, int h, double *F, nl_error *err);
/* The work of one 2D transform of a w x h image, in complex multiply-adds,
 * about: GSL's mixed-radix transform of length n costs n times the sum of
 * n's prime factors (a prime p beyond 7 is a general O(p) pass per output),
 * so a prime side is O(n^2): 16 x 65521 costs 7e10, 16 x 65536 4e7.
 *
 * The guard every transform goes through: nl_spectrum_check_size refuses a
 * size when a side has a prime factor beyond NL_SPECTRUM_MAX_FACTOR and the
 * transform costs more than NL_SPECTRUM_MAX_COST, with a message naming the
 * side, its largest prime factor and a size to crop to that passes (the
 * side with the larger factor cropped first); nl_spectrum_check_length the
 * same for n samples on a line (cost n times the sum of n's prime factors).
 * The bounds come from a measurement (nl_spectrum_power2 of n x n, GCC -O2,
 * one core of a Xeon shared with other jobs): 2-5e-10 s per operation of
 * the cost for smooth sides, 9e-10 s for a prime side (GSL's general pass);
 * n = 1024 (factor 2) 0.0093 s, 1029 (7) 0.026 s, 1001 (13) 0.037 s, 1012
 * (23) 0.038 s, 1003 (59) 0.062 s, 1022 (73) 0.068 s, 1027 (79) 0.087 s,
 * 509 (prime) 0.22 s, 1021 (prime) 1.9 s, 2039 (prime) 25 s. A
 * factor up to 127 keeps a transform within about 12 times a power of two
 * of the same size, so any size made of such factors passes; 2e8 operations
 * is at most 0.2 s per transform whatever the factors (257 x 257, prime,
 * 0.03 s, passes). An experiment transforms dozens of images: S3 --quick at
 * 1021 took 58 s against 4.35 s at 1024. */
#define NL_SPECTRUM_MAX_FACTOR 127
#define NL_SPECTRUM_MAX_COST 2e8
double nl_spectrum_fft2_cost(int w, int h);
nl_status nl_spectrum_check_size(int w, int h, nl_error *err);
nl_status nl_spectrum_check_length(size_t n, nl_error *err);
NL_MUST_CHECK nl_status nl_spectrum_fft2_inverse(const double *F, int w, int h, double *img, nl_error *err);
NL_MUST_CHECK nl_status nl_spectrum_power2(const double *img, int w, int h, double *P, nl_error *err);
NL_MUST_CHECK nl_status nl_spectrum_radial(const double *img, int w, int h, int nbins, double *f, double *p,
                                           nl_error *err);
/* A Hann-tapered copy of a non-periodic image, for power spectra without
 * the edge discontinuity the DFT's periodic extension adds (its power
 * leaks ~1/f^2 across every band): out = (img - mean) h(x) h(y) / sqrt(W),
 * h(x) = sin^2(pi (x + 1/2) / w) (no zero samples), W the mean of
 * (h(x) h(y))^2 (9/64 for w, h >= 3), so a stationary signal keeps its
 * expected total power: sum of nl_spectrum_power2(out) = variance of img.
 * The mean is removed first, or the taper would spread the DC term into the
 * lowest frequencies. out may be img. */
void nl_spectrum_hann2(const double *img, int w, int h, double *out);
/* The same with a tapered-cosine (Tukey) window: the fraction `frac` of each
 * axis (half at either edge) rises as sin^2, the rest is flat; frac 1 is the
 * Hann window above, smaller fractions keep more of the image's samples
 * (frac in (0, 1]; power normalised the same way). */
void nl_spectrum_taper2(const double *img, int w, int h, double frac, double *out);
/* Signed frequency of index u of an n-point DFT, in cycles per sample. */
double nl_spectrum_freq(int u, int n);
/* f and P hold n/2 + 1 values. n >= 2, rate > 0, n passing
 * nl_spectrum_check_length; NL_EINVAL otherwise, NL_ENUM if GSL's transform
 * fails. */
nl_status nl_spectrum_psd1(const double *x, size_t n, double rate, double *f, double *P, nl_error *err);
enum { NL_SPECTRUM_RECT = 0, NL_SPECTRUM_HANN = 1 };
/* NL_EINVAL also for an unknown window. */
nl_status nl_spectrum_psd1_window(const double *x, size_t n, double rate, int window, double *f, double *P,
                                  nl_error *err);

#ifdef __cplusplus
}
#endif

#endif
