/* nl_wavelet_simd_body.h - the vector sample loop of nl_wavelet_row,
 * written once with GCC vector extensions. Included by
 * nl_wavelet_simd_{sse2,avx2,avx512}.c after they define NL_SIMD_W, the
 * vector types vd, vl, vi and v_ceil (simd/nl_simd_<level>.h: exact for
 * |x| < 2^52; a zero result's sign may differ from ceil's, which the one use
 * below cannot see), v_gd
 * (simd/nl_simd_lanes.h) and ld, st, SPLAT (simd/nl_simd_vec.h). Each lane
 * repeats nl_wavelet.c's scalar operations in the same order (no FMA).
 */
#include <string.h>

/* nl_wavelet.c's row loop over a line L of columns already unwrapped (column
 * c is the tile's column a + c mod n): per sample its bspline() -
 * mid = ceil(p - 1/2), t = mid - (p - 1/2), w0 = t^2/2, w2 = (1 - t)^2/2,
 * w1 = 1 - w0 - w2, first tap mid - 1 - and
 * out = out + weight (w0 L[c] + w1 L[c + 1] + w2 L[c + 2]). A zero mid's
 * sign only reaches t = mid - (p - 1/2) = +-0, whose square is +0. */
static inline void v_bspline(vd x, vd fa1, vi *cp, vd *w0, vd *w1, vd *w2)
{
  vd p5 = x - 0.5, mid = v_ceil(p5), t = mid - p5, u = 1.0 - t;
  *w0 = t * t / 2.0;
  *w2 = u * u / 2.0;
  *w1 = 1.0 - *w0 - *w2;
  *cp = __builtin_convertvector(mid - fa1, vi);   /* mid - 1 - a, exact */
}

static void bspline_tail(const double *L, long a, double x0, double dx, size_t k0, size_t n,
                         double weight, double *out)
{
  double xs[NL_SIMD_W], acc[NL_SIMD_W] = {0}, res[NL_SIMD_W];
  for (int l = 0; l < NL_SIMD_W; l++)   /* lanes past n repeat sample k0 */
    xs[l] = x0 + (double)(k0 + ((size_t)l < n - k0 ? (size_t)l : 0)) * dx;
  memcpy(acc, out + k0, (n - k0) * sizeof *acc);
  vd w0, w1, w2;
  vi c;
  v_bspline(ld(xs), SPLAT((double)a + 1.0), &c, &w0, &w1, &w2);
  vd s = w0 * v_gd(L, c) + w1 * v_gd(L + 1, c) + w2 * v_gd(L + 2, c);
  st(res, ld(acc) + weight * s);
  memcpy(out + k0, res, (n - k0) * sizeof *out);
}

static void bspline_lanes(const double *L, long a, double x0, double dx, size_t n, double weight,
                          double *out)
{
  vd kv, fa1 = SPLAT((double)a + 1.0);
  for (int l = 0; l < NL_SIMD_W; l++) kv[l] = l;
  size_t k = 0;
  for (; k + NL_SIMD_W <= n; k += NL_SIMD_W, kv += (double)NL_SIMD_W) {
    vd w0, w1, w2;
    vi c;
    v_bspline(kv * dx + x0, fa1, &c, &w0, &w1, &w2);
    vd s = w0 * v_gd(L, c) + w1 * v_gd(L + 1, c) + w2 * v_gd(L + 2, c);
    st(out + k, ld(out + k) + weight * s);
  }
  if (k < n) bspline_tail(L, a, x0, dx, k, n, weight, out);
}

