/* Unit tests of C2's equivalence test (equiv.c) against scipy 1.10's Welch
 * p-values (tests/data/stats/meantest.tsv, rows 2 and 3): when |d| < margin
 * the larger one-sided p is that of the difference margin - |d|, half the
 * two-sided p of two means that far apart. Tolerance 1e-9 relative (the
 * shifted means differ from the table's by rounding only). */
#include "equiv.h"
#include "nl_test.h"

#include <math.h>

static int close_rel(double a, double b) { return fabs(a - b) <= 1e-9 * fabs(b); }

NL_TEST(tost_matches_scipy_welch)
{
  double p;
  nl_error err;
  /* meantest row: 0.51 (0.02, 10) vs 0.5 (0.03, 10), two-sided p 0.39369440499485187 */
  NL_CHECK(c2_tost_p(0.5, 0.02, 10, 0.501, 0.03, 10, 0.011, &p, &err) == NL_OK);
  NL_CHECK(close_rel(p, 0.39369440499485187 / 2));
  /* the same with a and b swapped: TOST is symmetric in the sign of d */
  NL_CHECK(c2_tost_p(0.501, 0.03, 10, 0.5, 0.02, 10, 0.011, &p, &err) == NL_OK);
  NL_CHECK(close_rel(p, 0.39369440499485187 / 2));
  /* meantest row: 0 (1, 3) vs 1 (1, 3), two-sided p 0.2878641347266908 */
  NL_CHECK(c2_tost_p(2.0, 1, 3, 2.5, 1, 3, 1.5, &p, &err) == NL_OK);
  NL_CHECK(close_rel(p, 0.2878641347266908 / 2));
}

NL_TEST(tost_limits)
{
  double p;
  nl_error err;
  /* a difference beyond the margin cannot be called equivalent: p > 1/2 */
  NL_CHECK(c2_tost_p(10, 1, 5, 12, 1, 5, 1, &p, &err) == NL_OK && p > 0.5 && p <= 1);
  /* equal means, a margin of many standard errors: p near 0 */
  NL_CHECK(c2_tost_p(10, 1, 10, 10, 1, 10, 5, &p, &err) == NL_OK && p < 1e-6);
  NL_CHECK(c2_tost_p(10, 1, 10, 10, 1, 10, 0, &p, &err) == NL_EINVAL);
  NL_CHECK(c2_tost_p(10, 1, 1, 10, 1, 10, 1, &p, &err) == NL_EINVAL); /* n < 2 */
}

int main(void) { return nl_test_run(); }
