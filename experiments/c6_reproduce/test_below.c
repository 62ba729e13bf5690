/* Unit tests of C6's sign test (below.c) against exact binomial sums:
 * P(X <= k) = sum_{i <= k} C(n, i) / 2^n, in integers (tolerance 1e-12
 * relative: GSL's incomplete beta against the exact ratio). */
#include "below.h"
#include "nl_test.h"

#include <math.h>

static double exact(unsigned k, unsigned n)
{
  double c = 1, s = 0; /* C(n, i), exact in a double for n <= 50 */
  for (unsigned i = 0; i <= k; i++) {
    s += c;
    c = c * (n - i) / (i + 1);
  }
  return s / ldexp(1.0, (int)n);
}

NL_TEST(sign_p_matches_exact_sums)
{
  unsigned cases[][2] = { { 0, 24 }, { 3, 8 }, { 4, 8 }, { 11, 24 }, { 0, 8 }, { 20, 40 } };
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
    double p = c6_sign_p(cases[i][0], cases[i][1]), e = exact(cases[i][0], cases[i][1]);
    NL_CHECK(fabs(p - e) <= 1e-12 * e);
  }
  NL_CHECK(c6_sign_p(8, 8) == 1.0);
  NL_CHECK(fabs(c6_sign_p(0, 24) - ldexp(1.0, -24)) <= 1e-12 * ldexp(1.0, -24));
}

int main(void) { return nl_test_run(); }
