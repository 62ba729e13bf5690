/* nl_cellular_simd_body.h - the SIMD row kernel of cellular F1..F4, written
 * once with GCC vector extensions. Included by nl_cellular_simd_{sse2,avx2,
 * avx512}.c after they define, for their instruction set:
 *   NL_CELL_W            lanes of double
 *   NL_CELL_ROW          the name of the kernel to define (nl_cellular_simd.h)
 *   vd, vl               W doubles, W int64 (comparison results)
 *   v_floor(vd)          floor, exact for |x| < 2^52
 *   v_min, v_max(vd, vd) a < b ? a : b and a > b ? a : b (no NaN reaches them)
 *   v_sqrt(vd)           IEEE square root (correctly rounded, as sqrt())
 *   v_any(vl)            some lane true
 *
 * Lanes are W consecutive samples of the row. Per lane the kernel computes
 * the scalar kernel's squared distances by the same operations, in the same
 * order, (ax * ax + ay2) + az2 with ax = px - x, and keeps the 4 smallest by
 * a sorting network of min/max (d0 <= d1 <= d2 <= d3): the same multiset as
 * the scalar insertion, hence the same sorted bits. Lanes may sit in
 * different cube columns: each cube is offered to a lane only if it is one
 * of the lane's 27 (its bound is +inf otherwise) and its bound is below the
 * lane's current F_n^2 (nl_cellular_simd.h: skipping it changes nothing);
 * a cube no lane needs is skipped.
 */
#include <math.h>
#include <string.h>

#define NL_SIMD_W NL_CELL_W
#include "simd/nl_simd_vec.h"   /* splat */
static inline vd sel(vl m, vd a, vd b) { return (vd)((m & (vl)a) | (~m & (vl)b)); }

typedef struct { vd d[4]; } dset;

/* Inserts v (per lane) into the 4 smallest, ascending. */
static inline void net(dset *s, vd v)
{
  s->d[3] = v_min(s->d[3], v_max(s->d[2], v));
  s->d[2] = v_min(s->d[2], v_max(s->d[1], v));
  s->d[1] = v_min(s->d[1], v_max(s->d[0], v));
  s->d[0] = v_min(s->d[0], v);
}

/* U vectors of lanes at a time: the network is a chain of dependent
 * min/max per point, so independent vectors keep the units busy. */
#define NL_CELL_U 2

/* The cube (column col, class q = 3 cy + cz) for the lanes at x in columns
 * cl (as doubles) with squared face distances lo2 (below) and hi2 (above). */
static inline void cube(const nl_cellular_rowpts *R, size_t col, int q, const vd *x, const vd *cl,
                        const vd *lo2, const vd *hi2, int n, dset *s)
{
  const vd inf = splat(INFINITY);
  vd cd = splat((double)(R->ifirst + (long)col)), by2 = splat(R->by2[q / 3]), bz2 = splat(R->bz2[q % 3]);
  vl own[NL_CELL_U];
  int any = 0;
  for (int u = 0; u < NL_CELL_U; u++) {
    vd bx2 = sel(cl[u] == cd, splat(0.0), sel(cl[u] == cd + 1.0, lo2[u], sel(cl[u] == cd - 1.0, hi2[u], inf)));
    own[u] = (bx2 + by2) + bz2 < s[u].d[n - 1];
    any |= v_any(own[u]);
  }
  if (!any) return;
  size_t c = 9 * col + (size_t)q;
  for (size_t p = R->start[c]; p < R->start[c + 1]; p++) {
    vd px = splat(R->px[p]), ay2 = splat(R->ay2[p]), az2 = splat(R->az2[p]);
    for (int u = 0; u < NL_CELL_U; u++) {
      vd ax = px - x[u];
      net(&s[u], sel(own[u], (ax * ax + ay2) + az2, inf));
    }
  }
}

void NL_CELL_ROW(const nl_cellular_rowpts *R, double x0, double dx, size_t count, int n, double *out)
{
  const double fmax2 = NL_CELLULAR_FMAX * NL_CELLULAR_FMAX;
  enum { G = NL_CELL_U * NL_CELL_W };
  for (size_t s0 = 0; s0 < count; s0 += G) {
    size_t m = count - s0 < G ? count - s0 : G;
    vd x[NL_CELL_U], cl[NL_CELL_U], lo2[NL_CELL_U], hi2[NL_CELL_U];
    dset s[NL_CELL_U];
    for (int u = 0; u < NL_CELL_U; u++) {
      vd kv;   /* the tail repeats the last sample */
      for (int l = 0; l < NL_CELL_W; l++) {
        size_t k = (size_t)(u * NL_CELL_W + l);
        kv[l] = (double)(s0 + (k < m ? k : m - 1));
      }
      x[u] = splat(x0) + kv * splat(dx);   /* the scalar x0 + (double)s * dx */
      cl[u] = v_floor(x[u]);
      vd lo = x[u] - cl[u], hi = (cl[u] + 1.0) - x[u];
      lo2[u] = lo * lo;
      hi2[u] = hi * hi;
      for (int q = 0; q < 4; q++) s[u].d[q] = splat(INFINITY);
    }
    /* x is monotone in s: the lanes' columns span cmin .. cmax */
    double cf = cl[0][0], cm = cl[(m - 1) / NL_CELL_W][(m - 1) % NL_CELL_W];
    size_t c0 = (size_t)((long)(cf < cm ? cf : cm) - R->ifirst), c1 = (size_t)((long)(cf < cm ? cm : cf) - R->ifirst);
    /* the 27 cubes around column c0 in visit order (near side of the first
     * lane), then the columns c0 + 2 .. c1 + 1 of lanes further on */
    double lo0 = x[0][0] - cl[0][0], hi0 = (cl[0][0] + 1.0) - x[0][0];
    int near_lo = lo0 <= hi0;
    for (int t = 0; t < 27; t++) {
      int cx = nl_cellular_visit[t] / 9, q = nl_cellular_visit[t] % 9;
      size_t col = cx == 0 ? c0 : (cx == 1) == near_lo ? c0 - 1 : c0 + 1;
      cube(R, col, q, x, cl, lo2, hi2, n, s);
    }
    for (size_t col = c0 + 2; col <= c1 + 1; col++)
      for (int q = 0; q < 9; q++) cube(R, col, q, x, cl, lo2, hi2, n, s);
    double F[NL_CELL_U][4][NL_CELL_W];
    for (int u = 0; u < NL_CELL_U; u++)
      for (int q = 0; q < n; q++) {
        vd d = s[u].d[q];
        vl in = d < splat(fmax2);
        vd f = sel(in, v_sqrt(sel(in, d, splat(0.0))), splat(NL_CELLULAR_FMAX));
        memcpy(F[u][q], &f, sizeof f);
      }
    for (size_t k = 0; k < m; k++)
      for (int q = 0; q < n; q++) out[(s0 + k) * (size_t)n + (size_t)q] = F[k / NL_CELL_W][q][k % NL_CELL_W];
  }
}
