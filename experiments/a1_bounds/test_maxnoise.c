/* Unit tests of A1's premise checks (maxnoise.c). */
#include "bounds/nl_bounds.h"
#include "maxnoise.h"
#include "nl_test.h"

#include <math.h>

NL_TEST(climbs_rise_and_stay_below_the_analytic_bound)
{
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 5);
  double xyz[3], sampled;
  double m = a1_local_max(&p, 20000, 20, 9, xyz, &sampled);
  NL_CHECK(m >= sampled && sampled > 0.5);
  NL_CHECK(m <= NL_NOISE3_BOUND);
  /* the reported point holds the reported value */
  NL_CHECK(fabs(fabs(nl_noise_perm3_eval(&p, xyz[0], xyz[1], xyz[2])) - m) < 1e-12);
}

NL_TEST(octave_violations_nest_and_match_a_unit_bound)
{
  /* More octaves can only add violating points; with a bound of 1 that no
   * random point of nl_bounds_check_random exceeds, there are none. */
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 7);
  long a = a1_octave_over(&p, 2, 20000, 11), b = a1_octave_over(&p, 6, 20000, 11);
  NL_CHECK(a <= b);
  nl_noise_octaves o = nl_noise_octaves_fractal(6);
  nl_bounds_check c;
  nl_bounds_check_random(&p, &o, 1.0, 20000, 11, &c);
  NL_CHECK((c.max_abs_noise > 1.0) == (b > 0));
}

int main(void) { return nl_test_run(); }
