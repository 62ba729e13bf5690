/* worley_cellular.c - see worley_cellular.h. */
#include "reference/worley_cellular.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

void worley_ref_init(worley_ref *w, const unsigned short *perm, double lambda, int M, int rule)
{
  w->perm = perm;
  w->M = M;
  w->rule = rule;
  double p = exp(-lambda), acc = 0;
  for (int m = 0; m <= M; m++) {
    if (m > 0)
      p = p * lambda / m;
    w->pmf[m] = p;
    acc += p;
    w->cdf[m] = acc;
  }
}

static long mod16(long v)
{
  long m = v % 65536;
  return m < 0 ? m + 65536 : m;
}

/* splitmix64's published step: add the golden gamma, then mix. */
static double next_uniform(uint64_t *s)
{
  *s += UINT64_C(0x9E3779B97F4A7C15);
  uint64_t z = *s;
  z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
  z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
  z ^= z >> 31;
  return ldexp((double)(z >> 11), -53);
}

static int count_of(const worley_ref *w, double r)
{
  if (w->rule == WORLEY_INVERSE_CDF) {
    int m = 0;
    while (m < w->M && !(r < w->cdf[m]))
      m++;
    return m;
  }
  int best = 0;
  for (int m = 1; m <= w->M; m++) {
    double d = fabs(w->pmf[m] - r), b = fabs(w->pmf[best] - r);
    if (d < b || (d == b && w->rule == WORLEY_CLOSEST_LAST))
      best = m;
  }
  return best;
}

int worley_ref_cube(const worley_ref *w, long i, long j, long k, double *xyz)
{
  long s = w->perm[mod16(k)];
  s = w->perm[mod16(j + s)];
  uint64_t state = w->perm[mod16(i + s)];
  int m = count_of(w, next_uniform(&state));
  for (int q = 0; q < m; q++) {
    xyz[3 * q] = (double)i + next_uniform(&state);
    xyz[3 * q + 1] = (double)j + next_uniform(&state);
    xyz[3 * q + 2] = (double)k + next_uniform(&state);
  }
  return m;
}

static int by_value(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

void worley_ref_d2(const worley_ref *w, const double *p, int reach, double d2[4])
{
  long side = 2 * reach + 1, cap = side * side * side * (w->M + 1);
  double *all = malloc((size_t)cap * sizeof *all), pts[3 * 65];
  long n = 0;
  long i = (long)floor(p[0]), j = (long)floor(p[1]), k = (long)floor(p[2]);
  for (long a = i - reach; a <= i + reach; a++)
    for (long b = j - reach; b <= j + reach; b++)
      for (long c = k - reach; c <= k + reach; c++) {
        int m = worley_ref_cube(w, a, b, c, pts);
        for (int q = 0; q < m; q++) {
          double dx = pts[3 * q] - p[0], dy = pts[3 * q + 1] - p[1], dz = pts[3 * q + 2] - p[2];
          all[n++] = dx * dx + dy * dy + dz * dz;
        }
      }
  qsort(all, (size_t)n, sizeof *all, by_value);
  for (int q = 0; q < 4; q++)
    d2[q] = q < n ? all[q] : INFINITY;
  free(all);
}
