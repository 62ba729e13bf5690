/* Unit tests of A4's line (line.c). */
#include "line.h"
#include "nl_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

NL_TEST(line_direction_and_sample)
{
  /* (1, 1/phi, 1/phi^2) normalised, to 5 digits */
  nl_study_line l = a4_line();
  double phi = 0.5 * (1.0 + sqrt(5.0)), d[3] = { 1.0, 1.0 / phi, 1.0 / (phi * phi) };
  double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  for (int k = 0; k < 3; k++) NL_CHECK(fabs(l.dir[k] - d[k] / len) < 1e-5);
  /* noise(f p) along the line, the bits of nl_bounds_sample_line */
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 2);
  size_t n;
  double *x = a4_line_sample(&p, 0.5, 16.0, 4.0, &n);
  NL_CHECK(n == 64);
  nl_noise_octaves o = nl_noise_octaves_fbm(1, 1.0, 1.0);
  o.freq[0] = 0.5;
  double y[64];
  nl_bounds_sample_line(&p, &o, l.origin, l.dir, 4.0, 64, y);
  NL_CHECK(memcmp(x, y, sizeof y) == 0);
  free(x);
}

int main(void) { return nl_test_run(); }
