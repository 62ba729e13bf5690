/* expect.c - L1's exact expectation of the band variance (expect.h). The
 * filters are typed here from Cook & DeRose's appendix, not taken from
 * src/wavelet, so that the value does not share code with the tile. */
#include "expect.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The appendix's aCoeffs, first half (the second half is its mirror). */
static const double AH[16] = { 0.000334,  -0.001528, 0.000410,  0.003545,  -0.000938, -0.008233,
                               0.002172,  0.019120,  -0.005040, -0.044412, 0.011655,  0.103311,
                               -0.025936, -0.243780, 0.033979,  0.655340 };

/* analysis tap j in [-16, 15] */
static double atap(int j) { return j < 0 ? AH[j + 16] : AH[15 - j]; }

/* upsampling tap j = i - 2k in [-2, 1] (the appendix's p = &pCoeffs[2]) */
static double ptap(int j)
{
  static const double PC[4] = { 0.25, 0.75, 0.75, 0.25 };
  return PC[j + 2];
}

static int wrap(int i, int n) { return ((i % n) + n) % n; }

double l1_bspline(double x)
{
  x = fabs(x);
  if (x < 0.5) return 0.75 - x * x;
  if (x < 1.5) return 0.5 * (1.5 - x) * (1.5 - x);
  return 0;
}

double l1_bspline_autocorrelation(int d, int per_unit)
{
  if (abs(d) > 2) return 0;
  if (per_unit <= 0) {
    static const double A[3] = { 11.0 / 20, 13.0 / 60, 1.0 / 120 };
    return A[abs(d)];
  }
  double s = 0;
  for (int q = 0; q < per_unit; q++) {
    double x = (q + 0.5) / per_unit;
    for (int m = -3; m <= 3; m++) s += l1_bspline(x - m) * l1_bspline(x - m - d);
  }
  return s / per_unit;
}

/* c = a b, n x n row-major */
static void mul(const double *a, const double *b, double *c, int n)
{
  memset(c, 0, (size_t)n * n * sizeof *c);
  for (int i = 0; i < n; i++)
    for (int k = 0; k < n; k++) {
      double v = a[(size_t)i * n + k];
      if (v == 0) continue;
      for (int j = 0; j < n; j++) c[(size_t)i * n + j] += v * b[(size_t)k * n + j];
    }
}

static void transpose(const double *a, double *t, int n)
{
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) t[(size_t)j * n + i] = a[(size_t)i * n + j];
}

/* tr(A1 Y) for the circulant A1 (a by lag) */
static double trace_a(const double *y, const double *a, int n)
{
  double t = 0;
  for (int i = 0; i < n; i++)
    for (int d = -2; d <= 2; d++) t += a[d + 2] * y[(size_t)wrap(i + d, n) * n + i];
  return t;
}

/* The 16 traces tr(A1 Z) of the header, Z = Y, s Y, Y s^T, s Y s^T for Y = I,
 * P, P^T, P P^T (t[4 y + j]); 1 for bad arguments. */
static int traces(int n, int per_unit, double t[16])
{
  if (n < 8 || n % 2) return 1;
  int h = n / 2, off = n / 2 + (n / 2 % 2 == 0);
  size_t nn = (size_t)n * n;
  double *D = calloc((size_t)h * n, sizeof *D); /* h x n */
  double *work = calloc(8 * nn, sizeof *work);
  double *Y[4] = { work, work + nn, work + 2 * nn, work + 3 * nn };
  double *s = work + 4 * nn, *st = work + 5 * nn, *z = work + 6 * nn, *z2 = work + 7 * nn;
  for (int i = 0; i < h; i++)
    for (int k = 2 * i - 16; k < 2 * i + 16; k++) D[(size_t)i * n + wrap(k, n)] += atap(k - 2 * i);
  for (int i = 0; i < n; i++) { /* P = U D, U[i][k] = p(i - 2k), k = i/2, i/2 + 1 (mod h) */
    Y[0][(size_t)i * n + i] = 1;
    for (int k = i / 2; k <= i / 2 + 1; k++)
      for (int j = 0; j < n; j++)
        Y[1][(size_t)i * n + j] += ptap(i - 2 * k) * D[(size_t)wrap(k, h) * n + j];
    s[(size_t)i * n + wrap(i + off, n)] = 1; /* (s x)[i] = x[i + off] */
  }
  transpose(Y[1], Y[2], n);
  mul(Y[1], Y[2], Y[3], n);
  transpose(s, st, n);
  double a[5];
  for (int d = -2; d <= 2; d++) a[d + 2] = l1_bspline_autocorrelation(d, per_unit);
  for (int y = 0; y < 4; y++) {
    t[4 * y] = trace_a(Y[y], a, n);
    mul(s, Y[y], z, n);
    t[4 * y + 1] = trace_a(z, a, n);
    mul(z, st, z2, n);
    t[4 * y + 3] = trace_a(z2, a, n);
    mul(Y[y], st, z, n);
    t[4 * y + 2] = trace_a(z, a, n);
  }
  free(D);
  free(work);
  return 0;
}

void l1_variance_expected2(int n, int per_unit, double *v2, double *v3)
{
  double t[16];
  *v2 = *v3 = NAN;
  if (traces(n, per_unit, t)) return;
  static const double sign[4] = { 1, -1, -1, 1 }; /* M M^T = I - P - P^T + P P^T, per axis */
  double s2 = 0, s3 = 0;
  for (int i = 0; i < 16; i++) {
    s2 += sign[i / 4] * t[i] * t[i];
    s3 += sign[i / 4] * t[i] * t[i] * t[i];
  }
  *v2 = s2 / ((double)n * n);
  *v3 = s3 / ((double)n * n * n);
}

double l1_variance_expected(int dim, int n, int per_unit)
{
  double v2, v3;
  if (dim != 2 && dim != 3) return NAN;
  l1_variance_expected2(n, per_unit, &v2, &v3);
  return dim == 2 ? v2 : v3;
}
