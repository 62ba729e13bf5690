/* nl_noise_lattice.h - the scalar lattice helpers every lattice noise of the
 * library uses: Perlin's fade, the cell of a coordinate and the fraction in
 * it, and a modulo that stays in [0, m) for negative lattice indices.
 *
 * One copy, included by noise's scalar kernels and SIMD row drivers (which
 * test_noise_simd.c holds to the same bits), by cellular (its cube index) and
 * by cheng's incremental problems (their stored corner weights must equal
 * the noise's own, bit for bit). All are static inline: no call in the
 * inner loops, and the same IEEE operations wherever they are inlined (the
 * project compiles with -ffp-contract=off).
 *
 *   long i = nl_noise_lfloor(x);          // the cell, floor(x)
 *   double t = nl_noise_lfrac(x, i);      // x - i in [0, 1]
 *   double w = nl_noise_fade(t);          // 6t^5 - 15t^4 + 10t^3
 *   long e = nl_noise_lmod(i, m);         // i mod m in [0, m)
 */
#ifndef NL_NOISE_LATTICE_H
#define NL_NOISE_LATTICE_H

#include <math.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Perlin 2002's quintic fade, in his operation order (Horner from t^5 down):
 * another order changes the last bits of every sample. */
static inline double nl_noise_fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

/* floor() is a libm call without SSE4.1; the x86-64 baseline has only a
 * truncating conversion, so correct it for negative non-integers.
 * Safe for every double: a long holds floor(x) only for |x| < 2^63, so
 * beyond 2^62 the cell wraps modulo 2^62 (every such double is an integer
 * and its fraction is 0: deterministic, no undefined conversion), and NaN
 * or an infinity maps to cell 0 (nl_noise_lfrac then gives NaN, so the
 * output says it). Callers that sample rows keep to |x| < 2^52. */
#define NL_LATTICE_WRAP 0x1p62
static inline long nl_noise_lfloor(double x)
{
  if (x > -NL_LATTICE_WRAP && x < NL_LATTICE_WRAP) {
    long i = (long)x;
    return i - (x < (double)i);
  }
  if (!isfinite(x)) return 0;
  return (long)fmod(x, NL_LATTICE_WRAP);
}

/* The fraction x - i for the cell i = nl_noise_lfloor(x), rounded as
 * Perlin's reference code rounds x - floor(x): in [0, 1) and exact, except
 * for -1 < x < 0, where x - (-1) = 1 + x rounds, and to 1 itself for x in
 * [-2^-54, 0). The fraction is then 1 in cell -1, which is the point x = 0
 * (the far face of the cell, where the fade is 1): the noise is continuous
 * there and equals the reference. Mapping that 1 to 0 would move the point
 * to x = -1. 0 beyond 2^62 (x is an integer there), NaN for NaN and inf. */
static inline double nl_noise_lfrac(double x, long i)
{
  double f = x - (double)i;
  return f >= 0 && f <= 1 ? f : isfinite(x) ? 0.0 : NAN;
}

/* a mod m in [0, m) for m > 0 (C's % keeps the sign of a): lattice indices
 * left of the origin wrap into the table like those right of it. */
static inline long nl_noise_lmod(long a, long m)
{
  long r = a % m;
  return r < 0 ? r + m : r;
}

/* Row sampling indexes collapsed columns by cell: only where the lattice
 * coordinate is below 2^52 (beyond, doubles have no fractional bits). */
#define NL_LATTICE_EXACT 0x1p52

#ifdef __cplusplus
}
#endif

#endif
