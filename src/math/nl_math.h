/* nl_math.h - elementary functions of our own: sin(pi x) and cos(pi x).
 *
 *   double nl_math_sinpi(double x);                          sin(pi x)
 *   double nl_math_cospi(double x);                          cos(pi x)
 *   void   nl_math_sincospi(double x, double *s, double *c); both, one reduction
 *   void   nl_math_sinpi_n(size_t n, const double *x, double *y);
 *                                         y[j] = nl_math_sinpi(x[j]), j < n,
 *                                         vectorised, the same bits
 *
 * Why our own: a value that reaches an `exact` column must not depend on
 * which libm the machine has. glibc's sin picks an FMA or a non-FMA variant
 * per CPU (and may change between versions), and the two differ by one ulp on
 * about 0.07% of sin(pi v); these functions use only +, -, * in double,
 * compiled with -ffp-contract=off (meson.build), so every IEEE-754 machine
 * gives the same bits. And sin(M_PI * x) is not sin(pi x): it is the sine of
 * pi rounded times x rounded, off by about |x| * 1.2e-16 absolute, 4 * 10^7
 * ulps of sin(pi x) at x = 1 - 2^-30.
 *
 * Method.
 *  1. Reduce: a = |x| (sinpi is odd, cospi even; the sign goes back at the
 *     end), k = round(2a) by (2a + 1.5 * 2^52) - 1.5 * 2^52 (exact rounding
 *     for 2a < 2^51), r = a - k/2 in [-1/4, 1/4]. r is exact: it is a
 *     multiple of a's ulp and |r| <= a when k != 0 (r = a when k = 0). So
 *     the reduction adds no error, and integers and half-integers give
 *     exact 0 and +-1. From |x| >= 2^50 (and for inf and NaN) one branch,
 *     never taken for the annealer's |x| <= 1, first takes a mod 4 exactly
 *     the same way (1.5 * 2^54: the doubles near it are the multiples of 4;
 *     from 2^53 on every double is an even integer, so a becomes 0).
 *  2. sin(pi (k/2 + r)) is s, c, -s, -c for k mod 4 = 0..3, with
 *     s = sin(pi r) = 0 + r (P0 + u (P1 + ... + P6 u^5)) and
 *     c = cos(pi r) = 1 + u (Q1 + u (Q2 + ... + Q7 u^5)), u = r^2: the same
 *     shape, base + w (K + u poly(u)) with (base, w) = (0, r) or (1, u). So
 *     one polynomial is evaluated, its coefficients chosen by k's parity
 *     (a table, nl_math__coef), not two polynomials and a selection. The
 *     coefficients are Chebyshev fits of 200-bit values by
 *     src/math/nl_math_fit.py (mpmath), rounded to double; the fits' own
 *     relative errors are 3.5e-18 (P) and 4.3e-20 (Q), far below the
 *     rounding of the evaluation.
 *  3. Evaluated as base + (w K + (w u) poly(u)), poly by Estrin's scheme:
 *     the annealer's loop waits on the result, and Estrin's dependency
 *     chain is half of Horner's. Speed is chosen over the last ulp:
 *     summing w K from exact parts (26- and 27-bit heads, Fast2Sum) gives
 *     0.77 ulp but lengthens that chain, 6.1 ns a call against 4.8 (glibc's
 *     sin(M_PI * v): 8.9 ns), and speeds marble's optimisation up 1.05x
 *     against 1.2x.
 *  4. Signs by multiplying with +-1 (exact, and no branch on the data nor a
 *     trip through the integer registers); + 0.0 turns the -0 of
 *     -sin(pi 0) into +0; then sinpi is multiplied by x's sign.
 *
 * Domain and special values (IEEE 754-2008 sinPi, cosPi):
 *   every finite x; sinpi(+-n) = +-0 and cospi(n + 1/2) = +0 for integers n;
 *   sinpi(n + 1/2) and cospi(n) are exactly +-1; sinpi(-0) = -0;
 *   +-inf and NaN give NaN. Huge |x| is exact (step 1), not a loss.
 *
 * Accuracy: at most 1.83 ulp for both, measured at 10^6 random x against a
 * long double reference and at 2331 hard inputs against 300-bit mpmath
 * values (tests/data/math/sinpi.tsv); src/math/test_math.c holds them to
 * 2 ulp. On marble's c = (1 + sinpi(V)) / 2, V in [-1, 1]: 1.21e-16 at most
 * (glibc's sin(M_PI * V): 2.3e-16).
 *
 * The definitions are inline (C99 inline: nl_math.c holds the external
 * ones), because the annealer calls nl_math_sinpi for every point a move
 * touches. So a program that includes this header compiles them with its
 * own flags: for the library's bits it needs -ffp-contract=off (GCC's
 * default in ISO C modes, -std=c11, but not in -std=gnu11, where a machine
 * with FMA would fuse the polynomial's products and sums).
 */
#ifndef NL_MATH_H
#define NL_MATH_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#ifdef __cplusplus
extern "C" {
#endif

/* src/math/nl_math_fit.py's output, verbatim (P0's value is pi to 17
 * digits, not pi itself). */
/* SINPI_P: degree 6 in u, largest relative error 3.5e-18 */
#define NL_MATH__SINPI_P0 0x1.921fb54442d18p+1   /* 3.1415926535897932 */
#define NL_MATH__SINPI_P1 -0x1.4abbce625be41p+2   /* -5.1677127800499545 */
#define NL_MATH__SINPI_P2 0x1.466bc677587f8p+1   /* 2.5501640398733761 */
#define NL_MATH__SINPI_P3 -0x1.32d2cce2e5b19p-1   /* -0.59926452893964493 */
#define NL_MATH__SINPI_P4 0x1.50782fda12d96p-4   /* 0.082145869180001746 */
#define NL_MATH__SINPI_P5 -0x1.e30071afc3e59p-8   /* -0.0073700215869077703 */
#define NL_MATH__SINPI_P6 0x1.e3f38399551bfp-12   /* 0.000461531855383581 */
/* COSPI_Q: degree 7 in u, largest relative error 4.29e-20 */
#define NL_MATH__COSPI_Q0 0x1.0000000000000p+0   /* 1.0 */
#define NL_MATH__COSPI_Q1 -0x1.3bd3cc9be45dep+2   /* -4.9348022005446792 */
#define NL_MATH__COSPI_Q2 0x1.03c1f081b5aacp+2   /* 4.0587121264167473 */
#define NL_MATH__COSPI_Q3 -0x1.55d3c7e3c90f8p+0   /* -1.3352627688519174 */
#define NL_MATH__COSPI_Q4 0x1.e1f5068355e15p-3   /* 0.23533063019088786 */
#define NL_MATH__COSPI_Q5 -0x1.a6d1ec7906c20p-6   /* -0.025806885652951305 */
#define NL_MATH__COSPI_Q6 0x1.f9cc41140bb60p-10   /* 0.0019294657440800043 */
#define NL_MATH__COSPI_Q7 -0x1.b264ba152378ap-14   /* -0.00010356747255199479 */

/* The kernel's coefficients by k's parity (nl_math.c): base, K, then the 6
 * of poly, lowest degree first. */
#define NL_MATH__NCOEF 8
extern const double nl_math__coef[2][NL_MATH__NCOEF];
extern const double nl_math__coef_sign[2];   /* 1, -1 */

inline uint64_t nl_math__bits(double x)
{
  uint64_t b;
  memcpy(&b, &x, sizeof b);
  return b;
}

inline double nl_math__double(uint64_t b)
{
  double x;
  memcpy(&x, &b, sizeof x);
  return x;
}

/* Step 1's branch: a >= 2^50, inf or NaN, to a value < 4 with the same
 * sin(pi a) and cos(pi a) (NaN for inf and NaN). */
inline double nl_math__reduce_huge(double a)
{
  double t = (a + 0x1.8p54) - 0x1.8p54;
  return a < 0x1p53 ? a - t : a - a;
}

/* Step 1: r in [-1/4, 1/4] and k mod 4 for |x|. */
inline double nl_math__reduce(double x, unsigned *quadrant)
{
  double a = fabs(x);
  if (!(a < 0x1p50))
    a = nl_math__reduce_huge(a);
  double t = 2.0 * a + 0x1.8p52;
  double k = t - 0x1.8p52;
  /* t's ulp is 1, so its last bits are k's: the quadrant without a
   * conversion, which for the NaN of inf or NaN would be undefined. */
  *quadrant = (unsigned)(nl_math__bits(t) & 3u);
  return a - 0.5 * k;
}

/* Steps 2 to 4 for one quadrant: sin(pi (k/2 + r)) with k mod 4 = quadrant,
 * the -0 of an exact zero made +0. */
inline double nl_math__kernel(double r, double u, unsigned quadrant)
{
  const double *c = nl_math__coef[quadrant & 1u];
  uint64_t pick = (uint64_t)0 - (uint64_t)(quadrant & 1u);
  double w = nl_math__double((nl_math__bits(r) & ~pick) | (nl_math__bits(u) & pick));
  double u2 = u * u;
  double p = (c[2] + c[3] * u) + u2 * ((c[4] + c[5] * u) + u2 * (c[6] + c[7] * u));
  double v = c[0] + (w * c[1] + (w * u) * p);
  return v * nl_math__coef_sign[(quadrant >> 1) & 1u] + 0.0;
}

inline double nl_math_sinpi(double x)
{
  unsigned q;
  double r = nl_math__reduce(x, &q);
  return nl_math__kernel(r, r * r, q) * copysign(1.0, x);
}

/* cos(pi (k/2 + r)) is c, -s, -c, s for k mod 4 = 0..3: sinpi's kernel one
 * quadrant on. */
inline double nl_math_cospi(double x)
{
  unsigned q;
  double r = nl_math__reduce(x, &q);
  return nl_math__kernel(r, r * r, q + 1u);
}

inline void nl_math_sincospi(double x, double *s, double *c)
{
  unsigned q;
  double r = nl_math__reduce(x, &q);
  double u = r * r;
  *s = nl_math__kernel(r, u, q) * copysign(1.0, x);
  *c = nl_math__kernel(r, u, q + 1u);
}

/* sinpi of n values at the library's vector level (simd/nl_simd.h): the
 * same lane by lane operations, so every level gives the scalar function's
 * bits (nl_math_simd_body.h). x and y may be the same array. Marble's
 * annealer evaluates its control value this way, a move's points at once. */
void nl_math_sinpi_n(size_t n, const double *x, double *y);

#ifdef __cplusplus
}
#endif

#endif
