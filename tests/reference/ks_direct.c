/* ks_direct.c - see ks_direct.h. */
#include "reference/ks_direct.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void ks_direct_one(const double *x, size_t n, double (*cdf)(double), double *d_plus,
                   double *d_minus)
{
  double dp = -INFINITY, dm = -INFINITY;
  for (size_t a = 0; a < n; a++) {
    size_t le = 0, lt = 0;
    for (size_t b = 0; b < n; b++) {
      le += x[b] <= x[a];
      lt += x[b] < x[a];
    }
    double F = cdf(x[a]);
    dp = fmax(dp, (double)le / (double)n - F);
    dm = fmax(dm, F - (double)lt / (double)n);
  }
  *d_plus = dp;
  *d_minus = dm;
}

void ks_direct_two(const double *x, size_t n1, const double *y, size_t n2, double *d_plus,
                   double *d_minus, long *num)
{
  double dp = 0, dm = 0;
  long most = 0;
  for (size_t a = 0; a < n1 + n2; a++) {
    double t = a < n1 ? x[a] : y[a - n1];
    size_t c1 = 0, c2 = 0;
    for (size_t b = 0; b < n1; b++)
      c1 += x[b] <= t;
    for (size_t b = 0; b < n2; b++)
      c2 += y[b] <= t;
    double diff = (double)c1 / (double)n1 - (double)c2 / (double)n2;
    dp = fmax(dp, diff);
    dm = fmax(dm, -diff);
    long k = labs((long)c1 * (long)n2 - (long)c2 * (long)n1);
    most = k > most ? k : most;
  }
  *d_plus = dp;
  *d_minus = dm;
  if (num)
    *num = most;
}

long double ks_birnbaum_tingey(int n, long double d)
{
  if (d <= 0)
    return 1;
  if (d >= 1)
    return 0;
  long double sum = 0, binom = 1;   /* C(n, j) */
  int top = (int)floorl((long double)n * (1 - d));
  for (int j = 0; j <= top; j++) {
    long double a = 1 - d - (long double)j / n, b = d + (long double)j / n;
    if (j > 0)
      binom = binom * (n - j + 1) / j;
    sum += binom * powl(a, n - j) * powl(b, j - 1);
  }
  return d * sum;
}

static void matmul(const long double *A, const long double *B, long double *C, int m)
{
  for (int i = 0; i < m; i++)
    for (int j = 0; j < m; j++) {
      long double s = 0;
      for (int k = 0; k < m; k++)
        s += A[i * m + k] * B[k * m + j];
      C[i * m + j] = s;
    }
}

long double ks_durbin_cdf(int n, long double d)
{
  if (d <= 0.5L / n)
    return 0;
  if (d >= 1)
    return 1;
  int k = (int)floorl(n * d) + 1, m = 2 * k - 1;
  long double h = k - n * d;
  size_t sz = (size_t)m * m * sizeof(long double);
  long double *H = calloc(1, sz), *R = calloc(1, sz), *T = calloc(1, sz);
  for (int i = 0; i < m; i++)
    for (int j = 0; j < m; j++)
      H[i * m + j] = i - j + 1 >= 0 ? 1 : 0;
  for (int i = 0; i < m; i++) {
    H[i * m] -= powl(h, i + 1);
    H[(m - 1) * m + i] -= powl(h, m - i);
  }
  if (2 * h - 1 > 0)
    H[(m - 1) * m] += powl(2 * h - 1, m);
  for (int i = 0; i < m; i++)
    for (int j = 0; j < m; j++)
      if (i - j + 1 > 0)
        for (int g = 1; g <= i - j + 1; g++)
          H[i * m + j] /= g;
  /* R = H^n by repeated squaring */
  for (int i = 0; i < m; i++)
    for (int j = 0; j < m; j++)
      R[i * m + j] = i == j;
  for (int e = n; e > 0; e >>= 1) {
    if (e & 1) {
      matmul(R, H, T, m);
      memcpy(R, T, sz);
    }
    matmul(H, H, T, m);
    memcpy(H, T, sz);
  }
  long double s = R[(k - 1) * m + (k - 1)];
  for (int i = 1; i <= n; i++)   /* n! / n^n */
    s = s * i / n;
  free(H);
  free(R);
  free(T);
  return s;
}

long double ks_kolmogorov_sf(long double lambda)
{
  if (lambda <= 0)
    return 1;
  const long double pi = 3.141592653589793238462643383279502884L;
  if (lambda < 1) {   /* P(K <= l) = sqrt(2 pi) / l sum_j e^{-(2j-1)^2 pi^2 / (8 l^2)} */
    long double s = 0;
    for (int j = 1; j < 50; j++)
      s += expl(-(2.0L * j - 1) * (2.0L * j - 1) * pi * pi / (8 * lambda * lambda));
    return 1 - sqrtl(2 * pi) / lambda * s;
  }
  long double s = 0;
  for (int j = 1; j < 50; j++)
    s += (j % 2 ? 2 : -2) * expl(-2.0L * j * j * lambda * lambda);
  return s;
}

long double ks2_paths_sf(int n1, int n2, long dnum)
{
  /* p[j] over i: the probability that the ordering's first i + j values
   * hold i of sample 1 and j of sample 2 with every prefix inside. */
  long double *p = calloc((size_t)n2 + 1, sizeof *p);
  for (int i = 0; i <= n1; i++)
    for (int j = 0; j <= n2; j++) {
      long double v;
      if (i == 0 && j == 0)
        v = 1;
      else {
        v = 0;
        int left = n1 + n2 - (i + j - 1);   /* values not yet placed before this step */
        if (i > 0)   /* from (i-1, j): a sample-1 value next */
          v += p[j] * (long double)(n1 - i + 1) / left;
        if (j > 0)   /* from (i, j-1) */
          v += p[j - 1] * (long double)(n2 - j + 1) / left;
      }
      if (labs((long)i * n2 - (long)j * n1) >= dnum)
        v = 0;
      p[j] = v;
    }
  long double inside = p[n2];
  free(p);
  return 1 - inside;
}
