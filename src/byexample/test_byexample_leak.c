#include "byexample/nl_byexample_leak.h"
#include "nl_test.h"

#include <math.h>
#include <stdlib.h>

/* NNLS against scipy.optimize.nnls (scipy 1.10.1, /usr/bin/python3, run
 * once): x and the residual norm agree to 1e-12 (the problems are well
 * conditioned; both solve the same passive-set least squares). */
NL_TEST(nnls_matches_scipy)
{
  static const double M1[] = {1, 0, 1, 0, 0, 1}, b1[] = {2, 1, 1};
  static const double M2[] = {1, 2, 3, 4, 5, 6}, b2[] = {1, -1, 2};
  static const double M3[] = {0.9, 0.07, 0.01, 0, 0.07, 0.86, 0.07, 0.01, 0.01, 0.07, 0.86, 0.07, 0, 0.01, 0.07, 0.9};
  static const double b3[] = {1.0, 0.05, 0.8, 0.02};
  static const double M4[] = {2, -1, 0.5, 3, 1, 4, -2, 0.5, -1, 0.5, 3, 1, 0.5, 1, 1, -2, 3, 0, 1, 1};
  static const double b4[] = {1, -2, 3, 0.5, -1};
  static const double x1[] = {1.4999999999999998, 1.0}, x2[] = {0.22857142857142868, 0.0};
  static const double x3[] = {1.0934202253266132, 0.0, 0.9050007270582405, 0.0};
  static const double x4[] = {0.0, 0.0, 0.8428610880972106, 0.05854736260701447};
  struct { const double *M, *b, *x; int m, n; double r; } P[] = {
    {M1, b1, x1, 3, 2, 0.7071067811865475}, {M2, b2, x2, 3, 2, 2.0424075429327444},
    {M3, b3, x3, 4, 4, 0.10061040485732607}, {M4, b4, x4, 5, 4, 2.0290795368627657}};
  for (int p = 0; p < 4; p++) {
    double x[4];
    double r = nl_byexample_nnls(P[p].M, P[p].m, P[p].n, P[p].b, x);
    NL_CHECK_NEAR(r, P[p].r, 1e-12);
    for (int j = 0; j < P[p].n; j++) {
      NL_CHECK_NEAR(x[j], P[p].x[j], 1e-12);
      NL_CHECK(x[j] >= 0);
    }
  }
}

/* The transfer matrix of 128 x 128 noise: each band keeps most of its power
 * and gives some to its neighbours; the taper removes the edge leakage two
 * or more bands finer (i > j + 1) that the raw DFT shows. */
NL_TEST(transfer_matrix)
{
  nl_byexample_transfer T;
  int nb = nl_byexample_band_count(128, 128);
  NL_CHECK(nl_byexample_transfer_measure(&T, NL_BYEXAMPLE_TILE, 128, 128, nb, 1.0, 2, 7, 1, NULL) == NL_OK);
  double far[2] = {0, 0};
  for (int i = 0; i < nb; i++) {
    double tot = 0;
    for (int j = 0; j < nb; j++) tot += T.A[NL_BYEXAMPLE_TAPER][i * nb + j];
    printf("  band %d: raw diag %.3f, Hann diag %.3f of sigma_N^2 %.4f\n", i,
           T.A[0][i * nb + i] / T.sigma2, T.A[1][i * nb + i] / T.sigma2, T.sigma2);
    NL_CHECK(T.A[NL_BYEXAMPLE_TAPER][i * nb + i] > 0.5 * tot);
    for (int j = 0; j + 1 < i; j++) { far[0] += T.A[0][i * nb + j]; far[1] += T.A[1][i * nb + j]; }
  }
  printf("  power 2+ bands finer: raw %.3g, Hann %.3g\n", far[0], far[1]);
  NL_CHECK(far[1] < 0.1 * far[0]);
}

int main(void) { return nl_test_run(); }
