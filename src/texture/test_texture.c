#include "texture/nl_texture.h"

#include <stdlib.h>
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

NL_TEST(wood_rings_follow_distance_to_axis)
{
  /* Axis along z through (1, 1): r = distance in the plane; u = frac(2 r + turb g). */
  nl_texture_wood w = {.axis_p = {1, 1, 0}, .axis_d = {0, 0, 3}, .ring_freq = 2, .turb = 1, .light = {1, 1, 1}};
  double on[3] = {1, 1, 5}, p[3] = {1.3, 1.4, -2};
  NL_CHECK_NEAR(nl_texture_wood_radius(&w, p), 0.5, 1e-12);
  NL_CHECK_NEAR(nl_texture_wood_ring(&w, on, 0.0), 0.0, 1e-12);   /* u = 0: light wood */
  NL_CHECK_NEAR(nl_texture_wood_ring(&w, on, 0.81), 1.0, 1e-12);  /* u in [0.8, 0.83]: dark */
  NL_CHECK_NEAR(nl_texture_wood_ring(&w, p, 0.0), 0.0, 1e-12);    /* u = frac(1) = 0 */
  NL_CHECK_NEAR(nl_texture_wood_ring(&w, p, 0.4), 0.5, 1e-12);    /* smoothstep(0, 0.8, 0.4) */
  nl_noise_window win = {0, 0, 0, 2.0, 200, 200};
  double *t = malloc(200 * 200 * sizeof *t);
  nl_texture_wood_grid(&w, &win, NULL, t);
  nl_image *im = nl_texture_wood_image(&w, t, 200, 200);
  /* along row 100 (y = 1.005) r runs 1 -> 0 -> 1, u = 2 r covers two rings
   * each side: 4 dark bands; the same along column 100 */
  NL_CHECK(nl_texture_band_count(im, 0, 100) == 4);
  NL_CHECK(nl_texture_band_count(im, 1, 100) == 4);
  nl_image_free(im);
  free(t);
}

int main(void) { return nl_test_run(); }
