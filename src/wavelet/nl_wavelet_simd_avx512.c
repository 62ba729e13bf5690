/* nl_wavelet_simd_avx512.c - nl_wavelet_simd_body.h for AVX-512 (F, DQ,
 * BW, VL, VBMI), 8 doubles a vector, with a windowed loop for dense rows.
 * Compiled with a target pragma, never -march: called only when the
 * library's level (nl_simd_get) says the CPU runs it. No FMA. */
#include "simd/nl_simd_avx512.h"   /* vd, vl, v_ceil */
#include "wavelet/nl_wavelet_simd.h"
#include <math.h>

#define NL_SIMD_W 8
typedef int vi __attribute__((vector_size(32)));

#include "simd/nl_simd_lanes.h"   /* v_gd */
#include "simd/nl_simd_vec.h"     /* ld, st, SPLAT */
#include "wavelet/nl_wavelet_simd_body.h"

/* The B-spline row through a window (as noise's AVX-512 row samples): 8
 * samples span at most 7 first taps when 7 |dx| <= 4, and the three taps
 * read L[b ..], L[b + 1 ..], L[b + 2 ..] with one set of local indices
 * (b: lane 0's, the lowest). */
static void bspline(const double *L, long a, double x0, double dx, size_t n, double weight,
                    double *out)
{
  if (!(fabs(dx) * 7 <= 4) || !(dx >= 0)) {
    bspline_lanes(L, a, x0, dx, n, weight, out);
    return;
  }
  vd kv, fa1 = SPLAT((double)a + 1.0);
  for (int l = 0; l < NL_SIMD_W; l++) kv[l] = l;
  size_t k = 0;
  for (; k + NL_SIMD_W <= n; k += NL_SIMD_W, kv += (double)NL_SIMD_W) {
    vd w0, w1, w2;
    vi ci;
    v_bspline(kv * dx + x0, fa1, &ci, &w0, &w1, &w2);
    __m512d c = (__m512d)__builtin_convertvector(ci, vd);
    __m128d lane = _mm512_castpd512_pd128(c);
    long b = _mm_cvttsd_si64(lane);
    __m512i li = _mm512_cvttpd_epi64(_mm512_sub_pd(c, _mm512_broadcastsd_pd(lane)));
    vd l0 = (vd)_mm512_permutexvar_pd(li, _mm512_loadu_pd(L + b));
    vd l1 = (vd)_mm512_permutexvar_pd(li, _mm512_loadu_pd(L + b + 1));
    vd l2 = (vd)_mm512_permutexvar_pd(li, _mm512_loadu_pd(L + b + 2));
    st(out + k, ld(out + k) + weight * (w0 * l0 + w1 * l1 + w2 * l2));
  }
  if (k < n) bspline_tail(L, a, x0, dx, k, n, weight, out);
}

const nl_wavelet_simd_row_fn nl_wavelet_simd_avx512 = bspline;

#if defined(__clang__)
#pragma clang attribute pop
#endif
