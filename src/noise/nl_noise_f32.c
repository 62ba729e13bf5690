/* nl_noise_f32.c - the float32 noises (nl_noise.h, "float32 path"): the
 * scalar level, the dispatch to the vector levels, and the public calls.
 *
 * The scalar level is the definition: every vector level repeats its
 * operations lane by lane (nl_noise_f32_math.h holds the arithmetic, written
 * once) and test_noise_f32.c holds them to its bits. fmaf() is correctly
 * rounded, so it gives the bits of the vector levels' vfmadd. */
#include "noise/nl_noise.h"
#include "noise/nl_noise_f32_impl.h"
#include "base/nl_base.h"

#include <math.h>
#include <stdlib.h>

#define NLF_T float
#define NLF_FMA(a, b, c) fmaf((a), (b), (c))
#define NLF_C(k) (k)
#define NLF(name) s_##name
#include "noise/nl_noise_f32_math.h"

const float nl_noise_f32_g3[3][16] = {
  {1, -1, 1, -1, 1, -1, 1, -1, 0, 0, 0, 0, 1, 0, -1, 0},
  {1, 1, -1, -1, 0, 0, 0, 0, 1, -1, 1, -1, 1, -1, 1, -1},
  {0, 0, 0, 0, 1, 1, -1, -1, 1, 1, -1, -1, 0, 1, 0, -1}};

/* The cell floor(x) mod 256 of a float holding an integer. Every float of
 * magnitude 2^31 or more is a multiple of 256, so its cell mod 256 is 0:
 * the value a vector conversion's "integer indefinite" 0x80000000 gives
 * after & 255, which is how the vector levels get it. */
static inline unsigned cell256(float fl)
{
  return fabsf(fl) < 0x1p31f ? (unsigned)(int)fl & 255u : 0u;
}

/* The cell floor(x) mod m (m a power of two, m <= 2^24) of such a float:
 * fl - m floor(fl / m) is an integer in [0, m) computed exactly (1/m is a
 * power of two, the fused multiply-add rounds once, to itself), so it holds
 * for every float; NaN and infinities give cell 0 (their noise is NaN). */
static inline unsigned cellm(float fl, float m, float rm)
{
  float r = fmaf(-m, floorf(fl * rm), fl);
  return r >= 0 && r < m ? (unsigned)(int)r : 0u;
}

static float s_perm3(const nl_noise_perm3 *p, float x, float y, float z)
{
  float flx = floorf(x), fly = floorf(y), flz = floorf(z);
  float fx = x - flx, fy = y - fly, fz = z - flz;
  unsigned X = cell256(flx), Y = cell256(fly), Z = cell256(flz);
  /* Perlin's hashes of the corners; the table is doubled, every sum is
   * taken mod 256 as the vector levels' byte arithmetic takes it */
  const unsigned char *P = p->p;
  unsigned A = (P[X] + Y) & 255, B = (P[X + 1] + Y) & 255;
  unsigned AA = (P[A] + Z) & 255, AB = (P[A + 1] + Z) & 255;
  unsigned BA = (P[B] + Z) & 255, BB = (P[B + 1] + Z) & 255;
  unsigned h0[4] = {P[AA] & 15u, P[AB] & 15u, P[AA + 1] & 15u, P[AB + 1] & 15u};
  unsigned h1[4] = {P[BA] & 15u, P[BB] & 15u, P[BA + 1] & 15u, P[BB + 1] & 15u};
  float gx[4], gy[4], gz[4], GX0, A0, GX1, A1;
  float u = s_fade(fx), v = s_fade(fy), w = s_fade(fz), fy1 = fy - 1.0f, fz1 = fz - 1.0f;
  for (int q = 0; q < 4; q++) {
    gx[q] = nl_noise_f32_g3[0][h0[q]];
    gy[q] = nl_noise_f32_g3[1][h0[q]];
    gz[q] = nl_noise_f32_g3[2][h0[q]];
  }
  s_col3(gx, gy, gz, fy, fy1, fz, fz1, v, w, &GX0, &A0);
  for (int q = 0; q < 4; q++) {
    gx[q] = nl_noise_f32_g3[0][h1[q]];
    gy[q] = nl_noise_f32_g3[1][h1[q]];
    gz[q] = nl_noise_f32_g3[2][h1[q]];
  }
  s_col3(gx, gy, gz, fy, fy1, fz, fz1, v, w, &GX1, &A1);
  return s_blend(fx, u, GX0, A0, GX1, A1);
}

static float s_grad2(const nl_f32_g2 *g, float x, float y)
{
  const nl_noise_grad2 *t = g->t;
  float m = (float)g->m, rm = 1.0f / m;
  float flx = floorf(x), fly = floorf(y);
  float fx = x - flx, fy = y - fly;
  unsigned i = cellm(flx, m, rm), j = cellm(fly, m, rm), km = g->km;
  const unsigned *P = t->perm;
  unsigned s0 = (P[i] + j) & km, s1 = (P[(i + 1) & km] + j) & km;
  unsigned k00 = P[s0], k01 = P[(s0 + 1) & km], k10 = P[s1], k11 = P[(s1 + 1) & km];
  float u = s_fade(fx), v = s_fade(fy), fy1 = fy - 1.0f, GX0, A0, GX1, A1;
  s_col2((float)t->gx[k00], (float)t->gy[k00], (float)t->gx[k01], (float)t->gy[k01], fy, fy1, v,
         &GX0, &A0);
  s_col2((float)t->gx[k10], (float)t->gy[k10], (float)t->gx[k11], (float)t->gy[k11], fy, fy1, v,
         &GX1, &A1);
  return s_blend(fx, u, GX0, A0, GX1, A1);
}

/* The 2D calls on a table the float path does not index (m not a power of
 * two, or above 2^24): the double noise at the same point, rounded. */
static float s_grad2_double(const nl_f32_g2 *g, float x, float y)
{
  return (float)nl_noise_grad2_eval(g->t, (double)x, (double)y);
}

static inline int g2_native(const nl_noise_grad2 *t)
{
  return t->m >= 1 && (t->m & (t->m - 1)) == 0 && t->m <= (1u << 24);
}

/* Octave l adds a_l N(f_l p) (|N| for turbulence) to a sum started at 0. */
static float s_perm3_oct(const nl_noise_perm3 *p, const nl_f32_oct *o, float x, float y, float z)
{
  if (!o) return s_perm3(p, x, y, z);
  float sum = 0.0f;
  for (int l = 0; l < o->n; l++) {
    float f = o->f[l], v = s_perm3(p, x * f, y * f, z * f);
    sum = fmaf(o->a[l], o->turbulence ? fabsf(v) : v, sum);
  }
  return sum;
}

static float s_grad2_oct(const nl_f32_g2 *g, const nl_f32_oct *o, float x, float y)
{
  float (*noise)(const nl_f32_g2 *, float, float) = g2_native(g->t) ? s_grad2 : s_grad2_double;
  if (!o) return noise(g, x, y);
  float sum = 0.0f;
  for (int l = 0; l < o->n; l++) {
    float f = o->f[l], v = noise(g, x * f, y * f);
    sum = fmaf(o->a[l], o->turbulence ? fabsf(v) : v, sum);
  }
  return sum;
}

/* Sample k of a row: x0 + k dx rounded once. */
static inline float row_x(float x0, float dx, size_t k) { return fmaf((float)(int32_t)k, dx, x0); }

/* ---- dispatch ------------------------------------------------------------ */

/* The vector level's kernels, NULL for the scalar code (the SSE2 level
 * runs it: it has no FMA). Both vector levels need FMA besides their own
 * features (every AVX-512 CPU has it; AVX2 ones nearly all). */
static const nl_f32_kernels *kern(void)
{
#if NL_SIMD_X86
  static int fma = -1;
  if (fma < 0) fma = __builtin_cpu_supports("fma") != 0;
  if (fma) {
    switch (nl_simd_get()) {
    case NL_SIMD_AVX512: return &nl_noise_f32_avx512;
    case NL_SIMD_AVX2: return &nl_noise_f32_avx2;
    default: break;
    }
  }
#endif
  return NULL;
}

static nl_f32_oct oct_f32(const nl_noise_octaves *o)
{
  nl_f32_oct r = {0};
  r.n = o->n < 0 ? 0 : o->n > NL_MAX_OCTAVES ? NL_MAX_OCTAVES : o->n;
  r.turbulence = o->turbulence;
  for (int l = 0; l < r.n; l++) {
    r.f[l] = (float)o->freq[l];
    r.a[l] = (float)o->amp[l];
  }
  return r;
}

/* ---- public calls ---------------------------------------------------------- */

float nl_noise_perm3_eval_f32(const nl_noise_perm3 *p, float x, float y, float z)
{
  return s_perm3(p, x, y, z);
}

float nl_noise_grad2_eval_f32(const nl_noise_grad2 *t, float x, float y)
{
  nl_f32_g2 g = {t, (unsigned)t->m, (unsigned)t->m - 1, NULL, NULL};
  return s_grad2_oct(&g, NULL, x, y);
}

static void perm3_points(const nl_noise_perm3 *p, const nl_f32_oct *o, const float *x, const float *y,
                         const float *z, size_t n, float *out)
{
  const nl_f32_kernels *k = kern();
  if (k) {
    k->p3_points(p, o, x, y, z, n, out);
    return;
  }
  for (size_t i = 0; i < n; i++) out[i] = s_perm3_oct(p, o, x[i], y[i], z[i]);
}

static void perm3_row(const nl_noise_perm3 *p, const nl_f32_oct *o, float x0, float dx, float y, float z,
                      size_t n, float *out)
{
  const nl_f32_kernels *k = kern();
  if (k) {
    k->p3_row(p, o, x0, dx, y, z, n, out);
    return;
  }
  for (size_t i = 0; i < n; i++) out[i] = s_perm3_oct(p, o, row_x(x0, dx, i), y, z);
}

/* Batches below this many points skip the vector level's tables (their
 * O(m) set-up) and run the scalar code: the same bits. */
enum { G2_TABLE_MIN = 256 };

/* The batch tables of nl_f32_g2 (O(m) to make: for batches, and grids,
 * which share them over their rows). */
static void g2_tables(const nl_noise_grad2 *t, nl_f32_g2 *g)
{
  uint32_t *pp = nl_xmalloc((t->m + 1) * sizeof *pp);
  float *g4 = nl_xmalloc(8 * t->m * sizeof *g4);
  for (size_t s = 0; s <= t->m; s++) pp[s] = 4 * t->perm[s & g->km];
  for (size_t s = 0; s < 2 * t->m; s++) {
    unsigned e0 = t->perm[s & g->km], e1 = t->perm[(s + 1) & g->km];
    g4[4 * s] = (float)t->gx[e0];
    g4[4 * s + 1] = (float)t->gy[e0];
    g4[4 * s + 2] = (float)t->gx[e1];
    g4[4 * s + 3] = (float)t->gy[e1];
  }
  g->pp = pp;
  g->g4 = g4;
}

static void g2_tables_free(nl_f32_g2 *g)
{
  free((void *)g->pp);
  free((void *)g->g4);
  g->pp = NULL;
  g->g4 = NULL;
}

static void grad2_points(const nl_noise_grad2 *t, const nl_f32_oct *o, const float *x, const float *y,
                         size_t n, float *out)
{
  nl_f32_g2 g = {t, (unsigned)t->m, (unsigned)t->m - 1, NULL, NULL};
  const nl_f32_kernels *k = kern();
  if (k && g2_native(t) && n >= G2_TABLE_MIN) {
    g2_tables(t, &g);
    k->g2_points(&g, o, x, y, n, out);
    g2_tables_free(&g);
    return;
  }
  for (size_t i = 0; i < n; i++) out[i] = s_grad2_oct(&g, o, x[i], y[i]);
}

/* g: the table, with batch tables or without (the rows then read the
 * caller's table column by column). */
static void grad2_row(const nl_f32_g2 *g, const nl_f32_oct *o, float x0, float dx, float y, size_t n,
                      float *out)
{
  const nl_f32_kernels *k = kern();
  if (k && g2_native(g->t)) {
    k->g2_row(g, o, x0, dx, y, n, out);
    return;
  }
  for (size_t i = 0; i < n; i++) out[i] = s_grad2_oct(g, o, row_x(x0, dx, i), y);
}

void nl_noise_perm3_points_f32(const nl_noise_perm3 *p, const float *x, const float *y, const float *z,
                               size_t n, float *out)
{
  perm3_points(p, NULL, x, y, z, n, out);
}

void nl_noise_perm3_row_f32(const nl_noise_perm3 *p, float x0, float dx, float y, float z, size_t n,
                            float *out)
{
  perm3_row(p, NULL, x0, dx, y, z, n, out);
}

void nl_noise_grad2_points_f32(const nl_noise_grad2 *t, const float *x, const float *y, size_t n,
                               float *out)
{
  grad2_points(t, NULL, x, y, n, out);
}

void nl_noise_grad2_row_f32(const nl_noise_grad2 *t, float x0, float dx, float y, size_t n, float *out)
{
  nl_f32_g2 g = {t, (unsigned)t->m, (unsigned)t->m - 1, NULL, NULL};
  grad2_row(&g, NULL, x0, dx, y, n, out);
}

void nl_noise_perm3_fractal_points_f32(const nl_noise_perm3 *p, const nl_noise_octaves *o, const float *x,
                                       const float *y, const float *z, size_t n, float *out)
{
  nl_f32_oct of = oct_f32(o);
  perm3_points(p, &of, x, y, z, n, out);
}

void nl_noise_perm3_fractal_row_f32(const nl_noise_perm3 *p, const nl_noise_octaves *o, float x0,
                                    float dx, float y, float z, size_t n, float *out)
{
  nl_f32_oct of = oct_f32(o);
  perm3_row(p, &of, x0, dx, y, z, n, out);
}

void nl_noise_grad2_fractal_points_f32(const nl_noise_grad2 *t, const nl_noise_octaves *o, const float *x,
                                       const float *y, size_t n, float *out)
{
  nl_f32_oct of = oct_f32(o);
  grad2_points(t, &of, x, y, n, out);
}

void nl_noise_grad2_fractal_row_f32(const nl_noise_grad2 *t, const nl_noise_octaves *o, float x0,
                                    float dx, float y, size_t n, float *out)
{
  nl_f32_oct of = oct_f32(o);
  nl_f32_g2 g = {t, (unsigned)t->m, (unsigned)t->m - 1, NULL, NULL};
  grad2_row(&g, &of, x0, dx, y, n, out);
}

void nl_noise_fractal_grid_f32(const nl_noise_grad2 *t2, const nl_noise_perm3 *p3,
                               const nl_noise_octaves *o, const nl_noise_window *win, float *out)
{
  /* pixel centres as nl_noise_fractal_grid places them, in double, then rounded */
  double dx = win->size / win->w, dy = win->size / win->h;
  nl_f32_oct of = oct_f32(o);
  nl_f32_g2 g = {t2, p3 ? 0 : (unsigned)t2->m, p3 ? 0 : (unsigned)t2->m - 1, NULL, NULL};
  if (!p3 && kern() && g2_native(t2)) g2_tables(t2, &g);   /* the rows' columns read them */
  for (int r = 0; r < win->h; r++) {
    float x0 = (float)(win->x0 + 0.5 * dx), y = (float)(win->y0 + (r + 0.5) * dy);
    float *row = out + (size_t)r * (size_t)win->w;
    if (p3)
      perm3_row(p3, &of, x0, (float)dx, y, (float)win->z, (size_t)win->w, row);
    else
      grad2_row(&g, &of, x0, (float)dx, y, (size_t)win->w, row);
  }
  g2_tables_free(&g);
}
