/* nl_noise_f32_impl.h - what the float32 noise kernels share (dispatch in
 * nl_noise_f32.c, vector levels in nl_noise_f32_avx2.c and
 * nl_noise_f32_avx512.c). Library-internal, never installed. */
#ifndef NL_NOISE_F32_IMPL_H
#define NL_NOISE_F32_IMPL_H

#include "noise/nl_noise.h"

#include <stddef.h>
#include <stdint.h>

/* A sum of octaves in float: f = (float)freq, a = (float)amp. */
typedef struct {
  int n, turbulence;
  float f[NL_MAX_OCTAVES], a[NL_MAX_OCTAVES];
} nl_f32_oct;

/* The 2D table as the kernels read it (m a power of two, m <= 2^24).
 * pp and g4 are built only for batches: pp[s] = 4 P[s mod m] (s <= m) and
 * g4[4 s .. 4 s + 3] = (float) gx, gy of entries P[s mod m] and
 * P[(s + 1) mod m] (s < 2 m), so that a column's two corners (dy = 0, 1)
 * are the 16 bytes at g4 + pp[i] + 4 j, with no reduction mod m (P[i] + j
 * < 2 m). */
typedef struct {
  const nl_noise_grad2 *t;
  unsigned m, km;
  const uint32_t *pp;
  const float *g4;
} nl_f32_g2;

/* o NULL: the noise itself; else the sum of octaves. */
typedef struct {
  void (*p3_points)(const nl_noise_perm3 *p, const nl_f32_oct *o, const float *x, const float *y,
                    const float *z, size_t n, float *out);
  void (*p3_row)(const nl_noise_perm3 *p, const nl_f32_oct *o, float x0, float dx, float y, float z,
                 size_t n, float *out);
  void (*g2_points)(const nl_f32_g2 *t, const nl_f32_oct *o, const float *x, const float *y, size_t n,
                    float *out);
  void (*g2_row)(const nl_f32_g2 *t, const nl_f32_oct *o, float x0, float dx, float y, size_t n,
                 float *out);
} nl_f32_kernels;

extern const nl_f32_kernels nl_noise_f32_avx2, nl_noise_f32_avx512;
/* Perlin 2002's 16 gradients (12 edges, 4 repeated), one array per component. */
extern const float nl_noise_f32_g3[3][16];

#endif
