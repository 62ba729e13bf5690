/* Tests of nl_math: sinpi, cospi and sincospi against two references.
 *
 * 1. tests/data/math/sinpi.tsv: 300-bit mpmath values as double-doubles
 *    (tests/reference/make_sinpi_vectors.py) at 2331 hard inputs: integers,
 *    half-integers, a few ulps off each multiple of 1/2, tiny, subnormal,
 *    near 2^51..2^53 and huge x, and 1000 random ones. The reference's own
 *    error is below 2^-100 relative, nothing next to the tolerance.
 * 2. 10^6 random x against long double (64-bit significand): x - 2 round(x/2)
 *    and its fold into [-1/2, 1/2] are exact in long double, and sinl of pi
 *    times that is within about 3 long double ulps, 2^-61 relative, or
 *    0.004 double ulps; checked against table 1 here, below 0.01 ulp.
 * Tolerance: 2 ulp of the true value (measured here: 1.83 ulp for sinpi,
 * 1.79 for cospi: the roundings of w K, of u = r^2 and of the final sum,
 * nl_math.h). Exact zeros and ones must be exact, with IEEE 754's signs. */
#include "math/nl_math.h"
#include "simd/nl_simd.h"
#include "nl_test.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef NL_MATH_DATA
#error "NL_MATH_DATA (the tests/data/math directory) must be defined by meson"
#endif

#define TOL_ULPS 2.0

/* The unit in the last place of a double whose true value is y. */
static long double ulp_of(long double y)
{
  int e;
  if (fabsl(y) < 0x1p-1022L) return 0x1p-1074L;
  frexpl(y, &e);
  return ldexpl(1.0L, e - 53);
}

/* |got - (hi + lo)| in ulps of hi + lo; an exact zero must be returned as
 * zero (infinitely many ulps otherwise). */
static double err_ulps(double got, long double ref)
{
  if (ref == 0) return got == 0 ? 0.0 : INFINITY;
  return (double)(fabsl((long double)got - ref) / ulp_of(ref));
}

static int sign_bit(double v) { return signbit(v) ? 1 : 0; }

/* The long double reference: sin(pi x) for x reduced exactly to [-1/2, 1/2]
 * (the long double significand holds x - 2 round(x/2) for every double x). */
static long double ref_sinpi(long double b)
{
  b -= 2.0L * roundl(b / 2.0L);
  if (b > 0.5L) b = 1.0L - b;
  else if (b < -0.5L) b = -1.0L - b;
  return sinl(3.141592653589793238462643383279502884L * b);
}

static long double ref_cospi(double x)
{
  long double b = (long double)x - 2.0L * roundl((long double)x / 2.0L);
  return ref_sinpi(0.5L - b);   /* 1/2 - b is exact where the result is small */
}

NL_TEST(special_values_are_exact_with_ieee_signs)
{
  for (int n = -9; n <= 9; n++) {
    double x = n;
    double h = n + 0.5;
    NL_CHECK(nl_math_sinpi(x) == 0 && sign_bit(nl_math_sinpi(x)) == (n < 0));
    NL_CHECK(nl_math_cospi(x) == ((n % 2) ? -1.0 : 1.0));
    NL_CHECK(nl_math_cospi(h) == 0 && !sign_bit(nl_math_cospi(h)));
    NL_CHECK(nl_math_sinpi(h) == ((((n % 2) + 2) % 2) ? -1.0 : 1.0));
  }
  NL_CHECK(nl_math_sinpi(-0.0) == 0 && sign_bit(nl_math_sinpi(-0.0)));
  NL_CHECK(nl_math_sinpi(0.0) == 0 && !sign_bit(nl_math_sinpi(0.0)));
  NL_CHECK(nl_math_cospi(-0.0) == 1.0);
  NL_CHECK(nl_math_sinpi(0.25) == nl_math_cospi(0.25));
  double big[] = {0x1p52, 0x1p52 + 1, 0x1p53, 0x1p53 + 2, 1e300, 1.7976931348623157e308};
  for (size_t i = 0; i < sizeof big / sizeof big[0]; i++) {
    NL_CHECK(nl_math_sinpi(big[i]) == 0 && !sign_bit(nl_math_sinpi(big[i])));
    NL_CHECK(nl_math_sinpi(-big[i]) == 0 && sign_bit(nl_math_sinpi(-big[i])));
    NL_CHECK(nl_math_cospi(-big[i]) == (big[i] == 0x1p52 + 1 ? -1.0 : 1.0));
  }
  NL_CHECK(nl_math_sinpi(0x1p51 + 0.5) == 1.0 && nl_math_cospi(0x1p51 + 0.5) == 0);
  double bad[] = {INFINITY, -INFINITY, NAN, -NAN};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    double s, c;
    nl_math_sincospi(bad[i], &s, &c);
    NL_CHECK(isnan(nl_math_sinpi(bad[i])) && isnan(nl_math_cospi(bad[i])) && isnan(s) && isnan(c));
  }
}

NL_TEST(matches_mpmath_at_hard_inputs)
{
  FILE *f = fopen(NL_MATH_DATA "/sinpi.tsv", "r");
  if (!f) { perror(NL_MATH_DATA "/sinpi.tsv"); exit(99); }
  char line[256];
  NL_CHECK(fgets(line, sizeof line, f) && !strcmp(line, "x\tsin_hi\tsin_lo\tcos_hi\tcos_lo\n"));
  size_t rows = 0;
  double worst_s = 0, worst_c = 0, worst_ref = 0;
  while (fgets(line, sizeof line, f)) {
    double v[5];
    char *p = line;
    for (int i = 0; i < 5; i++) {
      char *end;
      v[i] = strtod(p, &end);
      NL_CHECK(end != p);
      p = end;
    }
    long double s_ref = (long double)v[1] + v[2], c_ref = (long double)v[3] + v[4];
    double es = err_ulps(nl_math_sinpi(v[0]), s_ref), ec = err_ulps(nl_math_cospi(v[0]), c_ref);
    if (es > TOL_ULPS || ec > TOL_ULPS)
      fprintf(stderr, "x = %a: sinpi %.3f ulp, cospi %.3f ulp\n", v[0], es, ec);
    worst_s = fmax(worst_s, es);
    worst_c = fmax(worst_c, ec);
    /* The long double reference of the random test, held to the table
     * where the table's lo is exact: below 2^-969 it underflows, leaving
     * hi alone, correctly rounded, worth 0.5 ulp. */
    if (fabs(v[0]) < 0x1p64 && fabs(v[0]) > 0x1p-960) {
      worst_ref = fmax(worst_ref, (double)(fabsl(ref_sinpi(v[0]) - s_ref) / ulp_of(s_ref)));
      worst_ref = fmax(worst_ref, (double)(fabsl(ref_cospi(v[0]) - c_ref) / ulp_of(c_ref)));
    }
    rows++;
  }
  fclose(f);
  printf("mpmath table: %zu inputs, worst sinpi %.3f ulp, cospi %.3f ulp, "
         "long double ref %.4f ulp\n", rows, worst_s, worst_c, worst_ref);
  NL_CHECK(rows > 2000);
  NL_CHECK(worst_s <= TOL_ULPS && worst_c <= TOL_ULPS);
  NL_CHECK(worst_ref < 0.01);
}

/* One of four kinds of x: in [-1, 1]; in [-8, 8]; any sign and magnitude
 * from 2^-40 to 2^60; within 1000 ulps of a multiple of 1/2 up to 16. */
static double random_x(gsl_rng *r, unsigned long i)
{
  double sign = gsl_rng_uniform(r) < 0.5 ? -1.0 : 1.0;
  switch (i % 4) {
  case 0: return 2 * gsl_rng_uniform(r) - 1;
  case 1: return 16 * gsl_rng_uniform(r) - 8;
  case 2: {
    int e = (int)gsl_rng_uniform_int(r, 101) - 40;
    return sign * ldexp(0.5 + 0.5 * gsl_rng_uniform(r), e);
  }
  default: {
    double h = 0.5 * (double)gsl_rng_uniform_int(r, 33);
    long k = (long)gsl_rng_uniform_int(r, 2001) - 1000;
    return sign * (h + (double)k * 0x1p-52 * fmax(h, 0x1p-40));
  }
  }
}

NL_TEST(matches_long_double_at_a_million_random_inputs)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 20261127);
  double worst_s = 0, worst_c = 0, wx_s = 0, wx_c = 0;
  unsigned long mismatched = 0;
  for (unsigned long i = 0; i < 1000000; i++) {
    double x = random_x(r, i);
    double s = nl_math_sinpi(x), c = nl_math_cospi(x), s2, c2;
    nl_math_sincospi(x, &s2, &c2);
    if (memcmp(&s, &s2, sizeof s) || memcmp(&c, &c2, sizeof c)) mismatched++;
    double es = err_ulps(s, ref_sinpi(x)), ec = err_ulps(c, ref_cospi(x));
    if (es > worst_s) { worst_s = es; wx_s = x; }
    if (ec > worst_c) { worst_c = ec; wx_c = x; }
  }
  gsl_rng_free(r);
  printf("10^6 random: worst sinpi %.3f ulp (x = %a), cospi %.3f ulp (x = %a)\n",
         worst_s, wx_s, worst_c, wx_c);
  NL_CHECK(worst_s <= TOL_ULPS);
  NL_CHECK(worst_c <= TOL_ULPS);
  NL_CHECK(mismatched == 0);   /* sincospi is sinpi and cospi, bit for bit */
}

/* nl_math_sinpi_n at every vector level the CPU runs: the scalar
 * function's bits at the random inputs and at the special ones (huge, inf
 * and NaN take the scalar path for their whole vector), for every length
 * 0..40 (the tails) and at every offset into the array. */
NL_TEST(sinpi_n_gives_the_scalar_bits_at_every_level)
{
  enum { N = 1 << 16 };
  double *x = malloc(N * sizeof *x), *y = malloc(N * sizeof *y), *z = malloc(N * sizeof *z);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 20261128);
  const double special[] = {0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 0x1p50, -0x1p50, 0x1p52 + 1, 1e300,
                            INFINITY, -INFINITY, NAN, 0x1p-1074, -0x1p-1022, 0x1p51 + 0.5};
  size_t ns = sizeof special / sizeof special[0];
  for (size_t i = 0; i < N; i++)
    x[i] = (i % 97 < ns) ? special[i % 97] : random_x(r, i);
  gsl_rng_free(r);
  for (size_t i = 0; i < N; i++) y[i] = nl_math_sinpi(x[i]);
  int saved = nl_simd_get(), levels = 0;
  for (int lv = NL_SIMD_SCALAR; lv <= NL_SIMD_AVX512; lv++) {
    if (!nl_simd_supported(lv)) continue;
    NL_CHECK(nl_simd_set(lv) == 0);
    levels++;
    nl_math_sinpi_n(N, x, z);
    size_t diff = 0;
    for (size_t i = 0; i < N; i++) diff += memcmp(&y[i], &z[i], sizeof y[i]) != 0;
    for (size_t n = 0; n <= 40; n++)
      for (size_t off = 0; off < 8; off++) {
        double t[48];
        for (size_t i = 0; i < 48; i++) t[i] = 7.0;
        nl_math_sinpi_n(n, x + 97 * off, t + off);
        for (size_t i = 0; i < n; i++)
          diff += memcmp(&t[off + i], &y[97 * off + i], sizeof t[0]) != 0;
        for (size_t i = 0; i < 48; i++) diff += (i < off || i >= off + n) && t[i] != 7.0;
      }
    if (diff) fprintf(stderr, "%s: %zu values differ from nl_math_sinpi\n", nl_simd_name(lv), diff);
    NL_CHECK(diff == 0);
  }
  nl_math_sinpi_n(N, x, x);   /* in place */
  NL_CHECK(memcmp(x, y, N * sizeof *x) == 0);
  nl_simd_set(saved);
  printf("sinpi_n: the scalar bits at %d levels\n", levels);
  free(x); free(y); free(z);
}

int main(void) { return nl_test_run(); }
