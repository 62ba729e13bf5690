/* expect.h - L1's exact expectation of the band variance (expect.c).
 *
 * Cook & DeRose's appendix builds a tile as a linear map of unit Gaussian
 * values g: along each axis the coarse part is U D (D: the 32-tap analysis
 * filter and decimation, U: the upsampling filter 1/4 3/4 3/4 1/4), so with
 * P = U D (n x n, one axis) the tile is
 *     c = (I + S) (I - P x P x P) g          (x: Kronecker product, 3D)
 * where S shifts every axis by the odd offset. The noise is
 * N(p) = sum_i c_i B(p - i) with the quadratic B-spline B, so its mean
 * square over a grid of `per_unit` samples per unit and axis is c^T A c / n^d,
 * A = A1 x A1 (x A1) with A1 the circulant of a(d) = (1/S) sum_q sum_m
 * B(x_q - m) B(x_q - m - d), x_q = (q + 1/2) / S (the continuous mean as S
 * grows: 11/20, 13/60, 1/120). Its expectation is tr(A C) / n^d,
 * C = E[c c^T]; every term of C is a Kronecker power of one n x n matrix, so
 * tr(A C) = sum of +- tr(A1 Y)^d over Y in {I, P, P^T, P P^T}, each also
 * shifted by s on the left, on the right (s^T) or both. No random numbers,
 * no tile, no evaluation code shared with the measurement: an independent
 * value for the volume reading of L1. */
#ifndef L1_EXPECT_H
#define L1_EXPECT_H

/* E[<N^2>] on the grid of per_unit samples per unit and axis (0: the
 * continuous mean) of a tile of dimension dim (2 or 3) and even period
 * n >= 8, built as above. NAN for bad arguments. */
double l1_variance_expected(int dim, int n, int per_unit);
/* Both at once (2D in *v2, 3D in *v3: the same traces, squared and cubed). */
void l1_variance_expected2(int n, int per_unit, double *v2, double *v3);

/* a(d) of the header for per_unit samples (0: continuous), |d| <= 2 (else 0). */
double l1_bspline_autocorrelation(int d, int per_unit);

/* The quadratic B-spline centred at 0, support [-3/2, 3/2]. */
double l1_bspline(double x);

#endif
