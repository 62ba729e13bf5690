/* nl_noise_simd.h - private: the kernels behind the run-time dispatch of
 * nl_noise.c's rows and the batch point API.
 *
 * One table of kernels per instruction-set level. nl_noise_simd_body.h holds
 * the kernels once, written with GCC vector extensions; nl_noise_simd_sse2.c,
 * _avx2.c and _avx512.c each include it under their own `#pragma GCC target`
 * with the few primitives that differ (floor, table lookups, lane tests).
 * The build never uses -march: the dispatcher (nl_noise_simd.c) asks the CPU
 * (__builtin_cpu_supports) which tables it may call.
 *
 * Bit-identity with the scalar code of nl_noise.c is the contract: every
 * kernel performs, per lane, the same IEEE operations in the same order as
 * the scalar function it replaces (no FMA: the project compiles with
 * -ffp-contract=off and these files contain no fused intrinsics). The
 * integer parts may differ (masks instead of lmod for power-of-two tables,
 * floor by rounding instruction instead of truncate-and-correct) only where
 * they give the same integers, which the preconditions below guarantee.
 * test_noise_simd.c checks every level the CPU runs against the scalar path.
 */
#ifndef NL_NOISE_SIMD_H
#define NL_NOISE_SIMD_H

#include "noise/nl_noise.h"
#include "noise/nl_noise_lattice.h"
#include <stddef.h>

/* Columns spanned by a row; 0 when sampling is so sparse (more than two
 * columns per sample) that collapsing columns costs more than it saves.
 * The scalar row (nl_noise.c) and the SIMD row drivers share it, so both
 * collapse the same rows. */
static inline size_t row_columns(double x0, double dx, size_t n, long *ifirst)
{
  double xl = x0 + (double)(n - 1) * dx;
  if (!(fabs(x0) < NL_LATTICE_EXACT && fabs(xl) < NL_LATTICE_EXACT)) return 0;
  long a = nl_noise_lfloor(dx >= 0 ? x0 : xl), b = nl_noise_lfloor(dx >= 0 ? xl : x0);
  *ifirst = a;
  size_t ncol = (size_t)(b - a) + 2;
  return ncol > 2 * n + 8 ? 0 : ncol;
}

/* Columns and points are padded to a multiple of this (the widest level). */
#define NL_SIMD_PAD 8
/* Zeroed doubles after a row's columns (a window may read past the last). */
#define NL_SIMD_COL_PAD 16

/* Sample modes: out = v; out = 0 + amp v (first octave of a sum); out =
 * out + amp v (the others), in nl_noise_fractal_row's operation order; | ABS:
 * |v| (turbulence). */
enum { NL_SIMD_STORE = 0, NL_SIMD_FIRST = 1, NL_SIMD_ADD = 2, NL_SIMD_ABS = 4 };

typedef struct {
  /* The sample loop of a row (nl_noise.c's row_from_columns): v_k = blend
   * over columns c = floor(x_k) - ifirst, x_k = x0 + k dx, k < n, and
   * out[k] = v_k, or the octave sum's step (mode, below). Precondition:
   * every x_k has |x_k| < 2^52 and its columns c and c + 1 lie in gx, a
   * (row_columns guarantees both), which are padded by NL_SIMD_COL_PAD. */
  void (*samples)(const double *gx, const double *a, long ifirst, double x0, double dx,
                  size_t n, double *out, int mode, double amp);
  /* Columns ifirst + c, c < ncol (a multiple of NL_SIMD_PAD; the arrays
   * have room) of the improved noise at row j, plane k: xm = ifirst & 255,
   * ym = j & 255, zm = k & 255; p32 is the permutation widened to int, and
   * p's second half repeats its first (the dispatcher checks). */
  void (*columns3)(const nl_noise_perm3 *p, const int *p32, unsigned xm, unsigned ym, unsigned zm, double fy,
                   double fz, double v, double w, size_t ncol, double *gx, double *a);
  /* Points; n is a multiple of NL_SIMD_PAD (the caller pads). Lanes whose
   * coordinates leave |.| < 2^31 (or are not finite) go through the scalar
   * nl_noise_grad2_eval / nl_noise_perm3_eval (at AVX-512 also those whose
   * cell is -2^31, and the rest of their vector or block of 64: same bits);
   * then (only then) the call returns 1, else 0: every coordinate finite and
   * below 2^31, which the checked batches take as their test passed. */
  int (*points2)(const nl_noise_grad2 *t, const double *x, const double *y, size_t n, double *out);
  int (*points3)(const nl_noise_perm3 *p, const int *p32, const double *x, const double *y,
                  const double *z, size_t n, double *out);
  /* One octave of a sum over points, as nl_noise_perm3_points_sum: sum[k] =
   * sum[k] + amp v_k, v_k the noise at (f x[k], f y[k], f z[k]), and *top
   * raised to the largest |v_k|; n a multiple of NL_SIMD_PAD, lanes out of
   * range as points3 (here f x[k] ..., so 0 means f |c| < 2^31). */
  int (*points3_sum)(const nl_noise_perm3 *p, const int *p32, double f, const double *x,
                     const double *y, const double *z, size_t n, double amp, double *sum,
                     double *top);
  /* nl_noise_perm3_points_bounded on the first n points of pk (n a
   * multiple of NL_SIMD_PAD): the undecided go to the front from 0, their
   * count returned; hi and *nhi, *top as there. pk->n is not touched. */
  size_t (*points3_bounded)(const nl_noise_perm3 *p, const int *p32, double f, double amp, double r,
                            const nl_noise_pack *pk, size_t n, int *hi, size_t *nhi, double *top);
  /* 1 if a coordinate among x[k], y[k], z[k], k < n (a multiple of
   * NL_SIMD_PAD; z NULL: planar) has |c| >= lim or is NaN, else 0: the
   * quick test of nl_noise_points_refused, a vector at a time. */
  int (*refused)(const double *x, const double *y, const double *z, size_t n, double lim);
} nl_noise_simd_kernels;

extern const nl_noise_simd_kernels nl_noise_simd_sse2, nl_noise_simd_avx2, nl_noise_simd_avx512;

/* The hooks nl_noise.c calls first: GSL_SUCCESS when the dispatched level
 * computed the row, GSL_CONTINUE when the scalar code should (scalar level). */
int nl_noise_simd_row2(const nl_noise_grad2 *t, double x0, double dx, double y, size_t n, double *out);
int nl_noise_simd_row3(const nl_noise_perm3 *p, double x0, double dx, double y, double z,
                       size_t n, double *out);
/* nl_noise_fractal_row over nl_noise_basis_grad2 or nl_noise_basis_perm3, each octave's row
 * summed as it is made; GSL_CONTINUE for another basis or the scalar level. */
int nl_noise_simd_fractal_row(const nl_noise_basis *b, const nl_noise_octaves *o, double x0, double dx,
                              double y, double z, size_t n, double *out, double *scratch);

/* Perlin's grad3 (nl_noise.c) by component, for table lookups. */
extern const double nl_noise_simd_g3[3][16];

#endif
