#include "texture/nl_texture.h"
#include "nl_test.h"

NL_TEST(linear_ramp_hits_knots_and_clamps)
{
  const double pos[] = {0, 0.25, 1};
  const float rgb[][3] = {{0, 0, 0}, {1, 0.5f, 0}, {1, 1, 1}};
  nl_texture_ramp r = nl_texture_ramp_linear(3, pos, rgb);
  float c[3];
  nl_texture_ramp_eval(&r, 0.25, c);
  NL_CHECK(c[0] == 1 && c[1] == 0.5f && c[2] == 0);
  nl_texture_ramp_eval(&r, 0.625, c);
  NL_CHECK_NEAR(c[1], 0.75, 1e-7);
  nl_texture_ramp_eval(&r, -3, c);
  NL_CHECK(c[0] == 0);
  nl_texture_ramp_eval(&r, 7, c);
  NL_CHECK(c[2] == 1);
}

NL_TEST(spline_ramp_passes_through_inner_knots)
{
  /* Ebert's spline: u = k / nspans lands on knot k + 1. */
  const float rgb[][3] = {{9, 9, 9}, {0, 0, 0}, {1, 2, 3}, {4, 4, 4}, {2, 1, 0}, {-9, -9, -9}};
  nl_texture_ramp r = nl_texture_ramp_spline(6, rgb);
  float c[3];
  for (int k = 0; k <= 3; k++) {
    nl_texture_ramp_eval(&r, k / 3.0, c);
    NL_CHECK_NEAR(c[0], rgb[k + 1][0], 1e-6);
    NL_CHECK_NEAR(c[2], rgb[k + 1][2], 1e-6);
  }
}

NL_TEST(marble_in_unit_interval)
{
  for (double y = -10; y < 10; y += 0.37)
    NL_CHECK(nl_texture_marble(y, 3.0, 0.4 * y) >= 0 && nl_texture_marble(y, 3.0, 0.4 * y) <= 1);
}

int main(void) { return nl_test_run(); }
