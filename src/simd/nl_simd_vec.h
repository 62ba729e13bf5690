/* nl_simd_vec.h - library-internal: unaligned loads and stores and a
 * broadcast, for the kernels of every level. Included after the level's
 * header (nl_simd_sse2.h, ...) and a definition of NL_SIMD_W, its lanes. */
#ifndef NL_SIMD_VEC_H
#define NL_SIMD_VEC_H
#include <string.h>

static inline vd ld(const double *p)   /* loadu */
{
  vd v;
  memcpy(&v, p, sizeof v);
  return v;
}
static inline void st(double *p, vd v) { memcpy(p, &v, sizeof v); }   /* storeu */
/* A broadcast; not 0 + x, which turns -0 into +0. */
static inline vd splat(double x)
{
  vd v;
  for (int l = 0; l < NL_SIMD_W; l++) v[l] = x;
  return v;
}
#define SPLAT(x) splat((double)(x))

#endif
