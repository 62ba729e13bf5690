/* nl_noise.h - gradient noise with explicit tables, and sums of octaves.
 *
 * Three gradient noises, the first two also evaluated a row of samples at a
 * time:
 *
 *  - nl_noise_grad2: 2D gradient noise as in Cheng 2009 eq. 3.1-3.2. A table of m
 *    unit gradients stored as angles (the optimiser edits them one at a time)
 *    and a permutation P of 0..m-1; lattice point (i, j) uses gradient
 *    G[P[(P[i mod m] + j) mod m]]. Quintic fade 6t^5 - 15t^4 + 10t^3.
 *    |noise| <= sqrt(2)/2 (the value at a cell centre with all four
 *    gradients pointing at it); noise is 0 at every lattice point.
 *
 *  - nl_noise_grad3: the same construction in 3D (Cheng 2009 ch. 5's future
 *    work, TARGETS C8): m unit gradient vectors, stored also as the two
 *    angles z = cos(polar) and phi = azimuth that the optimiser tests for
 *    uniformity on the sphere, and a permutation P; lattice point (i, j, k)
 *    uses G[P[(P[(P[i mod m] + j) mod m] + k) mod m]]. Same fade.
 *    |noise| <= sqrt(3)/2; 0 at every lattice point.
 *
 *  - nl_noise_perm3: Perlin's 2002 improved noise in 3D (12 edge gradients chosen
 *    by hash & 15, same fade), with his reference permutation (all 256
 *    entries of his published table) or one shuffled from a seed. Its
 *    gradients have length sqrt(2), so
 *    |noise| <= sqrt(2) * sqrt(3)/2 ~ 1.2247; in practice it stays near
 *    [-1, 1] (the S3 table reports the observed extremes).
 *
 * Both are tables of plain data owned by the caller, filled from a seed with
 * GSL's MT19937: same seed, same noise, on any x86-64 build at any -O level
 * (the project compiles with -ffp-contract=off).
 *
 * Evaluation order. The four (2D) or eight (3D) corner contributions are
 * interpolated along y (and z) first, which leaves, per lattice column c, a
 * line L_c(t) = t * GX_c + A_c in the fractional x-coordinate t; the sample
 * is L_c(t) + fade(t) * (L_{c+1}(t - 1) - L_c(t)). Mathematically this is
 * Perlin's trilinear blend in another order; it lets a row at fixed y, z
 * compute each column's (GX, A) once and spend ~15 flops per sample. The
 * point functions use the same kernel, so a point and a row give the same
 * bits. Perlin's reference code blends x first, so the two round
 * differently: test_noise_reference.c compares every kernel (the point
 * call, rows, one-octave fractal rows, point batches and the two sums over
 * them, at the scalar level and every SIMD level) with a transcription of
 * his Java code and table (tests/reference/perlin_improved_noise.c) at 2^20
 * random points of [-300, 300]^3 a run, half of whose coordinates are
 * lattice points, half-integers, an ulp off an integer, tiny of either sign
 * or near a multiple of 256, and along rows across 0 and -256: they agree
 * within 1e-15 (measured 6.7e-16), and every kernel gives the point call's
 * bits.
 *
 * Cell and fraction (nl_noise_lattice.h): floor(x) and x - floor(x),
 * rounded as Perlin's code rounds them. For x in [-2^-54, 0) the fraction
 * rounds to 1 in cell -1, which is the point x = 0: the noise there is its
 * value at 0 (to 1e-15), as in the reference, in both the 2D and 3D noises.
 *
 * Sums of octaves (Cheng eq. 3.3, Shaffer's fractal sum, turbulence, fBm):
 *     sum_l amp_l * N(freq_l * p)       (|N(...)| for turbulence)
 * nl_noise_octaves holds freq and amp explicitly; builders give fBm
 * (amp = gain^l, freq = lacunarity^l) and Cheng's f_l = f1 2^l with
 * amplitude 1/a_l, a_l = a1 2^l. The analytic bound of a sum is
 * bound(N) * sum |amp_l| (Arnerin 2009 eq. 4.2 with |N| <= bound(N)).
 */
#ifndef NL_NOISE_H
#define NL_NOISE_H

#include "simd/nl_simd.h"

#include <stddef.h>
#include <stdint.h>

/* The point calls nl_noise_grad2_eval, nl_noise_perm3_eval and
 * nl_noise_perm3_fractal_eval are inline functions in C99's sense: their
 * bodies are at the end of this header, so a loop of calls compiles into
 * the caller (and work that does not change from one call to the next,
 * such as the z of points on a plane, leaves the loop), while the library
 * still exports each of them as a symbol (bindings, pointers to them).
 * Define NL_NOISE_NO_INLINE to call the library's copies instead. */
#if defined(__GNUC__) && !defined(NL_NOISE_NO_INLINE)
#define NL_NOISE_INLINE inline
#else
#define NL_NOISE_INLINE
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- 2D gradient-table noise ---------------------------------------- */

typedef struct {
  size_t m;          /* table size; Cheng uses 512 */
  double *angle;     /* m gradient angles in [0, 2pi) */
  double *gx, *gy;   /* cos and sin of angle, kept in step by nl_noise_grad2_set_angle */
  unsigned *perm;    /* permutation of 0..m-1 */
} nl_noise_grad2;

nl_noise_grad2 *nl_noise_grad2_alloc(size_t m);
void nl_noise_grad2_free(nl_noise_grad2 *t);
/* Uniform angles on [0, 2pi) and a uniform random permutation. */
void nl_noise_grad2_seed(nl_noise_grad2 *t, unsigned long seed);
void nl_noise_grad2_set_angle(nl_noise_grad2 *t, size_t k, double theta);
void nl_noise_grad2_copy(nl_noise_grad2 *dst, const nl_noise_grad2 *src);   /* same m */
/* Table entry used by lattice point (i, j). */
size_t nl_noise_grad2_index(const nl_noise_grad2 *t, long i, long j);

NL_NOISE_INLINE double nl_noise_grad2_eval(const nl_noise_grad2 *t, double x, double y);
/* The same noise, out of line and for every double: what nl_noise_grad2_eval
 * computes when m is not a power of two or a coordinate is 2^31 or more
 * from 0 (or not finite). */
double nl_noise_grad2_eval_general(const nl_noise_grad2 *t, double x, double y);
/* out[k] = noise(x0 + k dx, y), k < n. */
void nl_noise_grad2_row(const nl_noise_grad2 *t, double x0, double dx, double y, size_t n, double *out);
#define NL_NOISE2_BOUND 0.70710678118654752440

/* ---- 3D gradient-table noise ---------------------------------------
 *
 * Noise(x, y, z) = sum over the 8 corners c = (i, j, k) of the cell holding
 * p of w(x - i) w(y - j) w(z - k) (Delta_c . G_c), Delta_c = p - c, w the
 * quintic fade (Cheng 2009 eq. 3.1-3.2 in 3D). The noise is linear in the
 * gradients: nl_noise_grad3_corners gives, for one point, the 8 table
 * entries its corners use and the weight vectors W_c = amp w w w Delta_c,
 * so that amp * noise = sum_c W_c . G[entry_c]. An optimiser that stores
 * them updates a point's value in O(1) when one gradient moves.
 *
 *   nl_noise_grad3 *t = nl_noise_grad3_alloc(512);
 *   nl_noise_grad3_seed(t, seed);               // uniform on the sphere
 *   double n = nl_noise_grad3_eval(t, x, y, z);  // |n| <= NL_NOISE_GRAD3_BOUND
 *   nl_noise_grad3_free(t);
 */
typedef struct {
  size_t m;          /* table size; C8 uses 512 */
  double *v;         /* 3 m: unit gradients (x, y, z), entry k at v + 3 k */
  double *z, *phi;   /* cos(polar) in [-1, 1], azimuth in [0, 2 pi); kept in step by _set */
  unsigned *perm;    /* permutation of 0..m-1 */
} nl_noise_grad3;

/* Every gradient (0, 0, 1), the identity permutation. */
nl_noise_grad3 *nl_noise_grad3_alloc(size_t m);
void nl_noise_grad3_free(nl_noise_grad3 *t);
/* Directions uniform on the sphere (Archimedes' hat-box: z ~ U(-1, 1),
 * phi ~ U(0, 2 pi)) and a uniform permutation, from MT19937 on stream
 * ("cheng3.table", 0) of seed: the stream C8's optimiser starts from. */
void nl_noise_grad3_seed(nl_noise_grad3 *t, unsigned long seed);
/* Entry k := the direction of u (normalised; u != 0), its z and phi with it. */
void nl_noise_grad3_set(nl_noise_grad3 *t, size_t k, const double u[3]);
void nl_noise_grad3_copy(nl_noise_grad3 *dst, const nl_noise_grad3 *src);   /* same m */
/* Table entry used by lattice point (i, j, k). */
size_t nl_noise_grad3_index(const nl_noise_grad3 *t, long i, long j, long k);
/* The point's 8 corners, in the order q = di + 2 dj + 4 dk: entry[q] and
 * the weight vector w[3q .. 3q+2] = amp w w w Delta (amp folded in first,
 * so a sum of octaves is a sum of such terms). */
void nl_noise_grad3_corners(const nl_noise_grad3 *t, double x, double y, double z, double amp,
                            uint32_t entry[8], double w[24]);
double nl_noise_grad3_eval(const nl_noise_grad3 *t, double x, double y, double z);
#define NL_NOISE_GRAD3_BOUND 0.86602540378443864676   /* sqrt(3)/2 */

/* ---- Perlin's improved 3D noise ------------------------------------- */

typedef struct { unsigned char p[512]; } nl_noise_perm3;   /* 256 entries, doubled */

void nl_noise_perm3_reference(nl_noise_perm3 *p);                 /* Perlin 2002's table */
void nl_noise_perm3_seed(nl_noise_perm3 *p, unsigned long seed);  /* shuffled 0..255 */
NL_NOISE_INLINE double nl_noise_perm3_eval(const nl_noise_perm3 *p, double x, double y, double z);
/* The same noise, out of line and for every double: what nl_noise_perm3_eval
 * computes when a coordinate is 2^31 or more from 0 (or not finite). */
double nl_noise_perm3_eval_general(const nl_noise_perm3 *p, double x, double y, double z);
void nl_noise_perm3_row(const nl_noise_perm3 *p, double x0, double dx, double y, double z,
                        size_t n, double *out);
#define NL_NOISE3_BOUND 1.22474487139158904910

/* ---- SIMD kernels, run-time dispatch, batches of points ---------------
 *
 * Rows of both noises (and so the sums of octaves over nl_noise_basis_grad2
 * and nl_noise_basis_perm3) and the batches below run on the library's
 * vector level (simd/nl_simd.h: SSE2, AVX2 or AVX-512, chosen at run time,
 * NL_NOISE_SIMD in the environment or nl_simd_set to force one). Every
 * level returns the scalar code's bits (same IEEE operations in the same
 * order, no FMA); power-of-two tables index by mask.
 * The nl_noise_simd_* names below are the level's, for the programs that
 * call them so (bench_noise, the SIMD tests). */
typedef nl_simd_level nl_noise_simd_level;
#define NL_NOISE_SIMD_SCALAR NL_SIMD_SCALAR
#define NL_NOISE_SIMD_SSE2 NL_SIMD_SSE2
#define NL_NOISE_SIMD_AVX2 NL_SIMD_AVX2
#define NL_NOISE_SIMD_AVX512 NL_SIMD_AVX512
static inline int nl_noise_simd_get(void) { return nl_simd_get(); }
static inline int nl_noise_simd_best(void) { return nl_simd_best(); }
static inline int nl_noise_simd_supported(int level) { return nl_simd_supported(level); }
static inline nl_status nl_noise_simd_set(int level) { return nl_simd_set(level); }
static inline const char *nl_noise_simd_name(int level) { return nl_simd_name(level); }
static inline int nl_noise_simd_from_name(const char *name) { return nl_simd_from_name(name); }

/* out[k] = nl_noise_grad2_eval(t, x[k], y[k]) and nl_noise_perm3_eval(p, x[k], y[k], z[k]),
 * k < n. out may be one of the inputs (the same array), not overlap one. */
void nl_noise_grad2_points(const nl_noise_grad2 *t, const double *x, const double *y, size_t n,
                           double *out);
void nl_noise_perm3_points(const nl_noise_perm3 *p, const double *x, const double *y, const double *z,
                           size_t n, double *out);
/* One octave of a fractal sum over a batch of points (the bounded ray march
 * of nl_bounds, Arnerin 2009 eq. 5.1): for k < n,
 *   v_k = nl_noise_perm3_eval(p, f * x[k], f * y[k], f * z[k]),
 *   sum[k] = sum[k] + amp * v_k,
 * and the largest |v_k| is returned (0 for n = 0; NaN never counts) - the
 * bits of that scalar loop on every level. sum must not overlap x, y, z. */
double nl_noise_perm3_points_sum(const nl_noise_perm3 *p, double f, const double *x, const double *y,
                                 const double *z, size_t n, double amp, double *sum);
/* Checked batches: the callers that take points from outside (the Python
 * package) refuse a coordinate c with f |c| >= 2^52, f the finest octave's
 * frequency, or c NaN or infinite: beyond 2^52 a double has no fractional
 * bits, so the lattice position is lost and a cell index overflows a long.
 * nl_noise_points_refused returns the first k < n with x[k], y[k] or z[k]
 * (z NULL: planar points) refused, n if none.
 *
 * The _checked calls run the kernel and the check a block of
 * NL_NOISE_CHECK_BLOCK points at a time. The SIMD kernels test each
 * vector's range anyway (finite and below 2^31, else the scalar code), so
 * only a block with a point outside that range is checked exactly: the
 * check costs next to nothing (10^6 points: 1.01x the bare call, where a
 * separate pass first cost 1.3x). They return the first refused
 * k (n if none); out[0 .. k) holds the points' values, out[k .. k1) values
 * of no meaning, k1 the end of k's block (k1 = (k / NL_NOISE_CHECK_BLOCK
 * + 1) NL_NOISE_CHECK_BLOCK, at most n), and out[k1 ..) is untouched:
 *   nl_noise_perm3_points_checked   o NULL: nl_noise_perm3_points; else the
 *       sum over octaves o (o->turbulence 0) of improved noise, out = 0 then
 *       nl_noise_perm3_points_sum per octave (the same bits);
 *   nl_noise_grad2_points_checked   nl_noise_grad2_points, f = 1. */
enum { NL_NOISE_CHECK_BLOCK = 512 };
struct nl_noise_octaves;
size_t nl_noise_points_refused(const double *x, const double *y, const double *z, size_t n,
                               double f);
size_t nl_noise_perm3_points_checked(const nl_noise_perm3 *p, const struct nl_noise_octaves *o,
                                     const double *x, const double *y, const double *z, size_t n,
                                     double *out);
size_t nl_noise_grad2_points_checked(const nl_noise_grad2 *t, const double *x, const double *y,
                                     size_t n, double *out);
/* Points packed for nl_noise_perm3_points_bounded: coordinates, the base a
 * sum is added to, the partial sum, and the caller's id of each point, n
 * of them; every array has room for n + NL_NOISE_PACK_PAD entries (the
 * kernels store whole vectors past the last point). */
typedef struct { double *x, *y, *z, *base, *sum; int *id; size_t n; } nl_noise_pack;
enum { NL_NOISE_PACK_PAD = 16 };
/* One term of CLAMP(base + sum_l amp_l noise(f_l p)) under incremental
 * bounding (Arnerin 2009 eq. 5.4) over the packed points: for k < n,
 *   sum[k] = sum[k] + amp * noise(f x[k], f y[k], f z[k])
 * (the bits of nl_noise_perm3_points_sum), then with s = base[k] + sum[k]
 * and r the bound of the terms after this one, the point is decided at 0
 * when s + r <= 0 and at 1 when s - r >= 1, and leaves the pack: the
 * undecided ones move to the front in their order (pk->n becomes their
 * count). The ids of the points decided at 1 go to hi[0 ..) in order
 * (room for n); returns their count. *top is raised to the largest |noise|. */
size_t nl_noise_perm3_points_bounded(const nl_noise_perm3 *p, double f, double amp, double r, nl_noise_pack *pk,
                                     int *hi, double *top);

/* ---- a noise as a basis for sums ------------------------------------ */

typedef struct {
  /* out[k] = N(x0 + k dx, y, z); 2D noises ignore z. */
  void (*row)(const void *ctx, double x0, double dx, double y, double z, size_t n, double *out);
  const void *ctx;
  double bound;      /* sup |N| */
} nl_noise_basis;

nl_noise_basis nl_noise_basis_grad2(const nl_noise_grad2 *t);
nl_noise_basis nl_noise_basis_perm3(const nl_noise_perm3 *p);

#define NL_MAX_OCTAVES 32
typedef struct nl_noise_octaves {
  int n;
  int turbulence;               /* 1: sum |N| instead of N */
  double freq[NL_MAX_OCTAVES];
  double amp[NL_MAX_OCTAVES];
} nl_noise_octaves;

nl_noise_octaves nl_noise_octaves_fbm(int n, double gain, double lacunarity);
/* Shaffer's fractal sum: fBm with gain 1/2 and lacunarity 2. */
nl_noise_octaves nl_noise_octaves_fractal(int n);
/* Cheng eq. 3.10: f_l = f1 2^l, amplitude 1 / (a1 2^l), l = 0..n-1. */
nl_noise_octaves nl_noise_octaves_cheng(int n, double f1, double a1);
/* bound(N) * sum |amp|: the sum never leaves [-b, b] ([0, b] if turbulence). */
double nl_noise_octaves_bound(const nl_noise_octaves *o, double basis_bound);

/* The sum of octaves of Perlin's improved noise at one point: the bits of
 * nl_noise_fractal_row over nl_noise_basis_perm3 with n = 1. */
NL_NOISE_INLINE double nl_noise_perm3_fractal_eval(const nl_noise_perm3 *p,
                                                   const nl_noise_octaves *o,
                                                   double x, double y, double z);

/* out[k] = sum of octaves at (x0 + k dx, y, z); scratch holds n doubles. */
void nl_noise_fractal_row(const nl_noise_basis *b, const nl_noise_octaves *o, double x0, double dx,
                          double y, double z, size_t n, double *out, double *scratch);

/* out[k] = the sum of octaves at point k, by nl_noise_fractal_row one point
 * at a time (its bits, for any basis); z NULL: planar points (z = 0). One
 * call for a whole array where the basis has no batch kernel of its own. */
void nl_noise_fractal_points(const nl_noise_basis *b, const nl_noise_octaves *o, const double *x,
                             const double *y, const double *z, size_t n, double *out);
/* The finest frequency max_l |freq_l| of o (1 for no octaves): the f of
 * nl_noise_points_refused. */
double nl_noise_octaves_fmax(const nl_noise_octaves *o);

/* A w x h raster of the square [x0, x0 + size) x [y0, y0 + size) in the
 * plane z, sampled at pixel centres; row 0 is y0. */
typedef struct { double x0, y0, z, size; int w, h; } nl_noise_window;
void nl_noise_fractal_grid(const nl_noise_basis *b, const nl_noise_octaves *o, const nl_noise_window *win, double *out);

/* ---- float32 path ----------------------------------------------------
 *
 * Perlin's improved 3D noise and the 2D table noise (m a power of two, at
 * most 2^24) computed in float: rows, point batches, sums of octaves over
 * both, and a grid. Fused multiply-adds in the operation order of the
 * double path's kernels (the column lines of "Evaluation order" above);
 * 16 lanes on the AVX-512 level, 8 on AVX2 (either with FMA), and a
 * scalar level (fmaf(), the SSE2 level and non-x86 builds). Every level
 * gives the scalar level's bits (test_noise_f32.c); they are not the double
 * path's bits.
 *
 * Accuracy. At the same coordinates (a float converted to double exactly)
 * |f32 - double| <= 2e-6 (measured 1.1e-6, 9 ulps of 1; test_noise_f32.c)
 * for the improved noise and the 2D noise, at every finite float
 * coordinate: the cell and the fraction x - floor(x) are exact in float
 * (but in (-1, 0), where x + 1 rounds to a multiple of 2^-24, and to 1 -
 * the point 0's value, as in double - in [-2^-25, 0)), and the cell mod
 * 256 (mod m) is exact however far from 0 (from 2^31 on, every float is a
 * multiple of 256; the 2D cell is reduced mod m in float exactly). NaN or
 * an infinite coordinate gives NaN. What float loses is the input's
 * resolution: a coordinate given in double and rounded to float moves by
 * up to |c| 2^-24, so at |c| = 2^12 a sample lands up to 2^-12 of a cell
 * from where a double caller meant it; against the double noise at the
 * double point that measured 3.5e-4 in [-2^12, 2^12]^3 (3.8e-5 in
 * [-300, 300]^3), and beyond 2^23 every float is a lattice point. The
 * calls refuse nothing: below 2^12 the float path is within 1e-3 of the
 * double noise at double points; beyond, use the double path.
 * Rows sample x_k = fmaf((float)k, dx, x0) (k < 2^31); sums of
 * octaves use freq and amp rounded to float, octave l adding
 * fmaf(amp_l, N(f_l x, f_l y, f_l z), sum) to a sum started at 0 (|N| for
 * turbulence), so a row gives the bits of the points x_k, and of the
 * points' sums.
 * 2D tables whose m is not a power of two or above 2^24: every value is
 * the double noise at the same point, rounded to float.
 * out must not overlap the inputs unless it is one of them. */
float nl_noise_perm3_eval_f32(const nl_noise_perm3 *p, float x, float y, float z);
float nl_noise_grad2_eval_f32(const nl_noise_grad2 *t, float x, float y);
void nl_noise_perm3_points_f32(const nl_noise_perm3 *p, const float *x, const float *y, const float *z,
                               size_t n, float *out);
void nl_noise_grad2_points_f32(const nl_noise_grad2 *t, const float *x, const float *y, size_t n,
                               float *out);
/* out[k] = noise(fmaf((float)k, dx, x0), y[, z]), k < n */
void nl_noise_perm3_row_f32(const nl_noise_perm3 *p, float x0, float dx, float y, float z, size_t n,
                            float *out);
void nl_noise_grad2_row_f32(const nl_noise_grad2 *t, float x0, float dx, float y, size_t n, float *out);
/* Sums of octaves o (fBm, turbulence) over batches and rows. */
void nl_noise_perm3_fractal_points_f32(const nl_noise_perm3 *p, const nl_noise_octaves *o, const float *x,
                                       const float *y, const float *z, size_t n, float *out);
void nl_noise_perm3_fractal_row_f32(const nl_noise_perm3 *p, const nl_noise_octaves *o, float x0,
                                    float dx, float y, float z, size_t n, float *out);
void nl_noise_grad2_fractal_points_f32(const nl_noise_grad2 *t, const nl_noise_octaves *o, const float *x,
                                       const float *y, size_t n, float *out);
void nl_noise_grad2_fractal_row_f32(const nl_noise_grad2 *t, const nl_noise_octaves *o, float x0,
                                    float dx, float y, size_t n, float *out);
/* The sum of octaves of p3 (t2 when p3 is NULL) over a window, as
 * nl_noise_fractal_grid places the pixel centres (in double, then each
 * row's x0, dx and y rounded to float), out[r w + c]. */
void nl_noise_fractal_grid_f32(const nl_noise_grad2 *t2, const nl_noise_perm3 *p3,
                               const nl_noise_octaves *o, const nl_noise_window *win, float *out);

/* ---- threads ---------------------------------------------------------
 *
 * Large work split across threads by nl_parallel_for (base/nl_parallel.h),
 * the same bytes as one thread for any nthreads: every value is made by
 * the one-thread call on a part (a grid row; a run of whole
 * NL_NOISE_CHECK_BLOCK blocks of points), and no value depends on another.
 * The caller chooses nthreads (the library never does); nthreads <= 1, or
 * work below a size threshold measured where starting threads cost more
 * than they save, runs on the calling thread.
 *   nl_noise_fractal_grid_threads           nl_noise_fractal_grid, by rows;
 *       b->row must be safe to call from several threads at once (every
 *       basis of the library is: its tables are only read);
 *   nl_noise_perm3_points_checked_threads   nl_noise_perm3_points_checked,
 *   nl_noise_grad2_points_checked_threads   nl_noise_grad2_points_checked,
 *       with their contract exactly: the first refused k (n if none),
 *       out[0 .. k) the values, out[k1 ..) untouched for k1 the end of
 *       k's block. */
void nl_noise_fractal_grid_threads(const nl_noise_basis *b, const nl_noise_octaves *o,
                                   const nl_noise_window *win, int nthreads, double *out);
size_t nl_noise_perm3_points_checked_threads(const nl_noise_perm3 *p, const struct nl_noise_octaves *o,
                                             const double *x, const double *y, const double *z,
                                             size_t n, double *out, int nthreads);
size_t nl_noise_grad2_points_checked_threads(const nl_noise_grad2 *t, const double *x,
                                             const double *y, size_t n, double *out, int nthreads);

/* ---- the point calls, inline ----------------------------------------
 *
 * The bodies of nl_noise_grad2_eval, nl_noise_perm3_eval and
 * nl_noise_perm3_fractal_eval (see the top of this header). They compute
 * what the row kernels compute (the column lines L_c of the header's
 * "Evaluation order"), with the same IEEE operations in the same order,
 * so their bits are those of the rows, the batches and
 * nl_noise_*_eval_general. Besides being compiled into the caller, three
 * things make them faster than that code:
 *  - the two columns i and i + 1 of the cell go through the same
 *    operations, so they are the two lanes of one 2-double vector (SSE2
 *    on x86-64: half the arithmetic instructions);
 *  - Perlin's 16 gradients are read as pairs, one entry per pair of hashes
 *    (nl_noise_perm3_gradpairs, 12 KiB), three aligned loads per corner of
 *    both columns instead of six scalar ones;
 *  - cells within 2^31 of 0 (every finite double the noise is used at)
 *    take floor and fraction without nl_noise_lattice.h's range checks,
 *    one test of the converted coordinates deciding for all of them; the
 *    others go to nl_noise_*_eval_general, which makes the checks.
 * The bits are the library's only if the caller's compiler contracts no
 * a * b + c into a fused multiply-add: GCC in ISO C mode (-std=c11, the
 * project's flags) or with -ffp-contract=off, clang with
 * -ffp-contract=off. An inline definition may not use the static helpers
 * of nl_noise_lattice.h, hence the macros. */
#if defined(__GNUC__) && !defined(NL_NOISE_NO_INLINE)

#if defined(__x86_64__) && defined(__SSE2__)
#include <emmintrin.h>
#endif

typedef double nl_noise_v2d __attribute__((vector_size(16)));
/* Gradients a and b of Perlin's 16 as lane pairs, at entry 16 a + b of
 * each component's array. */
typedef struct { nl_noise_v2d gx[256], gy[256], gz[256]; } nl_noise_perm3_gradpairs_table;
#ifdef __cplusplus
static_assert(sizeof(nl_noise_v2d[256]) == 4096, "the point call's offsets of gy and gz");
#else
_Static_assert(sizeof(nl_noise_v2d[256]) == 4096, "the point call's offsets of gy and gz");
#endif
extern const nl_noise_perm3_gradpairs_table nl_noise_perm3_gradpairs;

#define NL_NOISE_FADE_(t) ((t) * (t) * (t) * ((t) * ((t) * 6.0 - 15.0) + 10.0))
#define NL_NOISE_LERP_(t, a, b) ((a) + (t) * ((b) - (a)))
/* NL_NOISE_TRUNC_(x) is (long)x where that is defined, and NL_NOISE_OFF_(i)
 * is below 2^32 just when i is in [-2^31, 2^31). With SSE2's conversion an
 * x beyond long (NaN included) gives -2^63, so the converted coordinates
 * are tested together after converting; elsewhere C's conversion is
 * guarded and gives 2^32 beyond 2^31. Every x whose truncation passes is
 * below 2^62 in size, where nl_noise_lattice.h's floor and fraction are
 * the ones computed here. */
#if defined(__x86_64__) && defined(__SSE2__)
#define NL_NOISE_TRUNC_(x) _mm_cvttsd_si64(_mm_set_sd(x))
#else
#define NL_NOISE_TRUNC_(x) ((x) > -0x1p31 && (x) < 0x1p31 ? (long)(x) : 0x100000000L)
#endif
#define NL_NOISE_OFF_(i) ((unsigned long long)(i) + 0x80000000ull)

/* L_c(t) + u (L_{c+1}(t - 1) - L_c(t)), u = fade(t), with lane 0 of gx
 * and a column c's line and lane 1 column c + 1's. */
#define NL_NOISE_BLEND_(t, u, gx, a, out)                                 \
  do {                                                                    \
    nl_noise_v2d lr_ = (nl_noise_v2d){(t), (t) - 1.0} * (gx) + (a);       \
    (out) = lr_[0] + (u) * (lr_[1] - lr_[0]);                             \
  } while (0)

NL_NOISE_INLINE double nl_noise_grad2_eval(const nl_noise_grad2 *t, double x, double y)
{
  size_t m = t->m, km = m - 1;
  long i = NL_NOISE_TRUNC_(x), j = NL_NOISE_TRUNC_(y);
  /* m ^ (m - 1) > m - 1 just when m is a power of two */
  if ((NL_NOISE_OFF_(i) | NL_NOISE_OFF_(j)) >= 0x100000000ull || (m ^ km) <= km)
    return nl_noise_grad2_eval_general(t, x, y);
  i -= x < (double)i;
  j -= y < (double)j;
  double fx = x - (double)i, fy = y - (double)j, res;
  nl_noise_v2d uv = NL_NOISE_FADE_(((nl_noise_v2d){fx, fy}));   /* fades of fx and fy */
  double v = uv[1];
  /* Table entries of the corners (i + di, j + dj), G[P[(P[i] + j) mod m]] */
  const unsigned *P = t->perm;
  long pi0 = P[i & km], pi1 = P[(i + 1) & km];
  size_t k00 = P[(pi0 + j) & km], k10 = P[(pi1 + j) & km];
  size_t k01 = P[(pi0 + j + 1) & km], k11 = P[(pi1 + j + 1) & km];
  const double *GX = t->gx, *GY = t->gy;
  nl_noise_v2d gx0 = {GX[k00], GX[k10]}, gx1 = {GX[k01], GX[k11]};
  nl_noise_v2d a0 = (nl_noise_v2d){GY[k00], GY[k10]} * (nl_noise_v2d){fy, fy};
  nl_noise_v2d a1 = (nl_noise_v2d){GY[k01], GY[k11]} * (nl_noise_v2d){fy - 1.0, fy - 1.0};
  nl_noise_v2d vv = {v, v};
  NL_NOISE_BLEND_(fx, uv[0], NL_NOISE_LERP_(vv, gx0, gx1), NL_NOISE_LERP_(vv, a0, a1), res);
  return res;
}

NL_NOISE_INLINE double nl_noise_perm3_eval(const nl_noise_perm3 *p, double x, double y, double z)
{
  long i = NL_NOISE_TRUNC_(x), j = NL_NOISE_TRUNC_(y), kt = NL_NOISE_TRUNC_(z);
  /* z's cell, fraction and fade come first, whatever z is (they are
   * defined for every double), so that a loop of calls at a constant z
   * computes them once: code after a branch out would stay in the loop. */
  long k = (long)((unsigned long)kt - (z < (double)kt));
  double fz = z - (double)k, fw = NL_NOISE_FADE_(fz);
  nl_noise_v2d w = {fw, fw}, fz0 = {fz, fz}, fz1 = {fz - 1.0, fz - 1.0};
  if ((NL_NOISE_OFF_(i) | NL_NOISE_OFF_(j) | NL_NOISE_OFF_(kt)) >= 0x100000000ull)
    return nl_noise_perm3_eval_general(p, x, y, z);
  i -= x < (double)i;
  j -= y < (double)j;
  double fx = x - (double)i, fy = y - (double)j, res;
  nl_noise_v2d uv = NL_NOISE_FADE_(((nl_noise_v2d){fx, fy}));   /* fades of fx and fy */
  nl_noise_v2d v = {uv[1], uv[1]};
  nl_noise_v2d fy0 = {fy, fy}, fy1 = {fy - 1.0, fy - 1.0};
  /* Perlin's hashes of the corners (i + di, j + dj, k + dk); the table
   * is doubled, so P[X + 1] is column i + 1's. */
  const unsigned char *P = p->p;
  size_t X = (size_t)i & 255, Y = (size_t)j & 255, Z = (size_t)k & 255;
  size_t A = P[X] + Y, B = P[X + 1] + Y;
  size_t AA = P[A] + Z, AB = P[A + 1] + Z, BA = P[B] + Z, BB = P[B + 1] + Z;
  /* The corners' byte offsets into each array of nl_noise_perm3_gradpairs */
  const char *G = (const char *)&nl_noise_perm3_gradpairs;
  size_t q00 = ((size_t)P[AA] & 15) << 8 | ((size_t)P[BA] & 15) << 4;
  size_t q10 = ((size_t)P[AB] & 15) << 8 | ((size_t)P[BB] & 15) << 4;
  size_t q01 = ((size_t)P[AA + 1] & 15) << 8 | ((size_t)P[BA + 1] & 15) << 4;
  size_t q11 = ((size_t)P[AB + 1] & 15) << 8 | ((size_t)P[BB + 1] & 15) << 4;
#define NL_NOISE_GX_(q) (*(const nl_noise_v2d *)(G + (q)))
#define NL_NOISE_GY_(q) (*(const nl_noise_v2d *)(G + 4096 + (q)))
#define NL_NOISE_GZ_(q) (*(const nl_noise_v2d *)(G + 8192 + (q)))
#define NL_NOISE_YZ_(q, fy, fz) (NL_NOISE_GY_(q) * (fy) + NL_NOISE_GZ_(q) * (fz))
  /* Each corner's y and z terms, blended along y then z into the lines */
  nl_noise_v2d gx = NL_NOISE_LERP_(w, NL_NOISE_LERP_(v, NL_NOISE_GX_(q00), NL_NOISE_GX_(q10)),
                                   NL_NOISE_LERP_(v, NL_NOISE_GX_(q01), NL_NOISE_GX_(q11)));
  nl_noise_v2d a00 = NL_NOISE_YZ_(q00, fy0, fz0), a10 = NL_NOISE_YZ_(q10, fy1, fz0);
  nl_noise_v2d a01 = NL_NOISE_YZ_(q01, fy0, fz1), a11 = NL_NOISE_YZ_(q11, fy1, fz1);
  nl_noise_v2d a = NL_NOISE_LERP_(w, NL_NOISE_LERP_(v, a00, a10), NL_NOISE_LERP_(v, a01, a11));
  NL_NOISE_BLEND_(fx, uv[0], gx, a, res);
  return res;
}

/* Octave l adds amp_l * N(freq_l p) to a sum started at 0 (|N| for
 * turbulence), as nl_noise_fractal_row adds its rows. */
NL_NOISE_INLINE double nl_noise_perm3_fractal_eval(const nl_noise_perm3 *p,
                                                   const nl_noise_octaves *o,
                                                   double x, double y, double z)
{
  double sum = 0;
  for (int l = 0; l < o->n; l++) {
    double f = o->freq[l], v = nl_noise_perm3_eval(p, x * f, y * f, z * f);
    sum += o->amp[l] * (o->turbulence ? __builtin_fabs(v) : v);
  }
  return sum;
}

#undef NL_NOISE_YZ_
#undef NL_NOISE_GZ_
#undef NL_NOISE_GY_
#undef NL_NOISE_GX_
#undef NL_NOISE_BLEND_
#undef NL_NOISE_OFF_
#undef NL_NOISE_TRUNC_
#undef NL_NOISE_LERP_
#undef NL_NOISE_FADE_

#endif

#ifdef __cplusplus
}
#endif

#endif
