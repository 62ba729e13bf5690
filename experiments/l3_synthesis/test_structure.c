/* Unit tests of L3's structure statistics (structure.c) on images whose
 * answer is known without the code: straight stripes have one gradient
 * orientation everywhere (coherence 1, one orientation bin), white noise has
 * none (coherence far below 1, orientations spread over every bin). */
#include "nl_test.h"
#include "structure.h"

#include <gsl/gsl_rng.h>
#include <math.h>

enum { N = 64 };

NL_TEST(structure_stripes)
{
  nl_image *im = nl_image_alloc(N, N, 1);
  for (int y = 0; y < N; y++)
    for (int x = 0; x < N; x++) im->data[y * N + x] = (float)(0.5 + 0.4 * sin(2 * M_PI * x / 9.0));
  l3_structure s;
  l3_structure_measure(im, &s);
  NL_CHECK_NEAR(s.coherence, 1, 1e-9); /* gradients along x only: lambda2 = 0 */
  /* gradient angle 0 or pi (mod pi: 0) -> bin 0 holds every gradient */
  NL_CHECK_NEAR(s.orient[0], 1, 1e-12);
  l3_structure t = s;
  for (int b = 0; b < L3_ORIENT_BINS; b++) t.orient[b] = b == L3_ORIENT_BINS / 2;
  NL_CHECK_NEAR(l3_structure_orient_distance(&s, &t), 1, 1e-12); /* disjoint histograms */
  NL_CHECK_NEAR(l3_structure_orient_distance(&s, &s), 0, 0);
  nl_image_free(im);
}

NL_TEST(structure_noise)
{
  nl_image *im = nl_image_alloc(N, N, 1);
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 1);
  for (int i = 0; i < N * N; i++) im->data[i] = (float)gsl_rng_uniform(rng);
  l3_structure s;
  l3_structure_measure(im, &s);
  /* an average over ~2 pi sigma^2 = 25 independent gradients: well below 1 (measured 0.2) */
  NL_CHECK(s.coherence > 0 && s.coherence < 0.4);
  double lo = 1, hi = 0, sum = 0;
  for (int b = 0; b < L3_ORIENT_BINS; b++) {
    lo = fmin(lo, s.orient[b]);
    hi = fmax(hi, s.orient[b]);
    sum += s.orient[b];
  }
  NL_CHECK_NEAR(sum, 1, 1e-12);
  NL_CHECK(lo > 0.5 / L3_ORIENT_BINS && hi < 2.0 / L3_ORIENT_BINS);
  gsl_rng_free(rng);
  nl_image_free(im);
}

int main(void) { return nl_test_run(); }
