/* nl_cellular.h - Qin & Yang 2000: cellular distances F1..F4 (Worley 1996)
 * and the generalized cellular texture basis function (GCTBF).
 *
 * Feature points (sec. 3.2). Space is cut into unit cubes. The cube with
 * base (i, j, k) = floor(x) gets a seed through a permutation table of 2^16
 * entries (sec. 3.2.2 step 3):
 *   PERM(v) = perm[v & 0xffff],  s = PERM(i + PERM(j + PERM(k))),
 * a fast generator (splitmix64) started from s draws a uniform r in [0, 1),
 * the count m from r (below), then 3 m coordinates inside the cube. F_i(x)
 * is the distance from x to the i-th closest feature point of the 27 cubes
 * around x; F1 <= F2 <= F3 <= F4. Values are exact when F_i <= 1 (every
 * point outside the 27 cubes is at least 1 away); if the 27 cubes hold
 * fewer than i points, F_i = NL_CELLULAR_FMAX = 2 sqrt 3, the largest
 * distance inside them.
 *
 * Count rules, with p(m) = lambda^m e^-lambda / m! tabulated for m = 0..M
 * (eq. 3; lambda = 4, M = 50 in the paper):
 *   NL_COUNT_CLOSEST      the paper's words: the m whose p(m) is closest to
 *                         r. This is not a sampler of p: with lambda = 4 every
 *                         r above max p(m) ~ 0.195 gives m = 3 (p(3) = p(4)),
 *                         and small r give large m. Q1 measures what it gives.
 *   NL_COUNT_INVERSE_CDF  the smallest m with r < P(m) = sum_{k<=m} p(k)
 *                         (M if r is beyond the truncated table): Poisson.
 *
 *   nl_cellular *c;
 *   nl_cellular_alloc(4.0, 50, NL_COUNT_INVERSE_CDF, seed, &c, &err);
 *   double F[4];
 *   nl_cellular_eval(c, xyz, 4, F);                      // F1..F4 at a point
 *   nl_cellular_row(c, x0, dx, y, z, count, 4, Frow);    // Frow[k*4 + i]
 *   nl_cellular_free(c);
 * A row reuses each cube's points for every sample of the row, so a raster
 * costs far less than point evaluations; both give the same bits. Both skip
 * a neighbour cube whose nearest possible squared distance (from the faces,
 * in the distance's own operation order) is already >= the current F_n^2:
 * none of its points could enter, so the bits are those of the full 27-cube
 * scan (nl_cellular_simd.h; test_cellular_simd.c). Rows run on the noise
 * library's SIMD level (nl_simd_get: scalar, SSE2, AVX2, AVX-512 chosen
 * at run time, NL_NOISE_SIMD to force one), every level the same bits.
 *
 * GCTBF (eq. 1):  GCTBF(x) = sum_i c_i F_i(x) + sum_{i,j} c_ij F_i(x) F_j(x),
 * i, j = 1..4. nl_cellular_gctbf_parse() reads it from text, e.g.
 *   "F2 - F1 - F1F1"    "0.5*F1 + 2 F1*F2"    "F1F2 + F2F3"
 * (terms: optional sign, optional number, one or two factors F1..F4, with or
 * without '*'); a bad number, an index outside 1..4 or any other text is an
 * NL_EINVAL with a one-line message. As a basis for sums and rendering:
 *   nl_cellular_gctbf_basis gb = {c, g};
 *   nl_noise_basis b = nl_cellular_basis_gctbf(&gb);     // b.row(...) evaluates GCTBF rows
 * b.bound = sum |c_i| FMAX + sum |c_ij| FMAX^2 (a valid, loose bound).
 *
 * Count statistics (Q1): nl_cellular_count_histogram() counts points per
 * cube over a block of cubes; nl_cellular_count_chisq() tests it against
 * Poisson(lambda) with Pearson's chi-square (bins 0..K-1 and a pooled tail
 * ">= K", K the largest with every expected count >= 5; nl_stats_chisq_test);
 * nl_cellular_f1_ks() tests F1 at random points against the nearest-
 * neighbour law of a Poisson process, P(F1 <= r) = 1 - exp(-lambda 4/3 pi r^3)
 * (nl_stats_ks_test).
 *
 * Texturing with the GCTBF (sec. 4), on a window of the plane z:
 *   nl_cellular_gctbf_fractal_bump_grid()  eq. 6 (and eq. 5 for octaves = 0):
 *       fractal = sum_{i=0}^{oct} |0.5 - GCTBF(2^i k x)| / 2^i, bump = fractal^3
 *   nl_cellular_gctbf_cloud_grid()         eq. 7 with smoothscale = 1 (see .c):
 *       sum_{i=0}^{oct} 2^-i (1 - 2 GCTBF(2^i k x))
 *   (the colours of sec. 4, nl_texture_ramp_cellular_marble() and
 *   nl_texture_cloud_colour(), live in texture/nl_texture.h: the algorithm
 *   module makes values, the texture module turns them into images)
 *   nl_cellular_heightfield_shade()        Lambert shading of the plane displaced by
 *       -bump along its normal, normals by central differences.
 */
#ifndef NL_CELLULAR_H
#define NL_CELLULAR_H

#include "base/nl_base.h"
#include "noise/nl_noise.h"
#include "stats/nl_stats.h"

#ifdef __cplusplus
extern "C" {
#endif

#define NL_CELLULAR_PERM 65536
#define NL_CELLULAR_MAX_M 64
#define NL_CELLULAR_NMAX 4
#define NL_CELLULAR_FMAX 3.46410161513775458705   /* 2 sqrt 3 */

/* How a uniform r becomes a cube's count m (Qin & Yang sec. 3.2):
 *   NL_COUNT_CLOSEST       the paper's "m whose p(m) is closest to r"; where two
 *                          p(m) are equally close (at lambda = 4, p(3) = p(4)
 *                          exactly in double) the smaller m: first on ties
 *   NL_COUNT_INVERSE_CDF   the smallest m with r < P(m): a sampler of p
 *   NL_COUNT_CLOSEST_LAST  the paper's rule, larger m on ties */
typedef enum { NL_COUNT_CLOSEST = 0, NL_COUNT_INVERSE_CDF = 1, NL_COUNT_CLOSEST_LAST = 2 } nl_cellular_count_rule;

typedef struct {
  double lambda;                          /* mean points per unit cube */
  int M;                                  /* largest count in the table */
  nl_cellular_count_rule rule;
  double pmf[NL_CELLULAR_MAX_M + 1];      /* p(m), eq. 3 */
  double cdf[NL_CELLULAR_MAX_M + 1];      /* sum_{k<=m} p(k) */
  unsigned short *perm;                   /* 2^16 entries, a permutation */
} nl_cellular;

/* lambda > 0, 1 <= M <= NL_CELLULAR_MAX_M; perm shuffled from seed (MT19937). */
nl_status nl_cellular_alloc(double lambda, int M, nl_cellular_count_rule rule, unsigned long seed,
                            nl_cellular **out, nl_error *err);
void nl_cellular_free(nl_cellular *c);
/* "closest", "inverse-cdf", "closest-last" */
const char *nl_cellular_count_rule_name(nl_cellular_count_rule rule);

/* The count for a uniform r in [0, 1) under c->rule. */
int nl_cellular_count_from_r(const nl_cellular *c, double r);
/* Feature points of cube (i, j, k): returns m, writes 3 m absolute coordinates. */
int nl_cellular_cube(const nl_cellular *c, long i, long j, long k, double *xyz);

/* F[0..n-1] = F1..Fn at xyz, 1 <= n <= 4. */
void nl_cellular_eval(const nl_cellular *c, const double *xyz, int n, double *F);
/* F[k n + i] = F_{i+1}(x[k], y[k], z[k]), k < count: nl_cellular_eval at
 * arbitrary points in one call. */
void nl_cellular_points(const nl_cellular *c, const double *x, const double *y, const double *z,
                        size_t count, int n, double *F);
/* F[k n + i] = F_{i+1}(x0 + k dx, y, z), k < count. */
void nl_cellular_row(const nl_cellular *c, double x0, double dx, double y, double z,
                     size_t count, int n, double *F);

/* ---- GCTBF (eq. 1) ---------------------------------------------------- */

typedef struct {
  int n;                                              /* largest index used, 1..4 */
  double c[NL_CELLULAR_NMAX];                         /* c_i, i = 1..4 at [i-1] */
  double cc[NL_CELLULAR_NMAX][NL_CELLULAR_NMAX];      /* c_ij */
} nl_cellular_gctbf;

nl_status nl_cellular_gctbf_parse(const char *expr, nl_cellular_gctbf *g, nl_error *err);
/* Adds coefficient v to c_i (j = 0) or c_ij; i, j in 1..4. */
nl_status nl_cellular_gctbf_add(nl_cellular_gctbf *g, int i, int j, double v, nl_error *err);
/* Canonical text, e.g. "F2 - F1 - F1F1"; buf of len bytes. */
void nl_cellular_gctbf_format(const nl_cellular_gctbf *g, char *buf, size_t len);
double nl_cellular_gctbf_value(const nl_cellular_gctbf *g, const double *F);
double nl_cellular_gctbf_bound(const nl_cellular_gctbf *g);
/* out[k] = GCTBF(x0 + k dx, y, z). */
void nl_cellular_gctbf_row(const nl_cellular *c, const nl_cellular_gctbf *g, double x0, double dx, double y,
                           double z, size_t count, double *out);

/* out[k] = GCTBF(x[k], y[k], z[k]) = nl_cellular_gctbf_value of nl_cellular_eval. */
void nl_cellular_gctbf_points(const nl_cellular *c, const nl_cellular_gctbf *g, const double *x,
                              const double *y, const double *z, size_t count, double *out);

/* GCTBF on a window (pixel centres, row 0 at y0), like nl_noise_fractal_grid. */
void nl_cellular_gctbf_grid(const nl_cellular *c, const nl_cellular_gctbf *g, const nl_noise_window *win, double *out);

typedef struct {
  const nl_cellular *cell;
  nl_cellular_gctbf g;
} nl_cellular_gctbf_basis;
/* A basis for nl_noise_fractal_row / nl_noise_fractal_grid and the render tool; ctx must
 * outlive the basis. */
nl_noise_basis nl_cellular_basis_gctbf(const nl_cellular_gctbf_basis *ctx);

/* ---- count statistics (Q1) -------------------------------------------- */

/* hist[m] (M + 1 entries) = number of cubes with m points among the cubes
 * (i, j, k), origin <= i, j, k < origin + side. */
void nl_cellular_count_histogram(const nl_cellular *c, long origin, int side, double *hist);
/* Mean and (population) variance of the counts 0..M of such a histogram. */
void nl_cellular_count_moments(const double *hist, int M, double *mean, double *var);
nl_status nl_cellular_count_chisq(const nl_cellular *c, const double *hist,
                                  nl_stats_chisq_result *res, nl_error *err);
/* 1 - exp(-lambda 4/3 pi r^3); params points to lambda. */
double nl_cellular_f1_cdf(double r, void *params);
/* F1 at n points uniform in [0, 1000)^3 drawn from seed (MT19937), KS test
 * against nl_cellular_f1_cdf. mean_f1 (may be NULL) gets the sample mean. */
nl_status nl_cellular_f1_ks(const nl_cellular *c, size_t n, unsigned long seed,
                            nl_stats_ks_result *res, double *mean_f1, nl_error *err);

/* ---- texturing (sec. 4) ----------------------------------------------- */

/* bump(x) of eq. 6 on win (scale k multiplies x); octaves 0..30. */
void nl_cellular_gctbf_fractal_bump_grid(const nl_cellular_gctbf_basis *b, int octaves, double k,
                                         const nl_noise_window *win, double *out);
/* fractal(x) of eq. 7 with smoothscale = 1. */
void nl_cellular_gctbf_cloud_grid(const nl_cellular_gctbf_basis *b, int octaves, double k,
                                  const nl_noise_window *win, double *out);
/* Sec. 4.3's textures (Q4) for one seed: a fresh table (lambda = 4, M = 50,
 * inverse-CDF counts) on win scaled by k, `octaves` after the first:
 *   NL_GCTBF_CLOUD  eq. 7's fractal of expr (nl_cellular_gctbf_cloud_grid); expr NULL:
 *                   of RenderMan's noise 0.5 + 0.5 N (improved noise of the
 *                   seed), for which 1 - 2 noise = -N
 *   NL_GCTBF_FLAME  the fractal sum of F1, sum_i F1(2^i k x) / 2^i
 *   NL_GCTBF_PLAIN  the GCTBF expr itself (nl_cellular_gctbf_grid)
 * v holds win->w * win->h values. NL_EINVAL for a bad expression. */
typedef enum { NL_GCTBF_CLOUD, NL_GCTBF_FLAME, NL_GCTBF_PLAIN } nl_cellular_gctbf_texture;
nl_status nl_cellular_texture_grid(nl_cellular_gctbf_texture kind, const char *expr, int octaves, double k,
                                   const nl_noise_window *win, unsigned long seed, double *v, nl_error *err);
/* out = max(0, N . L) of the surface z = -height over a w x h grid (w, h >= 2) with spacing
 * `spacing`; light is a unit vector. */
void nl_cellular_heightfield_shade(const double *height, int w, int h, double spacing,
                                   const double *light, double *out);

#ifdef __cplusplus
}
#endif

#endif
