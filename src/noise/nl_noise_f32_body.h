/* nl_noise_f32_body.h - the float32 kernels of one vector level, included
 * by nl_noise_f32_avx2.c and nl_noise_f32_avx512.c after they define
 *   W                   lanes per vector
 *   vf, vi              GCC vectors of W floats, W ints
 *   NLF_FMA, NLF_C      (nl_noise_f32_math.h)
 *   v_floor, v_cvtt     floor; truncation to int (0x80000000 out of range)
 *   v_i2f, v_abs, vi_c  int to float; |x|; an int broadcast
 *   v_load, v_store     W floats, unaligned
 *   p3ctx, p3ctx_make   the improved noise's tables as the level keeps them
 *   hash3               the 8 corners' gradient numbers (low 4 bits) of
 *                       the cells X, Y, Z (mod 256), in the order 000, 010,
 *                       001, 011, 100, 110, 101, 111 (x y z)
 *   grad3               component 0, 1, 2 of gradients h
 *   g2_get              the 2D corners' gradients of cells (cx, cy) mod m
 *   win_get             lane q: entry idx[q] < 2 W of a window of 2 vectors
 * Library-internal, never installed.
 *
 * Every value is the scalar level's (nl_noise_f32.c): the same operations
 * from nl_noise_f32_math.h, and cells taken as the scalar code takes them.
 * Rows read each lattice column's line (GX, A) from a window of 2 W
 * columns computed a vector at a time, refilled when a vector of samples
 * leaves it; a vector spanning more than 2 W - 1 columns (a step above
 * about two cells) goes through the point code, which computes the same
 * columns for itself, so a row gives its points' bits either way. */

#define NLF_T vf
#define NLF(name) v_##name
#include "noise/nl_noise_f32_math.h"

#include <string.h>

static inline vi v_iota(void)
{
  vi r;
  for (int q = 0; q < W; q++) r[q] = q;
  return r;
}

/* Samples k .. k + W - 1 of a row at octave frequency f (f NULL: 1, and
 * x * 1 = x, so skipping it changes no bit): fmaf(k, dx, x0) * f. kf is
 * k as a float, kept by adding W while that is exact (k < 2^24). */
static inline vf row_x(vf kf, float x0, float dx, const vf *f)
{
  vf x = NLF_FMA(kf, NLF_C(dx), NLF_C(x0));
  return f ? x * *f : x;
}
static inline vf row_k(size_t k) { return v_i2f(vi_c((int)k) + v_iota()); }
/* The largest cell the stored samples of a row reach: samples are
 * monotone in k, so it is the larger of the first and last sample's. */
static inline long long row_hi(float x0, float dx, const vf *f, size_t n)
{
  vi a = v_cvtt(v_floor(row_x(row_k(0), x0, dx, f))), b = v_cvtt(v_floor(row_x(row_k(n - 1), x0, dx, f)));
  return a[0] > b[0] ? a[0] : b[0];
}

/* ---- Perlin's improved noise ---------------------------------------------- */

/* the column of the corners h[0..3] of hash3's order */
static inline void p3_column(const p3ctx *c, const vi h[4], vf fy, vf fy1, vf fz, vf fz1, vf v, vf w,
                             vf *GX, vf *A)
{
  vf gx[4], gy[4], gz[4];
  for (int q = 0; q < 4; q++) {
    gx[q] = grad3(c, 0, h[q]);
    gy[q] = grad3(c, 1, h[q]);
    gz[q] = grad3(c, 2, h[q]);
  }
  v_col3(gx, gy, gz, fy, fy1, fz, fz1, v, w, GX, A);
}

static inline __attribute__((always_inline)) vf p3_eval(const p3ctx *c, vf x, vf y, vf z)
{
  vf flx = v_floor(x), fly = v_floor(y), flz = v_floor(z);
  vf fx = x - flx, fy = y - fly, fz = z - flz;
  vi h[8];
  hash3(c, v_cvtt(flx), v_cvtt(fly), v_cvtt(flz), h);
  vf u = v_fade(fx), v = v_fade(fy), w = v_fade(fz);
  vf fy1 = fy - NLF_C(1.0f), fz1 = fz - NLF_C(1.0f), GX0, A0, GX1, A1;
  p3_column(c, h, fy, fy1, fz, fz1, v, w, &GX0, &A0);
  p3_column(c, h + 4, fy, fy1, fz, fz1, v, w, &GX1, &A1);
  return v_blend(fx, u, GX0, A0, GX1, A1);
}

static inline __attribute__((always_inline)) vf p3_oct(const p3ctx *c, const nl_f32_oct *o, vf x, vf y,
                                                       vf z)
{
  if (!o) return p3_eval(c, x, y, z);
  vf sum = NLF_C(0.0f);
  for (int l = 0; l < o->n; l++) {
    vf f = NLF_C(o->f[l]), v = p3_eval(c, x * f, y * f, z * f);
    sum = NLF_FMA(NLF_C(o->a[l]), o->turbulence ? v_abs(v) : v, sum);
  }
  return sum;
}

static void p3_points(const nl_noise_perm3 *p, const nl_f32_oct *o, const float *x, const float *y,
                      const float *z, size_t n, float *out)
{
  p3ctx c = p3ctx_make(p);
  size_t k = 0;
  if (!o)   /* the plain noise's loop apart, with no octave test inside */
    for (; k + W <= n; k += W) v_store(out + k, p3_eval(&c, v_load(x + k), v_load(y + k), v_load(z + k)));
  else
    for (; k + W <= n; k += W) v_store(out + k, p3_oct(&c, o, v_load(x + k), v_load(y + k), v_load(z + k)));
  if (k < n) {
    float bx[W] = {0}, by[W] = {0}, bz[W] = {0}, bo[W];
    size_t r = n - k;
    memcpy(bx, x + k, r * sizeof *bx);
    memcpy(by, y + k, r * sizeof *by);
    memcpy(bz, z + k, r * sizeof *bz);
    v_store(bo, p3_oct(&c, o, v_load(bx), v_load(by), v_load(bz)));
    memcpy(out + k, bo, r * sizeof *bo);
  }
}

/* A row's state for one octave: y, z scaled and their lattice terms, and
 * the window of columns base .. base + 2W - 1. */
typedef struct {
  vf ys, zs, fy, fy1, fz, fz1, v, w;
  vi Y, Z;
  vf wgx[2], wa[2];
  long long base, hi;   /* window's first column; the row's last cell */
  int have;
} p3row;

static inline void p3_half(const p3ctx *c, p3row *r, int half, long long first)
{
  vi X = vi_c((int)first) + v_iota(), h[8];
  hash3(c, X, r->Y, r->Z, h);
  p3_column(c, h, r->fy, r->fy1, r->fz, r->fz1, r->v, r->w, &r->wgx[half], &r->wa[half]);
}

/* A window holding cells lo .. hi + 1. A row moving on by W columns or
 * more keeps its second half as the first (sparse rows refill every
 * vector or two: one half computed, not two). */
static inline void p3_window(const p3ctx *c, p3row *r, long long lo, long long hi)
{
  long long base = lo;
  if (r->have && lo >= r->base + W && hi <= r->base + 3 * W - 2) {
    r->wgx[0] = r->wgx[1];
    r->wa[0] = r->wa[1];
    base = r->base + W;
  } else {
    p3_half(c, r, 0, base);
  }
  if (r->hi + 1 < base + W)   /* the row ends in the first half */
    r->wgx[1] = r->wa[1] = NLF_C(0.0f);
  else
    p3_half(c, r, 1, base + W);
  r->base = base;
  r->have = 1;
}

/* Out-of-range cells convert to 0x80000000 as in the points (the window then
 * hashes column 0x80000000 + q as X = q mod 256, the points' X and X + 1),
 * so no lane needs a test; the rows' samples are monotone in k, so lanes 0
 * and W - 1 hold the extreme cells. */
static inline vf p3_row_vec(const p3ctx *c, p3row *r, vf x)
{
  vf fl = v_floor(x), t = x - fl;
  vi ci = v_cvtt(fl);
  long long a = ci[0], b = ci[W - 1], lo = a < b ? a : b, hi = a < b ? b : a;
  if (hi - lo > 2 * W - 2) return p3_eval(c, x, r->ys, r->zs);
  if (!r->have || lo < r->base || hi > r->base + 2 * W - 2) p3_window(c, r, lo, hi);
  vi idx = ci - vi_c((int)r->base), idx1 = idx + vi_c(1);
  vf g0 = win_get(r->wgx, idx), a0 = win_get(r->wa, idx);
  vf g1 = win_get(r->wgx, idx1), a1 = win_get(r->wa, idx1);
  return v_blend(t, v_fade(t), g0, a0, g1, a1);
}

static void p3_row(const nl_noise_perm3 *p, const nl_f32_oct *o, float x0, float dx, float y, float z,
                   size_t n, float *out)
{
  if (n == 0) return;
  if (o && o->n <= 0) {   /* an empty sum */
    memset(out, 0, n * sizeof *out);
    return;
  }
  p3ctx c = p3ctx_make(p);
  int nl = o ? o->n : 1;
  for (int l = 0; l < nl; l++) {
    vf f = NLF_C(o ? o->f[l] : 1.0f), amp = NLF_C(o ? o->a[l] : 1.0f);
    p3row r;
    r.ys = NLF_C(y) * f;
    r.zs = NLF_C(z) * f;
    vf fly = v_floor(r.ys), flz = v_floor(r.zs);
    r.fy = r.ys - fly;
    r.fz = r.zs - flz;
    r.Y = v_cvtt(fly);
    r.Z = v_cvtt(flz);
    r.v = v_fade(r.fy);
    r.w = v_fade(r.fz);
    r.fy1 = r.fy - NLF_C(1.0f);
    r.fz1 = r.fz - NLF_C(1.0f);
    r.have = 0;
    r.base = 0;
    r.hi = row_hi(x0, dx, o ? &f : NULL, n);
    vf kf = row_k(0);
    for (size_t k = 0; k < n; k += W, kf = k < (1u << 24) ? kf + NLF_C((float)W) : row_k(k)) {
      vf x = row_x(kf, x0, dx, o ? &f : NULL);
      vf val = p3_row_vec(&c, &r, x);
      size_t m = n - k < W ? n - k : W;
      float buf[W];
      if (o) {
        if (o->turbulence) val = v_abs(val);
        vf sum = NLF_C(0.0f);
        if (l > 0 && m == W) {
          sum = v_load(out + k);
        } else if (l > 0) {
          memcpy(buf, out + k, m * sizeof *buf);
          sum = v_load(buf);
        }
        val = NLF_FMA(amp, val, sum);
      }
      if (m == W) {
        v_store(out + k, val);
      } else {
        v_store(buf, val);
        memcpy(out + k, buf, m * sizeof *buf);
      }
    }
  }
}

/* ---- the 2D table noise ------------------------------------------------------ */

/* floor(x) mod m of a float holding an integer, as the scalar cellm */
static inline vi g2_cell(vf fl, vf m, vf rm, vi km)
{
  vf r = NLF_FMA(-m, v_floor(fl * rm), fl);
  return v_cvtt(r) & km;
}

/* Corners of cells (cx, cy) lane by lane from the caller's table (no
 * batch tables): gradients as the scalar code rounds them. */
static inline void g2_get_lanes(const nl_f32_g2 *g, vi cx, vi cy, vf gx[4], vf gy[4])
{
  const unsigned *P = g->t->perm;
  const double *GX = g->t->gx, *GY = g->t->gy;
  unsigned km = g->km;
  float ax[4][W], ay[4][W];
  for (int q = 0; q < W; q++) {
    unsigned i = (unsigned)cx[q], j = (unsigned)cy[q];
    unsigned s0 = (P[i] + j) & km, s1 = (P[(i + 1) & km] + j) & km;
    unsigned k[4] = {P[s0], P[(s0 + 1) & km], P[s1], P[(s1 + 1) & km]};
    for (int e = 0; e < 4; e++) {
      ax[e][q] = (float)GX[k[e]];
      ay[e][q] = (float)GY[k[e]];
    }
  }
  for (int e = 0; e < 4; e++) {
    gx[e] = v_load(ax[e]);
    gy[e] = v_load(ay[e]);
  }
}

/* tab: read the batch tables (g->pp, g->g4), else the caller's table */
static inline __attribute__((always_inline)) vf g2_eval(const nl_f32_g2 *g, vf x, vf y, int tab)
{
  /* 1/m exact: m is a power of two */
  vf m = NLF_C((float)g->m), rm = NLF_C(0x1p-24f * (float)((1u << 24) / g->m));
  vi km = vi_c((int)g->km);
  vf flx = v_floor(x), fly = v_floor(y), fx = x - flx, fy = y - fly;
  vi cx = g2_cell(flx, m, rm, km), cy = g2_cell(fly, m, rm, km);
  vf gx[4], gy[4], GX0, A0, GX1, A1;
  if (tab)
    g2_get(g, cx, cy, gx, gy);
  else
    g2_get_lanes(g, cx, cy, gx, gy);
  vf u = v_fade(fx), v = v_fade(fy), fy1 = fy - NLF_C(1.0f);
  v_col2(gx[0], gy[0], gx[1], gy[1], fy, fy1, v, &GX0, &A0);
  v_col2(gx[2], gy[2], gx[3], gy[3], fy, fy1, v, &GX1, &A1);
  return v_blend(fx, u, GX0, A0, GX1, A1);
}

static inline __attribute__((always_inline)) vf g2_oct(const nl_f32_g2 *g, const nl_f32_oct *o, vf x,
                                                       vf y)
{
  if (!o) return g2_eval(g, x, y, 1);
  vf sum = NLF_C(0.0f);
  for (int l = 0; l < o->n; l++) {
    vf f = NLF_C(o->f[l]), v = g2_eval(g, x * f, y * f, 1);
    sum = NLF_FMA(NLF_C(o->a[l]), o->turbulence ? v_abs(v) : v, sum);
  }
  return sum;
}

static void g2_points(const nl_f32_g2 *gp, const nl_f32_oct *o, const float *x, const float *y, size_t n,
                      float *out)
{
  const nl_f32_g2 gl = *gp, *g = &gl;   /* a copy no store can alias: m and the tables stay in registers */
  size_t k = 0;
  if (!o)
    for (; k + W <= n; k += W) v_store(out + k, g2_eval(g, v_load(x + k), v_load(y + k), 1));
  else
    for (; k + W <= n; k += W) v_store(out + k, g2_oct(g, o, v_load(x + k), v_load(y + k)));
  if (k < n) {
    float bx[W] = {0}, by[W] = {0}, bo[W];
    size_t r = n - k;
    memcpy(bx, x + k, r * sizeof *bx);
    memcpy(by, y + k, r * sizeof *by);
    v_store(bo, g2_oct(g, o, v_load(bx), v_load(by)));
    memcpy(out + k, bo, r * sizeof *bo);
  }
}

typedef struct {
  vf ys, fy, fy1, v;
  unsigned jm;
  vf wgx[2], wa[2];
  long long base, hi;
  int have;
} g2row;

static inline void g2_window(const nl_f32_g2 *g, g2row *r, long long base)
{
  const unsigned *P = g->t->perm;
  const double *GX = g->t->gx, *GY = g->t->gy;
  unsigned km = g->km, j = r->jm;
  float a[4][2 * W] = {{0}};
  long long cols = r->hi + 2 - base < 2 * W ? r->hi + 2 - base : 2 * W;
  if (g->g4) {   /* a grid's batch tables: the column's two corners, one entry */
    const float *G = g->g4 + 4 * j;
    for (int q = 0; q < cols; q++) {
      const float *e = G + g->pp[(unsigned)(base + q) & km];
      for (int c = 0; c < 4; c++) a[c][q] = e[c];
    }
  } else {
    for (int q = 0; q < cols; q++) {
      unsigned s = (P[(unsigned)(base + q) & km] + j) & km, k0 = P[s], k1 = P[(s + 1) & km];
      a[0][q] = (float)GX[k0];
      a[1][q] = (float)GY[k0];
      a[2][q] = (float)GX[k1];
      a[3][q] = (float)GY[k1];
    }
  }
  for (int half = 0; half < 2; half++) {
    int o = half * W;
    v_col2(v_load(a[0] + o), v_load(a[1] + o), v_load(a[2] + o), v_load(a[3] + o), r->fy, r->fy1, r->v,
           &r->wgx[half], &r->wa[half]);
  }
  r->base = base;
  r->have = 1;
}

/* As p3_row_vec; a cell out of int's range (0x80000000) would hash by
 * its low bits, not mod m by value: such vectors take the point code. */
static inline vf g2_row_vec(const nl_f32_g2 *g, g2row *r, vf x)
{
  vf fl = v_floor(x), t = x - fl;
  vi ci = v_cvtt(fl);
  long long a = ci[0], b = ci[W - 1], lo = a < b ? a : b, hi = a < b ? b : a;
  if (lo == -0x80000000LL || hi - lo > 2 * W - 2) return g2_eval(g, x, r->ys, 0);
  if (!r->have || lo < r->base || hi > r->base + 2 * W - 2) g2_window(g, r, lo);
  vi idx = ci - vi_c((int)r->base), idx1 = idx + vi_c(1);
  vf g0 = win_get(r->wgx, idx), a0 = win_get(r->wa, idx);
  vf g1 = win_get(r->wgx, idx1), a1 = win_get(r->wa, idx1);
  return v_blend(t, v_fade(t), g0, a0, g1, a1);
}

static void g2_row(const nl_f32_g2 *gp, const nl_f32_oct *o, float x0, float dx, float y, size_t n,
                   float *out)
{
  const nl_f32_g2 gl = *gp, *g = &gl;   /* a copy no store can alias */
  if (n == 0) return;
  if (o && o->n <= 0) {   /* an empty sum */
    memset(out, 0, n * sizeof *out);
    return;
  }
  int nl = o ? o->n : 1;
  vf m = NLF_C((float)g->m), rm = NLF_C(1.0f / (float)g->m);
  for (int l = 0; l < nl; l++) {
    vf f = NLF_C(o ? o->f[l] : 1.0f), amp = NLF_C(o ? o->a[l] : 1.0f);
    g2row r;
    r.ys = NLF_C(y) * f;
    vf fly = v_floor(r.ys);
    r.fy = r.ys - fly;
    r.jm = (unsigned)g2_cell(fly, m, rm, vi_c((int)g->km))[0];
    r.v = v_fade(r.fy);
    r.fy1 = r.fy - NLF_C(1.0f);
    r.have = 0;
    r.base = 0;
    r.hi = row_hi(x0, dx, o ? &f : NULL, n);
    vf kf = row_k(0);
    for (size_t k = 0; k < n; k += W, kf = k < (1u << 24) ? kf + NLF_C((float)W) : row_k(k)) {
      vf x = row_x(kf, x0, dx, o ? &f : NULL);
      vf val = g2_row_vec(g, &r, x);
      size_t mm = n - k < W ? n - k : W;
      float buf[W];
      if (o) {
        if (o->turbulence) val = v_abs(val);
        vf sum = NLF_C(0.0f);
        if (l > 0 && mm == W) {
          sum = v_load(out + k);
        } else if (l > 0) {
          memcpy(buf, out + k, mm * sizeof *buf);
          sum = v_load(buf);
        }
        val = NLF_FMA(amp, val, sum);
      }
      if (mm == W) {
        v_store(out + k, val);
      } else {
        v_store(buf, val);
        memcpy(out + k, buf, mm * sizeof *buf);
      }
    }
  }
}
