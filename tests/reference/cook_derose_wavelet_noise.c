/* cook_derose_wavelet_noise.c - see cook_derose_wavelet_noise.h. Line for
 * line the appendix of Cook & DeRose 2005; the comments in capitals are the
 * paper's. */
#include "reference/cook_derose_wavelet_noise.h"

#include <math.h>
#include <stdlib.h>

static int Mod(int x, int n)
{
  int m = x % n;
  return (m < 0) ? m + n : m;
}

#define ARAD 16

static void Downsample(const float *from, float *to, int n, int stride)
{
  /* the printed 32 coefficients, and a 0 for the read of a[ARAD] */
  static const float aCoeffs[2 * ARAD + 1] = {
    0.000334f, -0.001528f, 0.000410f, 0.003545f, -0.000938f, -0.008233f, 0.002172f, 0.019120f,
    -0.005040f, -0.044412f, 0.011655f, 0.103311f, -0.025936f, -0.243780f, 0.033979f, 0.655340f,
    0.655340f, 0.033979f, -0.243780f, -0.025936f, 0.103311f, 0.011655f, -0.044412f, -0.005040f,
    0.019120f, 0.002172f, -0.008233f, -0.000938f, 0.003546f, 0.000410f, -0.001528f, 0.000334f,
    0.0f};
  const float *a = &aCoeffs[ARAD];
  for (int i = 0; i < n / 2; i++) {
    to[i * stride] = 0;
    for (int k = 2 * i - ARAD; k <= 2 * i + ARAD; k++)
      to[i * stride] += a[k - 2 * i] * from[Mod(k, n) * stride];
  }
}

static void Upsample(const float *from, float *to, int n, int stride)
{
  static const float pCoeffs[4] = {0.25f, 0.75f, 0.75f, 0.25f};
  const float *p = &pCoeffs[2];
  for (int i = 0; i < n; i++) {
    to[i * stride] = 0;
    for (int k = i / 2; k <= i / 2 + 1; k++)
      to[i * stride] += p[i - 2 * k] * from[Mod(k, n / 2) * stride];
  }
}

void cd_generate_tile(float *noise, int n, int dim, int literal_shift)
{
  int nz = dim == 3 ? n : 1;
  int ix, iy, iz, i;
  size_t sz = (size_t)n * n * nz * sizeof(float);
  float *temp1 = malloc(sz), *temp2 = malloc(sz);
  int total = n * n * nz;

  /* STEPS 2 AND 3. DOWNSAMPLE AND UPSAMPLE THE TILE */
  for (iy = 0; iy < n; iy++)
    for (iz = 0; iz < nz; iz++) {   /* EACH X ROW */
      i = iy * n + iz * n * n;
      Downsample(&noise[i], &temp1[i], n, 1);
      Upsample(&temp1[i], &temp2[i], n, 1);
    }
  for (ix = 0; ix < n; ix++)
    for (iz = 0; iz < nz; iz++) {   /* EACH Y ROW */
      i = ix + iz * n * n;
      Downsample(&temp2[i], &temp1[i], n, n);
      Upsample(&temp1[i], &temp2[i], n, n);
    }
  if (dim == 3)
    for (ix = 0; ix < n; ix++)
      for (iy = 0; iy < n; iy++) {   /* EACH Z ROW */
        i = ix + iy * n;
        Downsample(&temp2[i], &temp1[i], n, n * n);
        Upsample(&temp1[i], &temp2[i], n, n * n);
      }

  /* STEP 4. SUBTRACT OUT THE COARSE-SCALE CONTRIBUTION */
  for (i = 0; i < total; i++)
    noise[i] -= temp2[i];

  /* AVOID EVEN/ODD VARIANCE DIFFERENCE BY ADDING ODD-OFFSET VERSION OF NOISE
   * TO ITSELF. */
  int offset = n / 2;
  if (offset % 2 == 0)
    offset++;
  for (i = 0, ix = 0; ix < n; ix++)
    for (iy = 0; iy < n; iy++)
      for (iz = 0; iz < nz; iz++) {
        int to = literal_shift ? i++ : ix + iy * n + iz * n * n;
        int z = dim == 3 ? Mod(iz + offset, n) * n * n : 0;
        temp1[to] = noise[Mod(ix + offset, n) + Mod(iy + offset, n) * n + z];
      }
  for (i = 0; i < total; i++)
    noise[i] += temp1[i];
  free(temp1);
  free(temp2);
}

double cd_wnoise(const float *tile, int n, int dim, const double *p)
{
  int i, f[3], c[3], mid[3] = {0};   /* F, C = FILTER, NOISE COEFF INDICES */
  double w[3][3], t, result = 0;

  /* EVALUATE QUADRATIC B-SPLINE BASIS FUNCTIONS */
  for (i = 0; i < dim; i++) {
    mid[i] = (int)ceil(p[i] - 0.5);
    t = mid[i] - (p[i] - 0.5);
    w[i][0] = t * t / 2;
    w[i][2] = (1 - t) * (1 - t) / 2;
    w[i][1] = 1 - w[i][0] - w[i][2];
  }
  if (dim == 2) {   /* the z loop of one pass, at c[2] = 0 with weight 1 */
    mid[2] = 1;
    w[2][0] = 1;
  }

  /* EVALUATE NOISE BY WEIGHTING NOISE COEFFICIENTS BY BASIS FUNCTION VALUES */
  for (f[2] = -1; f[2] <= (dim == 3 ? 1 : -1); f[2]++)
    for (f[1] = -1; f[1] <= 1; f[1]++)
      for (f[0] = -1; f[0] <= 1; f[0]++) {
        double weight = 1;
        for (i = 0; i < 3; i++) {
          c[i] = Mod(mid[i] + f[i], n);
          weight *= w[i][f[i] + 1];
        }
        result += weight * tile[(dim == 3 ? c[2] * n * n : 0) + c[1] * n + c[0]];
      }
  return result;
}
