/* nl_cheng_simd_avx2.c - the octave sums of a solution-pool move for AVX2,
 * four points a vector (nl_cheng_problem.c's general path, F = 4 octaves at
 * level 4). Compiled with a target pragma, never -march: called only when
 * the library's vector level (simd/nl_simd.h) is AVX2 or better. */
#include "simd/nl_simd_avx2.h"
#include "cheng/nl_cheng_internal.h"

/* sv[t] = nl_cheng__octave_sum(con, nv + 4 tp[t], amp, 4, -1, 0) for t < n
 * (tp NULL: point t itself), and pre[t] (if pre) the sum of the first
 * three octaves, the same function's first three steps: the four rows are
 * transposed so each lane sums its point's octaves in the scalar order,
 * v = ((((0 + a0 n0) + a1 n1) + a2 n2) + a3 n3), the same IEEE operations
 * (no FMA), so the same doubles. fire: |n_l|. */
void nl_cheng__sums4_avx2(size_t n, const size_t *tp, const double *nv, const double *amp,
                          int fire, double *sv, double *pre)
{
  const __m256d a0 = _mm256_set1_pd(amp[0]), a1 = _mm256_set1_pd(amp[1]);
  const __m256d a2 = _mm256_set1_pd(amp[2]), a3 = _mm256_set1_pd(amp[3]);
  const __m256d absmask = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffffLL));
  size_t t = 0;
  for (; t + 4 <= n; t += 4) {
    size_t i0 = tp ? tp[t] : t, i1 = tp ? tp[t + 1] : t + 1;
    size_t i2 = tp ? tp[t + 2] : t + 2, i3 = tp ? tp[t + 3] : t + 3;
    __m256d r0 = _mm256_loadu_pd(nv + 4 * i0), r1 = _mm256_loadu_pd(nv + 4 * i1);
    __m256d r2 = _mm256_loadu_pd(nv + 4 * i2), r3 = _mm256_loadu_pd(nv + 4 * i3);
    __m256d lo01 = _mm256_unpacklo_pd(r0, r1), hi01 = _mm256_unpackhi_pd(r0, r1);
    __m256d lo23 = _mm256_unpacklo_pd(r2, r3), hi23 = _mm256_unpackhi_pd(r2, r3);
    __m256d n0 = _mm256_permute2f128_pd(lo01, lo23, 0x20);
    __m256d n1 = _mm256_permute2f128_pd(hi01, hi23, 0x20);
    __m256d n2 = _mm256_permute2f128_pd(lo01, lo23, 0x31);
    __m256d n3 = _mm256_permute2f128_pd(hi01, hi23, 0x31);
    if (fire) {
      n0 = _mm256_and_pd(n0, absmask);
      n1 = _mm256_and_pd(n1, absmask);
      n2 = _mm256_and_pd(n2, absmask);
      n3 = _mm256_and_pd(n3, absmask);
    }
    __m256d v = _mm256_add_pd(_mm256_setzero_pd(), _mm256_mul_pd(a0, n0));
    v = _mm256_add_pd(v, _mm256_mul_pd(a1, n1));
    v = _mm256_add_pd(v, _mm256_mul_pd(a2, n2));
    if (pre) _mm256_storeu_pd(pre + t, v);
    v = _mm256_add_pd(v, _mm256_mul_pd(a3, n3));
    _mm256_storeu_pd(sv + t, v);
  }
  nl_cheng_con con = fire ? NL_CHENG_CON_FIRE : NL_CHENG_CON_PLAIN;
  for (; t < n; t++) {
    const double *row = nv + 4 * (tp ? tp[t] : t);
    sv[t] = nl_cheng__octave_sum(con, row, amp, 4, -1, 0.0);
    if (pre) pre[t] = nl_cheng__octave_sum(con, row, amp, 3, -1, 0.0);
  }
}

#if defined(__clang__)
#pragma clang attribute pop
#endif
