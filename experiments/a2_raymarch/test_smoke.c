/* Unit tests of A2's helpers (smoke.c): the plain/bounded render pair. */
#include "nl_test.h"
#include "smoke.h"

#include <stdlib.h>

/* A small smoke ball (the paper's settings otherwise) on the table of seed 1. */
static nl_bounds_smoke small_smoke(nl_noise_perm3 *p, int size, int octaves)
{
  nl_noise_perm3_seed(p, 1);
  nl_bounds_smoke s = nl_bounds_smoke_default();
  s.width = s.height = size;
  s.octaves = octaves;
  return s;
}

NL_TEST(smoke_render_pair)
{
  nl_noise_perm3 p;
  nl_bounds_smoke s = small_smoke(&p, 16, 4);
  double a[16 * 16], b[16 * 16];
  a2_smoke_pair t;
  NL_CHECK(a2_smoke_render_pair(&p, s, a, b, &t, NULL) == NL_OK);
  NL_CHECK(t.diff == 0 && t.evals[1] < t.evals[0] && t.samples > 0 && t.max_noise > 0);
  /* the images are the renderer's, plain then bounded */
  double c[16 * 16];
  nl_bounds_smoke_stats st;
  s.incremental = 1;
  NL_CHECK(nl_bounds_smoke_render(&p, &s, c, &st, NULL) == NL_OK);
  int same = 1;
  for (int k = 0; k < 16 * 16; k++) same &= c[k] == b[k];
  NL_CHECK(same && st.noise_evals == t.evals[1]);
  /* without images (temporaries) the same counts */
  a2_smoke_pair u;
  NL_CHECK(a2_smoke_render_pair(&p, s, NULL, NULL, &u, NULL) == NL_OK);
  NL_CHECK(u.evals[0] == t.evals[0] && u.evals[1] == t.evals[1]);
  NL_CHECK(u.samples == t.samples && u.diff == 0);
  /* plain: every term at every sample (A2's untimed count) */
  NL_CHECK(t.evals[0] == 4 * t.samples);
  s.slope = 1.0;
  NL_CHECK(a2_smoke_render_pair(&p, s, a, b, &t, NULL) == NL_EINVAL);
  NL_CHECK(a2_smoke_render_pair(&p, s, NULL, NULL, &t, NULL) == NL_EINVAL);
  s.slope = -4.0;
  s.width = 0;
  NL_CHECK(a2_smoke_render_pair(&p, s, NULL, NULL, &t, NULL) == NL_EINVAL);
}

int main(void) { return nl_test_run(); }
