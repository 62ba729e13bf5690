#include "noise/nl_noise.h"
#include "base/nl_base.h"
#include "noise/nl_noise_simd.h"
#include "noise/nl_noise_lattice.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>



/* The shared final step of both noises (see the header): column lines
 * L_c(t) = t GX_c + A_c blended across the cell with the fade of t. */
static inline double blend(double t, double gx0, double a0, double gx1, double a1)
{
  double l = t * gx0 + a0;
  double r = (t - 1) * gx1 + a1;
  return l + nl_noise_fade(t) * (r - l);
}

/* The library's copies of the inline point calls (C99 6.7.4: an extern
 * declaration makes this file's definition the external one). */
extern inline double nl_noise_grad2_eval(const nl_noise_grad2 *t, double x, double y);
extern inline double nl_noise_perm3_eval(const nl_noise_perm3 *p, double x, double y, double z);
extern inline double nl_noise_perm3_fractal_eval(const nl_noise_perm3 *p, const nl_noise_octaves *o,
                                                 double x, double y, double z);

/* ---- 2D --------------------------------------------------------------- */

nl_noise_grad2 *nl_noise_grad2_alloc(size_t m)
{
  nl_noise_grad2 *t = nl_xmalloc(sizeof *t);
  t->m = m;
  t->angle = nl_xcalloc(m, sizeof *t->angle);
  t->gx = nl_xcalloc(m, sizeof *t->gx);
  t->gy = nl_xcalloc(m, sizeof *t->gy);
  t->perm = nl_xcalloc(m, sizeof *t->perm);
  for (size_t k = 0; k < m; k++) { t->perm[k] = (unsigned)k; nl_noise_grad2_set_angle(t, k, 0); }
  return t;
}

void nl_noise_grad2_free(nl_noise_grad2 *t)
{
  if (!t) return;
  free(t->angle); free(t->gx); free(t->gy); free(t->perm); free(t);
}

void nl_noise_grad2_set_angle(nl_noise_grad2 *t, size_t k, double theta)
{
  t->angle[k] = theta;
  t->gx[k] = cos(theta);
  t->gy[k] = sin(theta);
}

void nl_noise_grad2_copy(nl_noise_grad2 *dst, const nl_noise_grad2 *src)
{
  memcpy(dst->angle, src->angle, src->m * sizeof *src->angle);
  memcpy(dst->gx, src->gx, src->m * sizeof *src->gx);
  memcpy(dst->gy, src->gy, src->m * sizeof *src->gy);
  memcpy(dst->perm, src->perm, src->m * sizeof *src->perm);
}

void nl_noise_grad2_seed(nl_noise_grad2 *t, unsigned long seed)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, nl_seed_stream(seed, "noise.grad2", 0));
  for (size_t k = 0; k < t->m; k++) nl_noise_grad2_set_angle(t, k, NL_TWO_PI * gsl_rng_uniform(r));
  for (size_t k = 0; k < t->m; k++) t->perm[k] = (unsigned)k;
  gsl_ran_shuffle(r, t->perm, t->m, sizeof *t->perm);
  gsl_rng_free(r);
}

size_t nl_noise_grad2_index(const nl_noise_grad2 *t, long i, long j)
{
  long m = (long)t->m;
  /* A power-of-two m: i mod m is a mask (two's complement), no division. */
  if (m > 0 && (m & (m - 1)) == 0) { long k = m - 1; return t->perm[((long)t->perm[i & k] + j) & k]; }
  long pi = (long)t->perm[nl_noise_lmod(i, m)];
  return t->perm[nl_noise_lmod(pi + nl_noise_lmod(j, m), m)];
}

/* Column i at row j with fractional fy and its fade v: blend the two
 * corners along y into the line t GX + A. */
static inline void column2(const nl_noise_grad2 *t, long i, long j, double fy, double v,
                           double *gxo, double *ao)
{
  size_t k0 = nl_noise_grad2_index(t, i, j), k1 = nl_noise_grad2_index(t, i, j + 1);
  double a0 = t->gy[k0] * fy, a1 = t->gy[k1] * (fy - 1);
  *gxo = t->gx[k0] + v * (t->gx[k1] - t->gx[k0]);
  *ao = a0 + v * (a1 - a0);
}

/* The inline nl_noise_grad2_eval (nl_noise.h) computes this for most
 * points with the same operations; this copy takes every double and any m. */
double nl_noise_grad2_eval_general(const nl_noise_grad2 *t, double x, double y)
{
  long i = nl_noise_lfloor(x), j = nl_noise_lfloor(y);
  double fy = nl_noise_lfrac(y, j), v = nl_noise_fade(fy), g0, a0, g1, a1;
  column2(t, i, j, fy, v, &g0, &a0);
  column2(t, i + 1, j, fy, v, &g1, &a1);
  return blend(nl_noise_lfrac(x, i), g0, a0, g1, a1);
}

/* The sample loop shared by both noises once columns are collapsed. */
static void row_from_columns(const double *gx, const double *a, long ifirst,
                             double x0, double dx, size_t n, double *out)
{
  for (size_t k = 0; k < n; k++) {
    double x = x0 + (double)k * dx;
    long i = nl_noise_lfloor(x);
    size_t c = (size_t)(i - ifirst);
    out[k] = blend(nl_noise_lfrac(x, i), gx[c], a[c], gx[c + 1], a[c + 1]);
  }
}


#define NL_STACK_COLS 1040

void nl_noise_grad2_row(const nl_noise_grad2 *t, double x0, double dx, double y, size_t n, double *out)
{
  if (n == 0) return;
  if (nl_noise_simd_row2(t, x0, dx, y, n, out) == GSL_SUCCESS) return;   /* nl_noise_simd.c */
  long ifirst;
  size_t ncol = row_columns(x0, dx, n, &ifirst);
  if (ncol == 0) {
    for (size_t k = 0; k < n; k++) out[k] = nl_noise_grad2_eval(t, x0 + (double)k * dx, y);
    return;
  }
  double sgx[NL_STACK_COLS], sa[NL_STACK_COLS];
  double *gx = ncol <= NL_STACK_COLS ? sgx : nl_xmalloc(ncol * sizeof *gx);
  double *a = ncol <= NL_STACK_COLS ? sa : nl_xmalloc(ncol * sizeof *a);
  long j = nl_noise_lfloor(y);
  double fy = nl_noise_lfrac(y, j), v = nl_noise_fade(fy);
  for (size_t c = 0; c < ncol; c++) column2(t, ifirst + (long)c, j, fy, v, &gx[c], &a[c]);
  row_from_columns(gx, a, ifirst, x0, dx, n, out);
  if (gx != sgx) { free(gx); free(a); }
}

/* ---- 3D gradient-table noise ------------------------------------------ */

nl_noise_grad3 *nl_noise_grad3_alloc(size_t m)
{
  nl_noise_grad3 *t = nl_xcalloc(1, sizeof *t);
  t->m = m;
  t->v = nl_xcalloc(3 * m, sizeof *t->v);
  t->z = nl_xcalloc(m, sizeof *t->z);
  t->phi = nl_xcalloc(m, sizeof *t->phi);
  t->perm = nl_xcalloc(m, sizeof *t->perm);
  for (size_t k = 0; k < m; k++) {
    t->perm[k] = (unsigned)k;
    t->v[3 * k + 2] = t->z[k] = 1;
  }
  return t;
}

void nl_noise_grad3_free(nl_noise_grad3 *t)
{
  if (!t) return;
  free(t->v);
  free(t->z);
  free(t->phi);
  free(t->perm);
  free(t);
}

void nl_noise_grad3_set(nl_noise_grad3 *t, size_t k, const double u[3])
{
  double n = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]), *v = t->v + 3 * k;
  for (int a = 0; a < 3; a++) v[a] = u[a] / n;
  t->z[k] = fmax(-1.0, fmin(1.0, v[2]));
  double ph = atan2(v[1], v[0]);
  if (ph < 0) ph += NL_TWO_PI;
  t->phi[k] = ph >= NL_TWO_PI ? 0.0 : ph;   /* -tiny + 2 pi rounds to 2 pi */
}

void nl_noise_grad3_seed(nl_noise_grad3 *t, unsigned long seed)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, nl_seed_stream(seed, "cheng3.table", 0));
  for (size_t k = 0; k < t->m; k++) {   /* hat-box: z ~ U(-1, 1), phi ~ U(0, 2 pi) */
    double z = 2 * gsl_rng_uniform(r) - 1, ph = NL_TWO_PI * gsl_rng_uniform(r);
    double s = sqrt(1 - z * z);
    double u[3] = {s * cos(ph), s * sin(ph), z};
    nl_noise_grad3_set(t, k, u);
  }
  for (size_t k = 0; k < t->m; k++) t->perm[k] = (unsigned)k;
  gsl_ran_shuffle(r, t->perm, t->m, sizeof *t->perm);
  gsl_rng_free(r);
}

void nl_noise_grad3_copy(nl_noise_grad3 *dst, const nl_noise_grad3 *src)
{
  memcpy(dst->v, src->v, 3 * src->m * sizeof *dst->v);
  memcpy(dst->z, src->z, src->m * sizeof *dst->z);
  memcpy(dst->phi, src->phi, src->m * sizeof *dst->phi);
  memcpy(dst->perm, src->perm, src->m * sizeof *dst->perm);
}

size_t nl_noise_grad3_index(const nl_noise_grad3 *t, long i, long j, long k)
{
  long m = (long)t->m;
  long pi = (long)t->perm[nl_noise_lmod(i, m)];
  long pj = (long)t->perm[nl_noise_lmod(pi + nl_noise_lmod(j, m), m)];
  return t->perm[nl_noise_lmod(pj + nl_noise_lmod(k, m), m)];
}

void nl_noise_grad3_corners(const nl_noise_grad3 *t, double x, double y, double z, double amp,
                            uint32_t entry[8], double w[24])
{
  double p[3] = {x, y, z}, f[3], s[3][2];
  long c0[3];
  for (int a = 0; a < 3; a++) {
    c0[a] = nl_noise_lfloor(p[a]);
    f[a] = nl_noise_lfrac(p[a], c0[a]);
    s[a][1] = nl_noise_fade(f[a]);
    s[a][0] = 1 - s[a][1];
  }
  for (int q = 0; q < 8; q++) {
    int b[3] = {q & 1, (q >> 1) & 1, (q >> 2) & 1};
    entry[q] = (uint32_t)nl_noise_grad3_index(t, c0[0] + b[0], c0[1] + b[1], c0[2] + b[2]);
    double ww = amp * s[0][b[0]] * s[1][b[1]] * s[2][b[2]];
    for (int a = 0; a < 3; a++) w[3 * q + a] = ww * (f[a] - b[a]);
  }
}

double nl_noise_grad3_eval(const nl_noise_grad3 *t, double x, double y, double z)
{
  uint32_t entry[8];
  double w[24], sum = 0;
  nl_noise_grad3_corners(t, x, y, z, 1.0, entry, w);
  for (int q = 0; q < 8; q++) {
    const double *g = t->v + 3 * entry[q];
    sum += w[3 * q] * g[0] + w[3 * q + 1] * g[1] + w[3 * q + 2] * g[2];
  }
  return sum;
}

/* ---- 3D improved noise ------------------------------------------------ */

/* Perlin 2002's permutation, all 256 entries: the array is sized by its
 * initialiser and checked, so a dropped entry cannot become a silent 0. */
static const unsigned char perlin_permutation[] = {
  151,160,137,91,90,15,131,13,201,95,96,53,194,233,7,225,140,36,103,30,69,142,
  8,99,37,240,21,10,23,190,6,148,247,120,234,75,0,26,197,62,94,252,219,203,117,
  35,11,32,57,177,33,88,237,149,56,87,174,20,125,136,171,168,68,175,74,165,71,
  134,139,48,27,166,77,146,158,231,83,111,229,122,60,211,133,230,220,105,92,41,
  55,46,245,40,244,102,143,54,65,25,63,161,1,216,80,73,209,76,132,187,208,89,
  18,169,200,196,135,130,116,188,159,86,164,100,109,198,173,186,3,64,52,217,226,
  250,124,123,5,202,38,147,118,126,255,82,85,212,207,206,59,227,47,16,58,17,182,
  189,28,42,223,183,170,213,119,248,152,2,44,154,163,70,221,153,101,155,167,43,
  172,9,129,22,39,253,19,98,108,110,79,113,224,232,178,185,112,104,218,246,97,
  228,251,34,242,193,238,210,144,12,191,179,162,241,81,51,145,235,249,14,239,
  107,49,192,214,31,181,199,106,157,184,84,204,176,115,121,50,45,127,4,150,254,
  138,236,205,93,222,114,67,29,24,72,243,141,128,195,78,66,215,61,156,180};
_Static_assert(sizeof perlin_permutation == 256, "Perlin's permutation has 256 entries");

/* Perlin's grad(hash, x, y, z) as vectors: the 12 cube edges, 4 repeated. */
static const double grad3[16][3] = {
  {1,1,0},{-1,1,0},{1,-1,0},{-1,-1,0},{1,0,1},{-1,0,1},{1,0,-1},{-1,0,-1},
  {0,1,1},{0,-1,1},{0,1,-1},{0,-1,-1},{1,1,0},{0,-1,1},{-1,1,0},{0,-1,-1}};

void nl_noise_perm3_reference(nl_noise_perm3 *p)
{
  for (int k = 0; k < 512; k++) p->p[k] = perlin_permutation[k & 255];
}

void nl_noise_perm3_seed(nl_noise_perm3 *p, unsigned long seed)
{
  unsigned char base[256];
  for (int k = 0; k < 256; k++) base[k] = (unsigned char)k;
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, nl_seed_stream(seed, "noise.perm3", 0));
  gsl_ran_shuffle(r, base, 256, 1);
  gsl_rng_free(r);
  for (int k = 0; k < 512; k++) p->p[k] = base[k & 255];
}

/* The same 16 gradients as constant expressions, for the pair table of the
 * inline point call: G3X(h) = grad3[h][0], and so on (test_noise checks). */
#define G3X(h) ((h) == 12 ? 1 : (h) == 14 ? -1 : (h) < 8 ? ((h) & 1 ? -1 : 1) : 0)
#define G3Y(h) ((h) < 4 ? ((h) & 2 ? -1 : 1) : (h) < 8 ? 0 : (h) == 12 || (h) == 14 ? 1 \
                : (h) == 13 || (h) == 15 ? -1 : ((h) & 1 ? -1 : 1))
#define G3Z(h) ((h) < 4 || (h) == 12 || (h) == 14 ? 0 : (h) < 8 ? ((h) & 2 ? -1 : 1) \
                : (h) == 13 ? 1 : (h) == 15 ? -1 : ((h) & 2 ? -1 : 1))
#define P2(C, a, b) {C(a), C(b)}
#define P16(C, a) P2(C, a, 0), P2(C, a, 1), P2(C, a, 2), P2(C, a, 3), P2(C, a, 4), P2(C, a, 5), \
                  P2(C, a, 6), P2(C, a, 7), P2(C, a, 8), P2(C, a, 9), P2(C, a, 10), P2(C, a, 11), \
                  P2(C, a, 12), P2(C, a, 13), P2(C, a, 14), P2(C, a, 15)
#define P256(C) {P16(C, 0), P16(C, 1), P16(C, 2), P16(C, 3), P16(C, 4), P16(C, 5), P16(C, 6), \
                 P16(C, 7), P16(C, 8), P16(C, 9), P16(C, 10), P16(C, 11), P16(C, 12), P16(C, 13), \
                 P16(C, 14), P16(C, 15)}
const nl_noise_perm3_gradpairs_table nl_noise_perm3_gradpairs = {P256(G3X), P256(G3Y), P256(G3Z)};

/* Corner contribution without its x term: gy (fy - dj) + gz (fz - dk). */
static inline double yz_part(int h, double fy, double fz)
{
  return grad3[h][1] * fy + grad3[h][2] * fz;
}

static inline double lerp(double t, double a, double b) { return a + t * (b - a); }

static inline void column3(const nl_noise_perm3 *p, long i, long j, long k, double fy, double fz,
                           double v, double w, double *gxo, double *ao)
{
  int X = (int)(i & 255), Y = (int)(j & 255), Z = (int)(k & 255);
  int A = p->p[X] + Y, AA = p->p[A] + Z, AB = p->p[A + 1] + Z;
  int h00 = p->p[AA] & 15, h10 = p->p[AB] & 15, h01 = p->p[AA + 1] & 15, h11 = p->p[AB + 1] & 15;
  double gx = lerp(w, lerp(v, grad3[h00][0], grad3[h10][0]), lerp(v, grad3[h01][0], grad3[h11][0]));
  double a = lerp(w, lerp(v, yz_part(h00, fy, fz), yz_part(h10, fy - 1, fz)),
                  lerp(v, yz_part(h01, fy, fz - 1), yz_part(h11, fy - 1, fz - 1)));
  *gxo = gx;
  *ao = a;
}

/* The inline nl_noise_perm3_eval (nl_noise.h) computes this for most
 * points with the same operations; this copy takes every double. */
double nl_noise_perm3_eval_general(const nl_noise_perm3 *p, double x, double y, double z)
{
  long i = nl_noise_lfloor(x), j = nl_noise_lfloor(y), k = nl_noise_lfloor(z);
  double fy = nl_noise_lfrac(y, j), fz = nl_noise_lfrac(z, k);
  double v = nl_noise_fade(fy), w = nl_noise_fade(fz), g0, a0, g1, a1;
  column3(p, i, j, k, fy, fz, v, w, &g0, &a0);
  column3(p, i + 1, j, k, fy, fz, v, w, &g1, &a1);
  return blend(nl_noise_lfrac(x, i), g0, a0, g1, a1);
}

void nl_noise_perm3_row(const nl_noise_perm3 *p, double x0, double dx, double y, double z,
                        size_t n, double *out)
{
  if (n == 0) return;
  if (nl_noise_simd_row3(p, x0, dx, y, z, n, out) == GSL_SUCCESS) return;   /* nl_noise_simd.c */
  long ifirst;
  size_t ncol = row_columns(x0, dx, n, &ifirst);
  if (ncol == 0) {
    for (size_t k = 0; k < n; k++) out[k] = nl_noise_perm3_eval(p, x0 + (double)k * dx, y, z);
    return;
  }
  double sgx[NL_STACK_COLS], sa[NL_STACK_COLS];
  double *gx = ncol <= NL_STACK_COLS ? sgx : nl_xmalloc(ncol * sizeof *gx);
  double *a = ncol <= NL_STACK_COLS ? sa : nl_xmalloc(ncol * sizeof *a);
  long j = nl_noise_lfloor(y), k = nl_noise_lfloor(z);
  double fy = nl_noise_lfrac(y, j), fz = nl_noise_lfrac(z, k);
  double v = nl_noise_fade(fy), w = nl_noise_fade(fz);
  for (size_t c = 0; c < ncol; c++) column3(p, ifirst + (long)c, j, k, fy, fz, v, w, &gx[c], &a[c]);
  row_from_columns(gx, a, ifirst, x0, dx, n, out);
  if (gx != sgx) { free(gx); free(a); }
}

/* ---- bases and sums --------------------------------------------------- */

static void grad2_row(const void *ctx, double x0, double dx, double y, double z, size_t n, double *out)
{
  (void)z;
  nl_noise_grad2_row(ctx, x0, dx, y, n, out);
}

static void perm3_row(const void *ctx, double x0, double dx, double y, double z, size_t n, double *out)
{
  nl_noise_perm3_row(ctx, x0, dx, y, z, n, out);
}

nl_noise_basis nl_noise_basis_grad2(const nl_noise_grad2 *t)
{
  nl_noise_basis b = {grad2_row, t, NL_NOISE2_BOUND};
  return b;
}

nl_noise_basis nl_noise_basis_perm3(const nl_noise_perm3 *p)
{
  nl_noise_basis b = {perm3_row, p, NL_NOISE3_BOUND};
  return b;
}

nl_noise_octaves nl_noise_octaves_fbm(int n, double gain, double lacunarity)
{
  nl_noise_octaves o = {.n = n < 0 ? 0 : n > NL_MAX_OCTAVES ? NL_MAX_OCTAVES : n};
  double a = 1, f = 1;
  for (int l = 0; l < o.n; l++, a *= gain, f *= lacunarity) { o.amp[l] = a; o.freq[l] = f; }
  return o;
}

nl_noise_octaves nl_noise_octaves_fractal(int n) { return nl_noise_octaves_fbm(n, 0.5, 2.0); }

nl_noise_octaves nl_noise_octaves_cheng(int n, double f1, double a1)
{
  nl_noise_octaves o = nl_noise_octaves_fbm(n, 1.0, 2.0);
  for (int l = 0; l < o.n; l++) { o.freq[l] = f1 * o.freq[l]; o.amp[l] = 1.0 / (a1 * ldexp(1.0, l)); }
  return o;
}

double nl_noise_octaves_bound(const nl_noise_octaves *o, double basis_bound)
{
  double s = 0;
  for (int l = 0; l < o->n; l++) s += fabs(o->amp[l]);
  return s * basis_bound;
}

void nl_noise_fractal_row(const nl_noise_basis *b, const nl_noise_octaves *o, double x0, double dx,
                          double y, double z, size_t n, double *out, double *scratch)
{
  if (nl_noise_simd_fractal_row(b, o, x0, dx, y, z, n, out, scratch) == GSL_SUCCESS) return;
  for (size_t k = 0; k < n; k++) out[k] = 0;
  for (int l = 0; l < o->n; l++) {
    double f = o->freq[l], a = o->amp[l];
    b->row(b->ctx, x0 * f, dx * f, y * f, z * f, n, scratch);
    if (o->turbulence) for (size_t k = 0; k < n; k++) out[k] += a * fabs(scratch[k]);
    else for (size_t k = 0; k < n; k++) out[k] += a * scratch[k];
  }
}

void nl_noise_fractal_points(const nl_noise_basis *b, const nl_noise_octaves *o, const double *x,
                             const double *y, const double *z, size_t n, double *out)
{
  double scratch;
  for (size_t k = 0; k < n; k++)
    nl_noise_fractal_row(b, o, x[k], 0.0, y[k], z ? z[k] : 0.0, 1, out + k, &scratch);
}

double nl_noise_octaves_fmax(const nl_noise_octaves *o)
{
  double f = o->n > 0 ? 0.0 : 1.0;
  for (int l = 0; l < o->n; l++) f = fabs(o->freq[l]) > f ? fabs(o->freq[l]) : f;
  return f;
}

void nl_noise_fractal_grid(const nl_noise_basis *b, const nl_noise_octaves *o, const nl_noise_window *win, double *out)
{
  double dx = win->size / win->w, dy = win->size / win->h;
  double *scratch = nl_xmalloc((size_t)win->w * sizeof *scratch);
  for (int r = 0; r < win->h; r++)
    nl_noise_fractal_row(b, o, win->x0 + 0.5 * dx, dx, win->y0 + (r + 0.5) * dy, win->z,
                         (size_t)win->w, out + (size_t)r * win->w, scratch);
  free(scratch);
}
