/* Unit test of L2's trend test (claims.c) against a closed form: Student's
 * t with 2 degrees of freedom has the CDF 1/2 + t / (2 sqrt(2 + t^2)), so
 * three seeds' slopes give a p-value computed without GSL. */
#include "claims.h"
#include "nl_test.h"

#include <math.h>

NL_TEST(trend_three_seeds)
{
  const int sizes[3] = { 64, 128, 256 }; /* log2: 6, 7, 8 */
  /* err[i * seeds + s]: seed s falls by 0.1 (s + 1) per doubling */
  const double err[9] = { 1.0, 1.0, 1.0, 0.9, 0.8, 0.7, 0.8, 0.6, 0.4 };
  double m, sd, p;
  l2_trend(err, sizes, 3, 3, &m, &sd, &p);
  NL_CHECK_NEAR(m, -0.2, 1e-12);
  NL_CHECK_NEAR(sd, 0.1, 1e-12);
  double t = m / (sd / sqrt(3.0));
  NL_CHECK_NEAR(p, 0.5 + t / (2 * sqrt(2 + t * t)), 1e-9); /* 0.0371 */
  /* a rising error: p near 1; one size: no test */
  const double up[9] = { 0.4, 0.6, 0.8, 0.7, 0.8, 0.9, 1.0, 1.0, 1.0 };
  l2_trend(up, sizes, 3, 3, &m, &sd, &p);
  NL_CHECK(m > 0 && p > 0.9);
  l2_trend(err, sizes, 1, 3, &m, &sd, &p);
  NL_CHECK(p == 1);
}

int main(void) { return nl_test_run(); }
