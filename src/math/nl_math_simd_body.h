/* nl_math_simd_body.h - nl_math_sinpi over an array, one vector of
 * NL_SIMD_W lanes at a time: nl_math.h's steps in the same IEEE operations
 * lane by lane (no FMA: the including file's target pragma allows it, and
 * -ffp-contract=off keeps the compiler from fusing), so every lane has the
 * scalar function's bits. The coefficient table's lookup by k's parity
 * becomes a select by bit masks. A vector with a lane at |x| >= 2^50, inf
 * or NaN (step 1's branch) goes through the scalar function.
 *
 * Included by nl_math_simd_<level>.c after the level's header
 * (simd/nl_simd_<level>.h: vd, vl, v_all), NL_SIMD_W and NL_SIMD_SINPI_N. */
#include "math/nl_math.h"
#include "simd/nl_simd_vec.h"

#include <stddef.h>

/* a's bits where m is set, b's elsewhere. */
static inline __attribute__((always_inline)) vd pick(vl m, vd a, vd b)
{
  return (vd)(((vl)a & m) | ((vl)b & ~m));
}

/* nl_math_sinpi's steps, lane by lane. Inlined by force: GCC left it a
 * call, whose vector argument and result went through memory, and the
 * call cost as much as the arithmetic (a marble move 1.7x slower). */
static inline __attribute__((always_inline)) vd sinpi_lanes(vd x)
{
  const vl signbit = (vl)splat(-0.0);
  vl xb = (vl)x;
  vd a = (vd)(xb & ~signbit);
  vd t = SPLAT(2.0) * a + SPLAT(0x1.8p52);
  vd k = t - SPLAT(0x1.8p52);
  vl q = (vl)t & 3;
  vd r = a - SPLAT(0.5) * k;
  vd u = r * r;
  vl odd = -(q & 1);   /* all ones where k is odd: the cosine's coefficients */
  const double *c0 = nl_math__coef[0], *c1 = nl_math__coef[1];
  vd c[NL_MATH__NCOEF];
  for (int i = 0; i < NL_MATH__NCOEF; i++) c[i] = pick(odd, splat(c1[i]), splat(c0[i]));
  vd w = pick(odd, u, r);
  vd u2 = u * u;
  vd p = (c[2] + c[3] * u) + u2 * ((c[4] + c[5] * u) + u2 * (c[6] + c[7] * u));
  vd v = c[0] + (w * c[1] + (w * u) * p);
  vd sq = pick(-((q >> 1) & 1), SPLAT(-1.0), SPLAT(1.0));
  vd sx = (vd)((vl)SPLAT(1.0) | (xb & signbit));   /* copysign(1.0, x) */
  return (v * sq + SPLAT(0.0)) * sx;
}

void NL_SIMD_SINPI_N(size_t n, const double *x, double *y);
void NL_SIMD_SINPI_N(size_t n, const double *x, double *y)
{
  size_t j = 0;
  for (; j + NL_SIMD_W <= n; j += NL_SIMD_W) {
    vd xv = ld(x + j);
    vd a = (vd)((vl)xv & ~(vl)splat(-0.0));
    if (v_all(a < SPLAT(0x1p50))) {
      st(y + j, sinpi_lanes(xv));
    } else {
      for (int l = 0; l < NL_SIMD_W; l++) y[j + l] = nl_math_sinpi(x[j + l]);
    }
  }
  for (; j < n; j++) y[j] = nl_math_sinpi(x[j]);
}
