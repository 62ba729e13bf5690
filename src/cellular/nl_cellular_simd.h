/* nl_cellular_simd.h - private to src/cellular: the points of a row of
 * cellular F1..F4 (nl_cellular_row) as the sample kernels read them, and the
 * kernels of each SIMD level, chosen at run time by the noise
 * library's level (nl_simd_get: NL_NOISE_SIMD, nl_simd_set).
 *
 * Per-cube distance rejection. A sample x in cube (i, j, k) looks at the
 * 27 cubes around it (nl_cellular.h). Every feature point of the neighbour
 * with column offset -1 has px <= i (px = (double)(i - 1) + u with u < 1,
 * rounded: monotone), so its computed |px - x| is at least the computed
 * x - i; likewise +1 gives px - x >= (i + 1) - x, and the same along y and
 * z. Rounding is monotone in every operation of the distance
 * (ax * ax + ay * ay) + az * az, so the bound b = (bx^2 + by^2) + bz^2,
 * evaluated in that order from the face distances, is <= the computed
 * squared distance of every point of the cube. When b >= the current
 * n-th smallest squared distance, every point of the cube would be refused
 * by the insertion (insert_d2 keeps v only if v < d2[n-1]), so skipping the
 * cube leaves d2 unchanged: the same bits, whichever cubes are skipped and
 * in whichever order the cubes are visited (d2 is the sorted n smallest of
 * the candidates, a multiset that does not depend on the order). The
 * bound needs |x|, |y|, |z| < 2^52 (cube corners exact as doubles);
 * other inputs take the full scan. test_cellular_simd.c checks every level
 * against a copy of the full scan, bit for bit.
 *
 * Visit order: the cube of x, then by increasing typical bound (the cubes
 * "near" on an axis, on the side of the nearer face, before the "far"
 * ones), so that d2[n-1] falls early and most far cubes are skipped.
 * Class code per axis: 0 the sample's own cube, 1 the near neighbour,
 * 2 the far one.
 */
#ifndef NL_CELLULAR_SIMD_H
#define NL_CELLULAR_SIMD_H

#include <stddef.h>

/* The 27 (cx, cy, cz) class triples in visit order, a code 9 cx + 3 cy + cz. */
extern const unsigned char nl_cellular_visit[27];

/* The feature points of a row (y, z fixed): column col (cube i = ifirst +
 * col) holds 9 cubes q = 3 cy + cz (cy, cz the classes of the row's j and k
 * neighbours, see by2); cube (col, q) holds points start[9 col + q] ..
 * start[9 col + q + 1] - 1, stored as px (absolute x), ay2 = (py - y)^2 and
 * az2 = (pz - z)^2, each computed as the full scan computes it. */
typedef struct {
  long ifirst;
  size_t ncol;
  const size_t *start;     /* 9 ncol + 1 */
  const double *px, *ay2, *az2;
  double by2[3], bz2[3];   /* squared face distance of class 0, 1, 2 along y, z */
} nl_cellular_rowpts;

/* out[s n + q] = F_{q+1}(x0 + s dx, y, z), s < count, 1 <= n <= 4, for a
 * row whose samples all satisfy |x| < 2^52 and lie in columns 1 .. ncol - 2
 * of R (the scalar kernel of nl_cellular.c and one per level; same bits). */
void nl_cellular_row_sse2(const nl_cellular_rowpts *R, double x0, double dx, size_t count, int n,
                          double *out);
void nl_cellular_row_avx2(const nl_cellular_rowpts *R, double x0, double dx, size_t count, int n,
                          double *out);
void nl_cellular_row_avx512(const nl_cellular_rowpts *R, double x0, double dx, size_t count, int n,
                            double *out);

#endif
