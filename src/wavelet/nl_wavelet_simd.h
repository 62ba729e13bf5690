/* nl_wavelet_simd.h - private to src/wavelet: the vector sample loop of
 * nl_wavelet_row, one per level of the library's dispatch (simd/nl_simd.h),
 * each giving the scalar loop's bits.
 *
 * The loop runs over a line L of columns already unwrapped from the tile's
 * period (column c is the tile's column a + c mod n), padded by
 * NL_WAVELET_SIMD_PAD zeroed doubles: for k < n, at x = x0 + k dx,
 *   out[k] += weight (w0 L[c] + w1 L[c + 1] + w2 L[c + 2])
 * with the weights and first tap a + c of nl_wavelet.c's bspline().
 * Precondition: every x has |x| < 2^51 and its taps lie in L. */
#ifndef NL_WAVELET_SIMD_H
#define NL_WAVELET_SIMD_H

#include <stddef.h>

/* Zeroed doubles after L's last column (a vector load may read past it). */
#define NL_WAVELET_SIMD_PAD 16

typedef void (*nl_wavelet_simd_row_fn)(const double *L, long a, double x0, double dx, size_t n,
                                       double weight, double *out);
extern const nl_wavelet_simd_row_fn nl_wavelet_simd_sse2, nl_wavelet_simd_avx2,
    nl_wavelet_simd_avx512;

#endif
