/* nl_noise_lattice.h - private to src/noise: the scalar lattice helpers the
 * scalar kernels (nl_noise.c) and the SIMD row drivers (nl_noise_simd.c)
 * share, so that both find cells and fractions by the very same operations
 * (test_noise_simd.c holds every level to the scalar bits). */
#ifndef NL_NOISE_LATTICE_H
#define NL_NOISE_LATTICE_H

#include <math.h>
#include <stddef.h>

/* Perlin's fade, in his operation order. */
static inline double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

/* floor() is a libm call without SSE4.1; the x86-64 baseline has only a
 * truncating conversion, so correct it for negative non-integers.
 * Safe for every double: a long holds floor(x) only for |x| < 2^63, so
 * beyond 2^62 the cell wraps modulo 2^62 (every such double is an integer
 * and its fraction is 0: deterministic, no undefined conversion), and NaN
 * or an infinity maps to cell 0 (lfrac then gives NaN, so the output says
 * it). Callers that sample rows keep to |x| < 2^52 (row_columns). */
#define NL_LATTICE_WRAP 0x1p62
static inline long lfloor(double x)
{
  if (x > -NL_LATTICE_WRAP && x < NL_LATTICE_WRAP) { long i = (long)x; return i - (x < (double)i); }
  if (!isfinite(x)) return 0;
  return (long)fmod(x, NL_LATTICE_WRAP);
}

/* The fraction x - floor(x) in [0, 1) for the cell i = lfloor(x): exact for
 * |x| < 2^62, 0 beyond (x is an integer there), NaN for NaN and inf. */
static inline double lfrac(double x, long i)
{
  double f = x - (double)i;
  return f >= 0 && f < 1 ? f : isfinite(x) ? 0.0 : NAN;
}

/* Row sampling indexes collapsed columns by cell: only where the lattice
 * coordinate is below 2^52 (beyond, doubles have no fractional bits). */
#define NL_LATTICE_EXACT 0x1p52

/* Columns spanned by a row; 0 when sampling is so sparse (more than two
 * columns per sample) that collapsing columns costs more than it saves. */
static size_t row_columns(double x0, double dx, size_t n, long *ifirst)
{
  double xl = x0 + (double)(n - 1) * dx;
  if (!(fabs(x0) < NL_LATTICE_EXACT && fabs(xl) < NL_LATTICE_EXACT)) return 0;
  long a = lfloor(dx >= 0 ? x0 : xl), b = lfloor(dx >= 0 ? xl : x0);
  *ifirst = a;
  size_t ncol = (size_t)(b - a) + 2;
  return ncol > 2 * n + 8 ? 0 : ncol;
}

#endif
