/* Unit tests of A4's aliased energy and t test (alias.c). */
#include "alias.h"
#include "nl_test.h"

#include <math.h>

NL_TEST(t_test_against_closed_form)
{
  /* Student's t with 4 degrees of freedom has a closed-form CDF,
   * F(t) = 1/2 + (3/8) a (1 - a^2 / 12), a = t / sqrt(1 + t^2 / 4),
   * independent of GSL's incomplete beta function; tolerance 1e-12. */
  double x[5] = { 0.5, 0.9, 1.3, 0.7, 0.2 }, m = 0.72, ss = 0;
  for (int k = 0; k < 5; k++) ss += (x[k] - m) * (x[k] - m);
  double t = (m - 1.0) / sqrt(ss / 4.0 / 5.0), a = t / sqrt(1.0 + t * t / 4.0);
  double f = 0.5 + 0.375 * a * (1.0 - a * a / 12.0);
  double lo, hi;
  a4_t_test(x, 5, 1.0, &lo, &hi);
  NL_CHECK(fabs(lo - f) < 1e-12);
  NL_CHECK(fabs(hi - (1.0 - f)) < 1e-12);
  /* no spread: the sign of the difference decides */
  double c[3] = { 2, 2, 2 };
  a4_t_test(c, 3, 1.0, &lo, &hi);
  NL_CHECK(lo == 1.0 && hi == 0.0);
}

NL_TEST(alias_energy_scales_with_frequency)
{
  /* A stretched noise (lower frequency) puts less energy above Nyquist. */
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 3);
  nl_error err;
  double e1, e2;
  NL_CHECK(a4_alias_energy(&p, 1.0, 64.0, 32.0, 1.0, &e1, &err) == NL_OK);
  NL_CHECK(a4_alias_energy(&p, 0.5, 64.0, 32.0, 1.0, &e2, &err) == NL_OK);
  NL_CHECK(e1 > 0.0 && e2 < e1);
}

int main(void) { return nl_test_run(); }
