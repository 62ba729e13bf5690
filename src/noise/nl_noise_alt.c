#include "noise/nl_noise_alt.h"

#include "base/nl_base.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <string.h>

/* Perlin 2002's grad(hash, x, y, z) as vectors (as in nl_noise.c). */
static const double edge[16][3] = {
  {1,1,0},{-1,1,0},{1,-1,0},{-1,-1,0},{1,0,1},{-1,0,1},{1,0,-1},{-1,0,-1},
  {0,1,1},{0,-1,1},{0,1,-1},{0,-1,-1},{1,1,0},{0,-1,1},{-1,1,0},{0,-1,-1}};

static void take_perm(nl_noise_alt *t, const nl_noise_perm3 *p, int quintic)
{
  memcpy(t->p, p->p, sizeof t->p);
  t->quintic = quintic;
  t->line1 = 0;
  t->f32 = 0;
  t->simplex_r2 = 0.0;
  t->plane = 0;
}

void nl_noise_alt_improved(nl_noise_alt *t, const nl_noise_perm3 *p, int quintic)
{
  take_perm(t, p, quintic);
  for (int h = 0; h < 256; h++) memcpy(t->g[h], edge[h & 15], sizeof t->g[h]);
}

void nl_noise_alt_classic(nl_noise_alt *t, const nl_noise_perm3 *p, unsigned long seed)
{
  take_perm(t, p, 0);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, nl_seed_stream(seed, "noise.alt.classic", 0));
  for (int h = 0; h < 256; h++) {
    double v[3], s;
    do {   /* Perlin 1985: a point uniform in the unit ball, normalised */
      s = 0.0;
      for (int a = 0; a < 3; a++) { v[a] = 2.0 * gsl_rng_uniform(r) - 1.0; s += v[a] * v[a]; }
    } while (s > 1.0 || s < 1e-12);
    for (int a = 0; a < 3; a++) t->g[h][a] = v[a] / sqrt(s);
  }
  gsl_rng_free(r);
}

void nl_noise_alt_line1(nl_noise_alt *t, const nl_noise_perm3 *p, unsigned long seed, int quintic)
{
  take_perm(t, p, quintic);
  t->line1 = 1;
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, nl_seed_stream(seed, "noise.alt.line1", 0));
  for (int h = 0; h < 256; h++) {
    t->g[h][0] = 2.0 * gsl_rng_uniform(r) - 1.0;
    t->g[h][1] = t->g[h][2] = 0.0;
  }
  gsl_rng_free(r);
}

void nl_noise_alt_simplex(nl_noise_alt *t, const nl_noise_perm3 *p, double r2)
{
  take_perm(t, p, 1);
  t->simplex_r2 = r2;
  for (int h = 0; h < 256; h++) memcpy(t->g[h], edge[h % 12], sizeof t->g[h]);
}

void nl_noise_alt_simplex2(nl_noise_alt *t, const nl_noise_perm3 *p)
{
  nl_noise_alt_simplex(t, p, 0.5);
  t->plane = 1;
}

void nl_noise_alt_gpu8(nl_noise_alt *t)
{
  /* An RGBA8 texel stores (g + 1)/2 in [0, 1] as the nearest of 0..255;
   * the shader reads it back as byte / 255 * 2 - 1 (0 becomes 1/255). */
  for (int h = 0; h < 256; h++)
    for (int a = 0; a < 3; a++) t->g[h][a] = round((t->g[h][a] + 1.0) * 0.5 * 255.0) / 255.0 * 2.0 - 1.0;
  t->f32 = 1;
}

/* Perlin's trilinear blend of the eight corner dot products, in type T. */
#define ALT_EVAL(name, T, FLOOR)                                                        \
  static double name(const nl_noise_alt *t, T x, T y, T z)                              \
  {                                                                                     \
    T fx = FLOOR(x), fy = FLOOR(y), fz = FLOOR(z);                                      \
    int X = (int)((long)fx & 255), Y = (int)((long)fy & 255), Z = (int)((long)fz & 255); \
    x -= fx; y -= fy; z -= fz;                                                          \
    T u = t->quintic ? x * x * x * (x * (x * (T)6 - (T)15) + (T)10) : x * x * ((T)3 - (T)2 * x); \
    if (t->line1) {                                                                     \
      T a = (T)t->g[t->p[X]][0] * x, b = (T)t->g[t->p[X + 1]][0] * (x - (T)1);          \
      return (double)(a + u * (b - a));                                                 \
    }                                                                                   \
    T v = t->quintic ? y * y * y * (y * (y * (T)6 - (T)15) + (T)10) : y * y * ((T)3 - (T)2 * y); \
    T w = t->quintic ? z * z * z * (z * (z * (T)6 - (T)15) + (T)10) : z * z * ((T)3 - (T)2 * z); \
    T c[2][2][2];                                                                       \
    for (int i = 0; i < 2; i++)                                                         \
      for (int j = 0; j < 2; j++)                                                       \
        for (int k = 0; k < 2; k++) {                                                   \
          const double *g = t->g[t->p[t->p[t->p[X + i] + Y + j] + Z + k]];              \
          c[i][j][k] = (T)g[0] * (x - (T)i) + (T)g[1] * (y - (T)j) + (T)g[2] * (z - (T)k); \
        }                                                                               \
    T e[2][2];                                                                          \
    for (int j = 0; j < 2; j++)                                                         \
      for (int k = 0; k < 2; k++) e[j][k] = c[0][j][k] + u * (c[1][j][k] - c[0][j][k]); \
    T f0 = e[0][0] + v * (e[1][0] - e[0][0]), f1 = e[0][1] + v * (e[1][1] - e[0][1]);   \
    return (double)(f0 + w * (f1 - f0));                                                \
  }
ALT_EVAL(eval_f64, double, floor)
ALT_EVAL(eval_f32, float, floorf)

/* Gustavson 2005, 3D: skew to the simplex lattice, find the simplex
 * (which of the 6 orderings of the offsets), sum the 4 corner kernels. */
static double simplex3(const nl_noise_alt *t, double x, double y, double z)
{
  const double F3 = 1.0 / 3.0, G3 = 1.0 / 6.0;
  double s = (x + y + z) * F3;
  long i = (long)floor(x + s), j = (long)floor(y + s), k = (long)floor(z + s);
  double u = (double)(i + j + k) * G3, d[4][3];
  d[0][0] = x - ((double)i - u); d[0][1] = y - ((double)j - u); d[0][2] = z - ((double)k - u);
  int o1[3] = {0, 0, 0}, o2[3] = {1, 1, 1};   /* second corner: the largest offset; third: all but the smallest */
  const double *d0 = d[0];
  if (d0[0] >= d0[1]) {
    if (d0[1] >= d0[2]) { o1[0] = 1; o2[2] = 0; }
    else if (d0[0] >= d0[2]) { o1[0] = 1; o2[1] = 0; }
    else { o1[2] = 1; o2[1] = 0; }
  } else {
    if (d0[1] < d0[2]) { o1[2] = 1; o2[0] = 0; }
    else if (d0[0] < d0[2]) { o1[1] = 1; o2[0] = 0; }
    else { o1[1] = 1; o2[2] = 0; }
  }
  for (int q = 0; q < 3; q++) {
    d[1][q] = d0[q] - o1[q] + G3;
    d[2][q] = d0[q] - o2[q] + 2.0 * G3;
    d[3][q] = d0[q] - 1.0 + 3.0 * G3;
  }
  int ii = (int)(i & 255), jj = (int)(j & 255), kk = (int)(k & 255);
  int off[4][3] = {{0, 0, 0}, {o1[0], o1[1], o1[2]}, {o2[0], o2[1], o2[2]}, {1, 1, 1}};
  double n = 0.0;
  for (int q = 0; q < 4; q++) {
    double r = t->simplex_r2 - d[q][0] * d[q][0] - d[q][1] * d[q][1] - d[q][2] * d[q][2];
    if (r <= 0.0) continue;
    const double *g = t->g[t->p[ii + off[q][0] + t->p[jj + off[q][1] + t->p[kk + off[q][2]]]]];
    r *= r;
    n += r * r * (g[0] * d[q][0] + g[1] * d[q][1] + g[2] * d[q][2]);
  }
  return 32.0 * n;
}

/* Gustavson 2005, 2D: skew to the triangle lattice, 3 corner kernels. */
static double simplex2(const nl_noise_alt *t, double x, double y)
{
  const double F2 = 0.5 * (sqrt(3.0) - 1.0), G2 = (3.0 - sqrt(3.0)) / 6.0;
  double s = (x + y) * F2;
  long i = (long)floor(x + s), j = (long)floor(y + s);
  double u = (double)(i + j) * G2, d[3][2];
  d[0][0] = x - ((double)i - u); d[0][1] = y - ((double)j - u);
  int i1 = d[0][0] > d[0][1], j1 = !i1;   /* lower or upper triangle */
  d[1][0] = d[0][0] - i1 + G2; d[1][1] = d[0][1] - j1 + G2;
  d[2][0] = d[0][0] - 1.0 + 2.0 * G2; d[2][1] = d[0][1] - 1.0 + 2.0 * G2;
  int ii = (int)(i & 255), jj = (int)(j & 255), off[3][2] = {{0, 0}, {i1, j1}, {1, 1}};
  double n = 0.0;
  for (int q = 0; q < 3; q++) {
    double r = t->simplex_r2 - d[q][0] * d[q][0] - d[q][1] * d[q][1];
    if (r <= 0.0) continue;
    const double *g = t->g[t->p[ii + off[q][0] + t->p[jj + off[q][1]]]];
    r *= r;
    n += r * r * (g[0] * d[q][0] + g[1] * d[q][1]);
  }
  return 70.0 * n;
}

double nl_noise_alt_eval(const nl_noise_alt *t, double x, double y, double z)
{
  if (t->simplex_r2 > 0.0 && t->plane) return simplex2(t, x, y);
  if (t->simplex_r2 > 0.0) return simplex3(t, x, y, z);
  return t->f32 ? eval_f32(t, (float)x, (float)y, (float)z) : eval_f64(t, x, y, z);
}
