/* nl_simd_lanes.h - library-internal: table lookups lane by lane,
 * for the levels that include it after defining NL_SIMD_W and the vector
 * types vd (doubles) and vi (int indices). On the machines measured (AMD
 * Zen 4) a gather instruction costs more than its loads one by one. */
#include <string.h>

static inline vd v_gd(const double *b, vi i)
{
  double r[NL_SIMD_W];
  for (int l = 0; l < NL_SIMD_W; l++) r[l] = b[i[l]];
  vd v; memcpy(&v, r, sizeof v); return v;
}
static inline vi v_gi(const int *b, vi i)
{
  int r[NL_SIMD_W];
  for (int l = 0; l < NL_SIMD_W; l++) r[l] = b[i[l]];
  vi v; memcpy(&v, r, sizeof v); return v;
}
