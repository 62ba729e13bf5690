/* nl_cluster.c - hierarchical clustering: MST single linkage, NN-chain
 * complete/average/Ward linkage, flat clusters. Follows scipy 1.10's
 * scipy/cluster/_hierarchy.pyx (mst_single_linkage, nn_chain, label,
 * cluster_monocrit) so that outputs can be compared row by row. */
#include "stats/nl_cluster.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

static const char *method_names[] = {"single", "complete", "average", "ward", "weighted",
                                     "centroid", "median"};
static const char *metric_names[] = {"euclidean", "sqeuclidean", "cityblock", "chebyshev",
                                     "cosine", "correlation", "canberra", "braycurtis"};

nl_status nl_cluster_linkage_method_parse(const char *name, nl_cluster_linkage_method *m, nl_error *err)
{
  for (int i = 0; i < 7; i++)
    if (strcmp(name, method_names[i]) == 0) { *m = (nl_cluster_linkage_method)i; return NL_OK; }
  return nl_fail(err, NL_EINVAL, "unknown linkage '%s' (single, complete, average, weighted, "
                 "ward, centroid or median)", name);
}

const char *nl_cluster_linkage_method_name(nl_cluster_linkage_method m) { return method_names[m]; }

nl_status nl_cluster_metric_parse(const char *name, nl_cluster_metric *m, nl_error *err)
{
  for (int i = 0; i < 8; i++)
    if (strcmp(name, metric_names[i]) == 0) { *m = (nl_cluster_metric)i; return NL_OK; }
  return nl_fail(err, NL_EINVAL, "unknown metric '%s' (euclidean, sqeuclidean, cityblock, "
                 "chebyshev, cosine, correlation, canberra or braycurtis)", name);
}

const char *nl_cluster_metric_name(nl_cluster_metric m) { return metric_names[m]; }

/* 8 lanes as two 4-wide vectors; GCC emits SSE2 pairs or, in the AVX2 clone,
 * 256-bit ops. The summation order is the same in both. */
typedef double v4d __attribute__((vector_size(32)));
/* The AVX2 clone exists on x86 only; elsewhere (aarch64: NEON pairs) the one
 * generic version, with the same lane-wise operations and so the same bits. */
#if defined(__x86_64__) || defined(__i386__)
#define AVX2_CLONE __attribute__((target_clones("avx2", "default")))
#else
#define AVX2_CLONE
#endif

/* sum_j (a_j - b_j)^2, or sum_j a_j^2 when b is NULL. */
AVX2_CLONE
static double sq_diff_sum(const double *a, const double *b, size_t d)
{
  static const v4d zero = {0, 0, 0, 0};
  v4d s0 = zero, s1 = zero;
  size_t j = 0;
  for (; j + 8 <= d; j += 8) {
    v4d a0, a1, b0 = zero, b1 = zero;
    memcpy(&a0, a + j, 32); memcpy(&a1, a + j + 4, 32);
    if (b) { memcpy(&b0, b + j, 32); memcpy(&b1, b + j + 4, 32); }
    v4d t0 = a0 - b0, t1 = a1 - b1;
    s0 += t0 * t0;
    s1 += t1 * t1;
  }
  v4d s = s0 + s1;
  double r = (s[0] + s[1]) + (s[2] + s[3]);
  for (; j < d; j++) {
    double t = a[j] - (b ? b[j] : 0.0);
    r += t * t;
  }
  return r;
}

/* Four pairs (a, b[0..3]) at once: each lane group is sq_diff_sum's own
 * sequence of operations on its pair (same blocks, same sums, same tail), so
 * every result has sq_diff_sum's bits; a is loaded once for four b's and the
 * four addition chains overlap instead of one waiting on its own latency. */
AVX2_CLONE
static void sq_diff_sum4(const double *a, const double *const b[4], size_t d, double r[4])
{
  static const v4d zero = {0, 0, 0, 0};
  v4d s0[4] = {zero, zero, zero, zero}, s1[4] = {zero, zero, zero, zero};
  size_t j = 0;
  for (; j + 8 <= d; j += 8) {
    v4d a0, a1;
    memcpy(&a0, a + j, 32); memcpy(&a1, a + j + 4, 32);
    for (int q = 0; q < 4; q++) {
      v4d b0, b1;
      memcpy(&b0, b[q] + j, 32); memcpy(&b1, b[q] + j + 4, 32);
      v4d t0 = a0 - b0, t1 = a1 - b1;
      s0[q] += t0 * t0;
      s1[q] += t1 * t1;
    }
  }
  for (int q = 0; q < 4; q++) {
    v4d s = s0[q] + s1[q];
    r[q] = (s[0] + s[1]) + (s[2] + s[3]);
  }
  for (; j < d; j++)
    for (int q = 0; q < 4; q++) {
      double t = a[j] - b[q][j];
      r[q] += t * t;
    }
}

double nl_cluster_euclidean(const double *a, const double *b, size_t d)
{
  return sqrt(sq_diff_sum(a, b, d));
}

double nl_cluster_sumsq(const double *a, size_t d)
{
  return sq_diff_sum(a, NULL, d);
}

/* ---- turning merges into scipy's format ----------------------------------- */

typedef struct { double dist; size_t order; } merge_key;

/* The metrics other than Euclidean, as scipy.spatial.distance.pdist
 * computes them (scipy/spatial/src/distance_impl.h and distance_metrics.h):
 * sums in index order; cosine and correlation clip the cosine to [-1, 1];
 * canberra counts a 0/0 term as 0. Cosine and correlation take the rows
 * prepare_rows made (centred for correlation, scaled by a power of two). */
static double metric_dist(nl_cluster_metric m, const double *a, const double *b, size_t d)
{
  double s = 0.0, t = 0.0, u = 0.0;
  switch (m) {
  case NL_METRIC_EUCLIDEAN: return nl_cluster_euclidean(a, b, d);
  case NL_METRIC_SQEUCLIDEAN: return sq_diff_sum(a, b, d);
  case NL_METRIC_CITYBLOCK:
    for (size_t j = 0; j < d; j++) s += fabs(a[j] - b[j]);
    return s;
  case NL_METRIC_CHEBYSHEV:
    for (size_t j = 0; j < d; j++) s = fmax(s, fabs(a[j] - b[j]));
    return s;
  case NL_METRIC_CANBERRA:
    for (size_t j = 0; j < d; j++) {
      double den = fabs(a[j]) + fabs(b[j]);
      if (den > 0.0) s += fabs(a[j] - b[j]) / den;
    }
    return s;
  case NL_METRIC_BRAYCURTIS:
    for (size_t j = 0; j < d; j++) {
      s += fabs(a[j] - b[j]);
      t += fabs(a[j] + b[j]);
    }
    return s / t;   /* t = 0 only for b = -a: refused before (check_ratio_metric) */
  case NL_METRIC_COSINE:
  case NL_METRIC_CORRELATION: {
    for (size_t j = 0; j < d; j++) {
      s += a[j] * b[j];
      t += a[j] * a[j];
      u += b[j] * b[j];
    }
    double c = s / (sqrt(t) * sqrt(u));
    if (fabs(c) > 1.0) c = copysign(1.0, c);
    return 1.0 - c;
  }
  }
  return NAN;
}

/* numpy's pairwise sum of n doubles (numpy/core/src/umath/loops_utils.h,
 * pairwise_sum_DOUBLE): what X.mean(axis=1) adds in scipy's correlation, so
 * that the centred rows have scipy's bits. */
static double numpy_sum(const double *a, size_t n)
{
  if (n < 8) {
    double r = 0.0;
    for (size_t i = 0; i < n; i++) r += a[i];
    return r;
  }
  if (n <= 128) {
    double r[8];
    size_t i;
    for (int k = 0; k < 8; k++) r[k] = a[k];
    for (i = 8; i < n - n % 8; i += 8)
      for (int k = 0; k < 8; k++) r[k] += a[i + (size_t)k];
    double res = ((r[0] + r[1]) + (r[2] + r[3])) + ((r[4] + r[5]) + (r[6] + r[7]));
    for (; i < n; i++) res += a[i];
    return res;
  }
  size_t n2 = n / 2;
  n2 -= n2 % 8;
  return numpy_sum(a, n2) + numpy_sum(a + n2, n - n2);
}

/* Below this span (about 2e-121) the squares of the smaller distances
 * between the points fall under DBL_MIN and lose digits, and below about
 * 1e-154 underflow to 0 (scipy's heights are then all 0). */
enum { TINY_SPAN_EXP = -400 };

/* The points as the metric works on them, or NULL when that is x itself.
 * Cosine and correlation: the rows (correlation's centred on their mean,
 * scipy's X - X.mean(axis=1)), each scaled by the power of two that brings
 * its largest magnitude into [0.5, 1). Cosine is the same for any positive
 * scale of either row, and a power of two scales every product, sum and
 * square root exactly, so the distances have scipy's bits wherever scipy's
 * squares neither underflow nor overflow; where they would (coordinates
 * below about 1e-154: scipy gives 0/0, or 1 - 1 = 0 for every pair) they
 * stay the rows' cosine distance. A zero row stays zero: its distances are
 * 0/0, refused before (check_ratio_metric).
 * Euclidean and sqeuclidean: when the points span less than 2^TINY_SPAN_EXP,
 * all of them scaled by one power of two 2^-e that brings the span into
 * [0.5, 1); *shift = e (2e for sqeuclidean's squares) is what the heights
 * are scaled back by (unscale_heights), exactly as well. */
static double *prepare_rows(const double *x, size_t n, size_t d, nl_cluster_metric metric, double span,
                            int *shift)
{
  *shift = 0;
  if (metric == NL_METRIC_EUCLIDEAN || metric == NL_METRIC_SQEUCLIDEAN) {
    int e = 0;
    if (!(span > 0.0)) return NULL;
    frexp(span, &e);
    if (e >= TINY_SPAN_EXP) return NULL;
    double *y = nl_xmalloc(n * d * sizeof *y);
    for (size_t i = 0; i < n * d; i++) y[i] = ldexp(x[i], -e);
    *shift = metric == NL_METRIC_SQEUCLIDEAN ? 2 * e : e;
    return y;
  }
  if (metric != NL_METRIC_COSINE && metric != NL_METRIC_CORRELATION) return NULL;
  double *y = nl_xmalloc(n * d * sizeof *y);
  for (size_t i = 0; i < n; i++) {
    const double *a = x + i * d;
    double *r = y + i * d, mean = 0.0, big = 0.0;
    if (metric == NL_METRIC_CORRELATION) mean = numpy_sum(a, d) / (double)d;
    for (size_t j = 0; j < d; j++) {
      r[j] = a[j] - mean;
      big = fmax(big, fabs(r[j]));
    }
    int e = 0;
    if (big > 0.0) frexp(big, &e);
    for (size_t j = 0; j < d; j++) r[j] = ldexp(r[j], -e);
  }
  return y;
}

static void unscale_heights(double *Z, size_t n, int shift)
{
  if (shift)
    for (size_t i = 0; i + 1 < n; i++) Z[4 * i + 2] = ldexp(Z[4 * i + 2], shift);
}

/* The pairs whose cosine, correlation or Bray-Curtis distance is 0/0 or
 * x/0, which scipy's linkage refuses ("The condensed distance matrix must
 * contain only finite values"): a zero row (cosine), a constant row
 * (correlation: its centred row is zero; also when rounding leaves the mean
 * a few ulp off and scipy returns a distance made of that rounding error),
 * and a row that is the negative of another (Bray-Curtis: sum |u + v| = 0;
 * a zero row alone is at distance 1 from every nonzero one). The first such
 * pair in pdist's order is named. */
static nl_status check_ratio_metric(const double *x, size_t n, size_t d, nl_cluster_metric metric,
                                    nl_error *err)
{
  const char *name = metric_names[metric];
  if (metric == NL_METRIC_COSINE || metric == NL_METRIC_CORRELATION) {
    for (size_t i = 0; i < n; i++) {
      const double *a = x + i * d;
      size_t j = 1;
      if (metric == NL_METRIC_COSINE) while (j <= d && a[j - 1] == 0.0) j++;
      else while (j < d && a[j] == a[0]) j++;
      if (j <= d && (metric == NL_METRIC_COSINE || j < d)) continue;
      size_t p = i ? 0 : 1, q = i;   /* the first pair holding row i */
      return nl_fail(err, NL_EINVAL, "points %zu and %zu: the %s distance is 0/0 (point %zu is %s); "
                     "scipy's linkage refuses it too", (p < q ? p : q) + 1, (p < q ? q : p) + 1, name,
                     i + 1, metric == NL_METRIC_COSINE ? "zero" : "constant");
    }
  } else if (metric == NL_METRIC_BRAYCURTIS) {
    for (size_t i = 0; i + 1 < n; i++)
      for (size_t j = i + 1; j < n; j++) {
        size_t k = 0;
        while (k < d && x[i * d + k] == -x[j * d + k]) k++;
        if (k < d) continue;
        int zero = 1;
        for (k = 0; k < d; k++) zero &= x[i * d + k] == 0.0;
        return nl_fail(err, NL_EINVAL, "points %zu and %zu: the braycurtis distance is %s "
                       "(sum |u + v| = 0: %s); scipy's linkage refuses it too", i + 1, j + 1,
                       zero ? "0/0" : "x/0", zero ? "both are zero" : "one is the negative of the other");
      }
  }
  return NL_OK;
}

/* A distance that is not finite though the checks above passed: refused
 * rather than handed to a linkage whose comparisons assume an order. */
static nl_status not_finite(nl_cluster_metric metric, size_t i, size_t j, double v, nl_error *err)
{
  if (i > j) { size_t t = i; i = j; j = t; }
  return nl_fail(err, NL_EINVAL, "points %zu and %zu: the %s distance is %g, not finite", i + 1, j + 1,
                 metric_names[metric], v);
}

static int cmp_key(const void *pa, const void *pb)
{
  const merge_key *a = pa, *b = pb;
  if (a->dist != b->dist) return a->dist < b->dist ? -1 : 1;
  return a->order < b->order ? -1 : a->order > b->order;   /* stable */
}

/* Sorts the merges by height (stably, like numpy's mergesort) and relabels
 * them with a union-find: each merge joins the current roots of its two
 * points, the smaller id first, and creates cluster n + row (scipy's label). */
static void sort_and_label(double *Z, size_t n)
{
  size_t m = n - 1;
  merge_key *k = nl_xmalloc(m * sizeof *k);
  double *tmp = nl_xmalloc(m * 4 * sizeof(double));
  for (size_t i = 0; i < m; i++) { k[i].dist = Z[4 * i + 2]; k[i].order = i; }
  qsort(k, m, sizeof *k, cmp_key);
  for (size_t i = 0; i < m; i++) memcpy(tmp + 4 * i, Z + 4 * k[i].order, 4 * sizeof(double));
  size_t *parent = nl_xmalloc((2 * n - 1) * sizeof(size_t));
  double *size = nl_xmalloc((2 * n - 1) * sizeof(double));
  for (size_t i = 0; i < 2 * n - 1; i++) { parent[i] = i; size[i] = 1.0; }
  for (size_t i = 0; i < m; i++) {
    size_t r[2];
    for (int s = 0; s < 2; s++) {
      size_t x = (size_t)tmp[4 * i + s];
      while (parent[x] != x) x = parent[x] = parent[parent[x]];   /* path halving */
      r[s] = x;
    }
    size_t a = r[0] < r[1] ? r[0] : r[1], b = r[0] < r[1] ? r[1] : r[0];
    parent[a] = parent[b] = n + i;
    size[n + i] = size[a] + size[b];
    Z[4 * i] = (double)a;
    Z[4 * i + 1] = (double)b;
    Z[4 * i + 2] = tmp[4 * i + 2];
    Z[4 * i + 3] = size[n + i];
  }
  free(parent); free(size); free(tmp); free(k);
}

/* ---- single linkage: Prim's MST -------------------------------------------- */

static nl_status linkage_single(const double *x, size_t n, size_t d, nl_cluster_metric metric,
                                double *Z, nl_error *err)
{
  double *dmin = nl_xmalloc(n * sizeof(double));
  unsigned char *merged = nl_xcalloc(n, 1);
  for (size_t i = 0; i < n; i++) dmin[i] = INFINITY;
  size_t cur = 0;
  for (size_t k = 0; k + 1 < n; k++) {
    merged[cur] = 1;
    double best = INFINITY;
    size_t y = cur;
    for (size_t i = 0; i < n; i++) {
      if (merged[i]) continue;
      double dist = metric_dist(metric, x + cur * d, x + i * d, d);
      if (!isfinite(dist)) {
        free(dmin);
        free(merged);
        return not_finite(metric, cur, i, dist, err);
      }
      if (dist < dmin[i]) dmin[i] = dist;
      if (dmin[i] < best || y == cur) { best = dmin[i]; y = i; }
    }
    Z[4 * k] = (double)cur;
    Z[4 * k + 1] = (double)y;
    Z[4 * k + 2] = best;
    cur = y;
  }
  free(dmin);
  free(merged);
  return NL_OK;
}

/* ---- complete / average / ward: nearest-neighbour chain ----------------------------- */

/* Row i < j of the condensed matrix, as scipy.spatial.distance.pdist stores it. */
static inline size_t cidx(size_t n, size_t i, size_t j)
{
  if (i > j) { size_t t = i; i = j; j = t; }
  return n * i - i * (i + 1) / 2 + (j - i - 1);
}

/* Tiles of CD_TILE_I x CD_TILE_J points: the j tile (CD_TILE_J d doubles,
 * 160 KB at d = 81) stays in cache while the i tile's rows run over it,
 * instead of every row i streaming all of x from memory (6.5 MB at
 * 10,000 x 81, n/2 times). Each distance is the same sq_diff_sum of the
 * same pair (four pairs at a time, sq_diff_sum4), so D has the same bits as
 * row by row. */
enum { CD_TILE_I = 64, CD_TILE_J = 256 };

/* The condensed matrix on 2 MB pages where the kernel grants them
 * (transparent huge pages in "madvise" mode): the column scans below touch
 * one 4 KB page per element (rows are up to n doubles apart), so with small
 * pages nearly every strided read is a TLB miss, and filling 400 MB takes
 * 100,000 page faults instead of 200. Without THP this is plain memory. */
enum { HUGE_PAGE = 2u << 20 };

static double *condensed_alloc(size_t m)
{
  size_t bytes = m * sizeof(double);
  void *p = NULL;
  if (bytes < HUGE_PAGE) return malloc(bytes);
  bytes = (bytes + HUGE_PAGE - 1) / HUGE_PAGE * HUGE_PAGE;
  if (posix_memalign(&p, HUGE_PAGE, bytes) != 0) return NULL;
#ifdef MADV_HUGEPAGE
  madvise(p, bytes, MADV_HUGEPAGE);   /* advice only: failure leaves small pages */
#endif
  return p;
}

/* The few smallest entries of each column's strided part {D(i, x): i < x
 * active}, in increasing (value, row) order, so that the chain's
 * nearest-neighbour search reads row x (contiguous) and the head of a short
 * list instead of a strided column. Invariant: the cnt listed entries are
 * the column's cnt smallest, every unlisted active entry is above the last
 * listed, and full says nothing is unlisted. A merge drops rows from a
 * column and offers it the merged cluster's new entry (linkage_nn_chain);
 * only a list emptied while not full has lost its minimum and is rescanned
 * when next asked for. Rows are stored as uint32_t: n is far below 2^32
 * wherever n(n-1)/2 doubles fit in memory. */
enum { COL_K = 4 };

typedef struct { double v[COL_K]; uint32_t i[COL_K]; uint8_t cnt, full; } col_top;

static inline int lex_less(double a, size_t ia, double b, size_t ib)
{
  return a < b || (a == b && ia < ib);
}

/* Column c gains the entry (v, row id). */
static inline void col_offer(col_top *c, double v, size_t id)
{
  int k = c->cnt;
  if (k == 0 && !c->full) return;                  /* stale: nothing known to compare with */
  if (k > 0 && !lex_less(v, id, c->v[k - 1], c->i[k - 1])) {
    if (!c->full) return;                          /* stays unlisted, above the list */
    if (k == COL_K) { c->full = 0; return; }       /* the list is full up: it drops off */
    c->v[k] = v; c->i[k] = (uint32_t)id; c->cnt++;
    return;
  }
  if (k == COL_K) { k--; c->full = 0; }            /* the last listed drops off */
  else c->cnt++;
  for (; k > 0 && lex_less(v, id, c->v[k - 1], c->i[k - 1]); k--) { c->v[k] = c->v[k - 1]; c->i[k] = c->i[k - 1]; }
  c->v[k] = v;
  c->i[k] = (uint32_t)id;
}

/* Column c loses row id (no-op if it is not listed). */
static inline void col_drop(col_top *c, size_t id)
{
  for (int k = 0; k < c->cnt; k++)
    if (c->i[k] == id) {
      for (; k + 1 < c->cnt; k++) { c->v[k] = c->v[k + 1]; c->i[k] = c->i[k + 1]; }
      c->cnt--;
      return;
    }
}

/* The column lists are filled while D is: for a fixed column j the rows i
 * arrive in increasing order (i tiles outermost, i increasing inside a
 * tile), as a scan would offer them. */
static double *condensed_distances(const double *x, size_t n, size_t d, col_top *cm)
{
  size_t m = n * (n - 1) / 2;
  double *D = condensed_alloc(m);
  if (!D) return NULL;
  for (size_t j = 0; j < n; j++) { cm[j].cnt = 0; cm[j].full = 1; }
  for (size_t i0 = 0; i0 + 1 < n; i0 += CD_TILE_I) {
    size_t i1 = i0 + CD_TILE_I < n ? i0 + CD_TILE_I : n;
    for (size_t j0 = i0 + 1; j0 < n; j0 += CD_TILE_J) {
      size_t j1 = j0 + CD_TILE_J < n ? j0 + CD_TILE_J : n;
      for (size_t i = i0; i < i1 && i + 1 < j1; i++) {
        size_t j = j0 > i + 1 ? j0 : i + 1;
        double *out = D + cidx(n, i, j);
        for (; j + 4 <= j1; j += 4, out += 4) {
          const double *b[4] = {x + j * d, x + (j + 1) * d, x + (j + 2) * d, x + (j + 3) * d};
          sq_diff_sum4(x + i * d, b, d, out);
          for (int q = 0; q < 4; q++) {
            out[q] = sqrt(out[q]);
            col_offer(&cm[j + q], out[q], i);
          }
        }
        for (; j < j1; j++, out++) {
          *out = nl_cluster_euclidean(x + i * d, x + j * d, d);
          col_offer(&cm[j], *out, i);
        }
      }
    }
  }
  return D;
}

/* The active clusters as a list in increasing index order (succ; the end is
 * n, the head succ[n]): the scans below visit only active clusters, in the
 * order the plain loops over 0..n-1 did, so ties resolve the same way
 * (Muellner's fastcluster keeps the same list). */
typedef struct { size_t *succ, *pred; } active_list;

static void active_remove(active_list *a, size_t n, size_t i)
{
  size_t p = a->pred[i], s = a->succ[i];
  a->succ[p] = s;
  if (s < n) a->pred[s] = p;
}

/* How far ahead (in list nodes) the strided scans prefetch: the entries
 * (i, x), i < x, of the condensed matrix lie n - i - 1 doubles apart, a
 * stride the hardware prefetcher does not follow, so each would be a miss. */
enum { NN_AHEAD = 12 };

static inline size_t advance(const size_t *succ, size_t n, size_t i, int k)
{
  while (k-- > 0 && i < n) i = succ[i];
  return i;
}

/* Column x's list made anew from its strided entries, rows in increasing
 * order, prefetched NN_AHEAD list nodes ahead (the hardware prefetcher does
 * not follow a stride of n - i doubles). */
static void col_rescan(const double *D, size_t n, const active_list *a, col_top *c, size_t x)
{
  const size_t *succ = a->succ;
  size_t i = succ[n], ahead = advance(succ, n, i, NN_AHEAD);
  c->cnt = 0;
  c->full = 1;
  for (; i < x; i = succ[i]) {
    if (ahead < x) { __builtin_prefetch(D + cidx(n, ahead, x)); ahead = succ[ahead]; }
    col_offer(c, D[cidx(n, i, x)], i);
  }
}

/* The nearest active neighbour of x; prefers prev (the element before x on
 * the chain) on ties, which is what keeps the chain from cycling. The scan
 * order is increasing index with strict <: prev, else the first index at
 * the minimum; the column's cached (value, first row) gives the same. */
static size_t nearest(const double *D, size_t n, const active_list *a, col_top *cm, size_t x, size_t prev,
                      double *dmin)
{
  const size_t *succ = a->succ;
  double best = prev < n ? D[cidx(n, x, prev)] : INFINITY;
  size_t y = prev;
  col_top *c = &cm[x];
  if (c->cnt == 0 && !c->full) col_rescan(D, n, a, c, x);
  if (c->cnt > 0 && c->v[0] < best) { best = c->v[0]; y = c->i[0]; }
  size_t i = succ[x];
  const double *row = D + (x + 1 < n ? cidx(n, x, x + 1) : 0) - (x + 1);   /* row[i], i > x */
  for (; i < n; i = succ[i])         /* row x: contiguous */
    if (row[i] < best) { best = row[i]; y = i; }
  *dmin = best;
  return y;
}

static void linkage_nn_chain(double *D, size_t n, nl_cluster_linkage_method method, col_top *cm, double *Z)
{
  double *size = nl_xmalloc(n * sizeof(double));
  size_t *chain = nl_xmalloc(n * sizeof(size_t)), len = 0;
  active_list act = {nl_xmalloc((n + 1) * sizeof(size_t)), nl_xmalloc((n + 1) * sizeof(size_t))};
  for (size_t i = 0; i < n; i++) { size[i] = 1.0; act.succ[i] = i + 1; act.pred[i] = i ? i - 1 : n; }
  act.succ[n] = 0;
  for (size_t k = 0; k + 1 < n; k++) {
    if (len == 0) chain[len++] = act.succ[n];   /* the first active cluster */
    size_t x, y;
    double dmin;
    for (;;) {
      x = chain[len - 1];
      size_t prev = len > 1 ? chain[len - 2] : n;
      y = nearest(D, n, &act, cm, x, prev, &dmin);
      if (len > 1 && y == prev) break;
      chain[len++] = y;
    }
    len -= 2;
    if (x > y) { size_t t = x; x = y; y = t; }
    double nx = size[x], ny = size[y];
    Z[4 * k] = (double)x;
    Z[4 * k + 1] = (double)y;
    Z[4 * k + 2] = dmin;
    size[x] = 0.0;            /* x is dropped, y becomes the merged cluster */
    size[y] = nx + ny;
    active_remove(&act, n, x);
    /* The column lists after the merge: y's column is rewritten below (its
     * list made on the way, rows in increasing order); column i in (x, y)
     * lost row x; column i > y lost row x and has a new entry in row y. */
    col_top ycol = {.cnt = 0, .full = 1};
    size_t ahead = advance(act.succ, n, act.succ[n], NN_AHEAD);
    for (size_t i = act.succ[n]; i < n; i = act.succ[i]) {
      if (ahead < y) {         /* (ahead, y) and, below x, (ahead, x): strided */
        __builtin_prefetch(D + cidx(n, ahead, y), 1);
        if (ahead < x) __builtin_prefetch(D + cidx(n, ahead, x));
      }
      if (ahead < n) ahead = act.succ[ahead];
      if (i == y) continue;
      double dx = D[cidx(n, i, x)], dy = D[cidx(n, i, y)];
      double v;
      /* complete: max(dx, dy) (no NaN: every distance was checked finite) */
      if (method == NL_LINKAGE_COMPLETE) v = dx > dy ? dx : dy;
      else if (method == NL_LINKAGE_AVERAGE) v = (nx * dx + ny * dy) / (nx + ny);
      else if (method == NL_LINKAGE_WEIGHTED) v = 0.5 * (dx + dy);   /* WPGMA, scipy's _weighted */
      else {
        /* Ward (Lance-Williams on Euclidean distances), in scipy's
         * _hierarchy_distance_update.pxi _ward expression and order. */
        double ni = size[i], t = 1.0 / (nx + ny + ni);
        v = sqrt((ni + nx) * t * dx * dx + (ni + ny) * t * dy * dy - ni * t * dmin * dmin);
      }
      D[cidx(n, i, y)] = v;
      if (i < y) {
        col_offer(&ycol, v, i);
        if (i > x) col_drop(&cm[i], x);
      } else {
        col_drop(&cm[i], x);
        col_drop(&cm[i], y);
        col_offer(&cm[i], v, y);
      }
    }
    cm[y] = ycol;
  }
  free(size);
  free(chain);
  free(act.succ);
  free(act.pred);
}

/* ---- the chain on a square matrix with new clusters in new columns ---------
 * The condensed layout above keeps row x's entries (x, i > x) together but
 * spreads its column (i < x, x) one row apart: every merge reads two columns
 * and writes one, a cache (and TLB) miss an entry once the matrix outgrows
 * the caches, which made the chain's cost per n^2 grow with n (13.5 ns at
 * n = 1,000, 37 ns at 20,000 on a Zen 4). Here every cluster has a whole
 * row, so a merge reads rows x and y and writes the new cluster's row, all
 * contiguous; the new cluster takes a new column slot (slots are handed out
 * in increasing order, starting at a multiple of 8), and its column is
 * written into the other rows only once 8 new slots are out, as one cache
 * line a row (sq_flush). Until then an entry of a new column is read from
 * the new cluster's own row: D(a, b) is row[max(a, b)][min(a, b)] whenever
 * max(a, b) is at or past the flushed watermark F (sq_get). When the slots
 * run out, the active rows and columns are packed to the front (sq_compact).
 * Memory: n rows of C = n + n/4 (rounded) doubles: 1 GB at n = 10,000,
 * 2.5 times the condensed matrix; where that does not fit, the condensed
 * chain above runs (nl_cluster_linkage_metric).
 *
 * The merges are scipy's nn_chain's, ties included: scipy scans clusters in
 * index order with strict <, preferring the chain's previous element, and a
 * merged cluster keeps the larger of its two indices. Slots are not in that
 * order, so each slot carries its scipy index (pos), and the nearest
 * neighbour is the smallest (distance, pos), or prev when its distance equals
 * that minimum: the element scipy's scan ends on. Z records the scipy
 * indices, which sort_and_label relabels as before. */
enum { SQ_BATCH = 8 };   /* doubles in a cache line */

typedef struct {
  size_t C, F, next, m;   /* columns a row; flushed watermark; next free slot; active count */
  double **row;           /* row[s]: slot s's distances, by slot */
  uint32_t *pos, *act;    /* scipy's index of slot s; the active slots, increasing */
  double *size;
} sq_chain;

static inline size_t round_up8(size_t v) { return (v + SQ_BATCH - 1) / SQ_BATCH * SQ_BATCH; }

/* Columns a row needs for n points: the points, then room for new slots. */
static size_t sq_columns(size_t n)
{
  size_t extra = n / 4 > 2 * SQ_BATCH ? n / 4 : 2 * SQ_BATCH;
  return round_up8(n) + round_up8(extra);
}

static inline double sq_get(const sq_chain *q, size_t a, size_t b)
{
  size_t hi = a > b ? a : b, lo = a > b ? b : a;
  return hi >= q->F ? q->row[hi][lo] : q->row[a][b];
}

/* The square matrix for n points, uninitialised, rows on cache lines; NULL
 * if it cannot be had. On plain pages: its reads go along rows, where 4 KB
 * pages cost a TLB miss per 512 doubles, and asking for 2 MB pages
 * (MADV_HUGEPAGE) made the kernel compact memory to find them when it was
 * fragmented (measured: 0.45-0.7 GB/s of first touch then, against 3.4 on
 * 4 KB pages). */
static double *sq_alloc(size_t n)
{
  double need = (double)n * (double)sq_columns(n) * sizeof(double);
  if (!nl_mem_fits(need)) return NULL;
  return aligned_alloc(64, n * sq_columns(n) * sizeof(double));   /* C is a multiple of 8 */
}

/* Euclidean distances into the square matrix M (n rows of C), by the tiles
 * and the sq_diff_sum4 groups of condensed_distances, so every entry has
 * the bits of the condensed matrix's; (j, i) is written beside (i, j): within
 * a tile, 64 consecutive i of one row j. */
static void sq_distances(const double *x, size_t n, size_t d, double *M, size_t C)
{
  for (size_t i = 0; i < n; i++) M[i * C + i] = INFINITY;
  for (size_t i0 = 0; i0 + 1 < n; i0 += CD_TILE_I) {
    size_t i1 = i0 + CD_TILE_I < n ? i0 + CD_TILE_I : n;
    for (size_t j0 = i0 + 1; j0 < n; j0 += CD_TILE_J) {
      size_t j1 = j0 + CD_TILE_J < n ? j0 + CD_TILE_J : n;
      for (size_t i = i0; i < i1 && i + 1 < j1; i++) {
        size_t j = j0 > i + 1 ? j0 : i + 1;
        double *out = M + i * C + j;
        for (; j + 4 <= j1; j += 4, out += 4) {
          const double *b[4] = {x + j * d, x + (j + 1) * d, x + (j + 2) * d, x + (j + 3) * d};
          sq_diff_sum4(x + i * d, b, d, out);
          for (int k = 0; k < 4; k++) {
            out[k] = sqrt(out[k]);
            M[(j + k) * C + i] = out[k];
          }
        }
        for (; j < j1; j++, out++) {
          *out = nl_cluster_euclidean(x + i * d, x + j * d, d);
          M[j * C + i] = *out;
        }
      }
    }
  }
}

/* The square matrix from a condensed one, eight rows of it at a time so
 * that the mirrored entries (j, i0..i0+7) are one cache line. */
static void sq_from_condensed(const double *D, size_t n, double *M, size_t C)
{
  for (size_t i = 0; i < n; i++) M[i * C + i] = INFINITY;
  for (size_t i0 = 0; i0 < n; i0 += SQ_BATCH) {
    size_t i1 = i0 + SQ_BATCH < n ? i0 + SQ_BATCH : n;
    for (size_t i = i0; i < i1; i++)   /* the pairs inside the block of rows */
      for (size_t j = i + 1; j < i1; j++) M[i * C + j] = M[j * C + i] = D[cidx(n, i, j)];
    for (size_t j = i1; j < n; j++)
      for (size_t i = i0; i < i1; i++) M[i * C + j] = M[j * C + i] = D[cidx(n, i, j)];
  }
}

/* Writes the columns of the new slots [F, next) into every active row that
 * lacks them (rows made before the slot), and moves F to next. */
static void sq_flush(sq_chain *q)
{
  size_t F = q->F;
  for (size_t t = 0; t < q->m; t++) {
    size_t i = q->act[t];
    double *ri = q->row[i];
    for (size_t s = i >= F ? i + 1 : F; s < q->next; s++) ri[s] = q->row[s][i];   /* dead s: unread */
  }
  q->F = q->next;
}

/* Packs the active slots to 0..m-1 (in their order), rows and columns alike,
 * after a flush; chain[0..len) is renumbered with them. */
static void sq_compact(sq_chain *q, size_t *chain, size_t len)
{
  uint32_t *map = nl_xmalloc(q->C * sizeof *map);
  for (size_t t = 0; t < q->m; t++) map[q->act[t]] = (uint32_t)t;
  for (size_t t = 0; t < q->m; t++) {
    size_t old = q->act[t];
    double *r = q->row[old];
    for (size_t u = 0; u < q->m; u++) r[u] = r[q->act[u]];   /* act[u] >= u: forward is safe */
    q->row[t] = r;
    q->pos[t] = q->pos[old];
    q->size[t] = q->size[old];
  }
  for (size_t k = 0; k < len; k++) chain[k] = map[chain[k]];
  for (size_t t = 0; t < q->m; t++) q->act[t] = (uint32_t)t;
  q->F = q->next = round_up8(q->m);
  free(map);
}

/* The nearest active cluster of x: the smallest (distance, pos), or prev
 * (SIZE_MAX: none; slots run past n) when its distance is that smallest. */
static size_t sq_nearest(const sq_chain *q, size_t x, size_t prev, double *dmin)
{
  const double *rx = q->row[x];
  const uint32_t *act = q->act, *pos = q->pos;
  double bv = INFINITY;
  uint32_t bp = UINT32_MAX;
  size_t by = x, t = 0, m = q->m, F = q->F, j;
  for (; t < m && (j = act[t]) < F; t++) {   /* rx[j] is D(x, j); rx[x] is infinite */
    double v = rx[j];
    if (v < bv || (v == bv && pos[j] < bp)) { bv = v; bp = pos[j]; by = j; }
  }
  for (; t < m; t++) {                       /* the unflushed new slots */
    j = act[t];
    if (j == x) continue;
    double v = j > x ? q->row[j][x] : rx[j];
    if (v < bv || (v == bv && pos[j] < bp)) { bv = v; bp = pos[j]; by = j; }
  }
  if (prev != SIZE_MAX && sq_get(q, x, prev) == bv) by = prev;
  *dmin = bv;
  return by;
}

/* Removes slots a and b from the active list, keeping it increasing. */
static void sq_deactivate(sq_chain *q, size_t a, size_t b)
{
  size_t w = 0;
  for (size_t t = 0; t < q->m; t++)
    if (q->act[t] != a && q->act[t] != b) q->act[w++] = q->act[t];
  q->m = w;
}

/* M: the square matrix (n rows of C = sq_columns(n), sq_distances or
 * sq_from_condensed), freed here. */
static void linkage_nn_chain_square(double *M, size_t n, nl_cluster_linkage_method method, double *Z)
{
  sq_chain q;
  q.C = sq_columns(n);
  q.row = nl_xmalloc(q.C * sizeof *q.row);
  q.pos = nl_xmalloc(q.C * sizeof *q.pos);
  q.act = nl_xmalloc(n * sizeof *q.act);
  q.size = nl_xmalloc(q.C * sizeof *q.size);
  for (size_t i = 0; i < n; i++) {
    q.row[i] = M + i * q.C;
    q.pos[i] = q.act[i] = (uint32_t)i;
    q.size[i] = 1.0;
  }
  q.m = n;
  q.F = q.next = round_up8(n);
  size_t *chain = nl_xmalloc(n * sizeof *chain), len = 0;
  for (size_t k = 0; k + 1 < n; k++) {
    if (len == 0) {   /* scipy starts a chain at its lowest active index */
      size_t lo = q.act[0];
      for (size_t t = 1; t < q.m; t++)
        if (q.pos[q.act[t]] < q.pos[lo]) lo = q.act[t];
      chain[len++] = lo;
    }
    size_t x, y;
    double dmin;
    for (;;) {
      x = chain[len - 1];
      size_t prev = len > 1 ? chain[len - 2] : SIZE_MAX;
      y = sq_nearest(&q, x, prev, &dmin);
      if (len > 1 && y == prev) break;
      chain[len++] = y;
    }
    len -= 2;
    if (q.pos[x] > q.pos[y]) { size_t t = x; x = y; y = t; }
    double nx = q.size[x], ny = q.size[y];
    Z[4 * k] = (double)q.pos[x];
    Z[4 * k + 1] = (double)q.pos[y];
    Z[4 * k + 2] = dmin;
    /* The new cluster's row, written over y's: for i below F both rows hold
     * D(i, x) and D(i, y) at i; the unflushed slots go through sq_get. */
    size_t s = q.next++;
    double *rx = q.row[x], *ry = q.row[y];
    for (size_t t = 0; t < q.m; t++) {
      size_t i = q.act[t];
      if (i == x || i == y) continue;
      double dx, dy;
      if (i < q.F) { dx = rx[i]; dy = ry[i]; }
      else { dx = sq_get(&q, i, x); dy = sq_get(&q, i, y); }
      double v;
      /* complete: max(dx, dy) (no NaN: every distance was checked finite) */
      if (method == NL_LINKAGE_COMPLETE) v = dx > dy ? dx : dy;
      else if (method == NL_LINKAGE_AVERAGE) v = (nx * dx + ny * dy) / (nx + ny);
      else if (method == NL_LINKAGE_WEIGHTED) v = 0.5 * (dx + dy);   /* WPGMA, scipy's _weighted */
      else {
        /* Ward, in scipy's _hierarchy_distance_update.pxi _ward expression and order. */
        double ni = q.size[i], tt = 1.0 / (nx + ny + ni);
        v = sqrt((ni + nx) * tt * dx * dx + (ni + ny) * tt * dy * dy - ni * tt * dmin * dmin);
      }
      ry[i] = v;
    }
    ry[s] = INFINITY;
    q.row[s] = ry;
    q.pos[s] = q.pos[y];
    q.size[s] = nx + ny;
    sq_deactivate(&q, x, y);
    q.act[q.m++] = (uint32_t)s;
    if (q.next - q.F == SQ_BATCH) sq_flush(&q);
    if (q.next == q.C) {
      sq_flush(&q);
      sq_compact(&q, chain, len);
    }
  }
  free(chain);
  free(q.row);
  free(q.pos);
  free(q.act);
  free(q.size);
  free(M);
}

/* The condensed matrix of another metric, with the column lists filled in
 * the order condensed_distances fills them (rows increasing per column). */
static double *condensed_metric(const double *x, size_t n, size_t d, nl_cluster_metric metric,
                                col_top *cm, nl_status *st, nl_error *err)
{
  double *D = condensed_alloc(n * (n - 1) / 2);
  if (!D) return NULL;
  for (size_t j = 0; j < n; j++) { cm[j].cnt = 0; cm[j].full = 1; }
  for (size_t i = 0; i + 1 < n; i++)
    for (size_t j = i + 1; j < n; j++) {
      double v = metric_dist(metric, x + i * d, x + j * d, d);
      if (!isfinite(v)) {
        *st = not_finite(metric, i, j, v, err);
        return D;
      }
      D[cidx(n, i, j)] = v;
      col_offer(&cm[j], v, i);
    }
  return D;
}

/* ---- centroid / median: the generic algorithm ------------------------------ */

/* Their Lance-Williams updates are not reducible (a merge can sit lower than
 * the one before it), so the chain does not apply: Muellner's generic
 * algorithm (arXiv:1109.2378, fig. 2) as scipy's fast_linkage writes it,
 * with its binary heap of lower bounds on each cluster's nearest neighbour
 * among higher indices, so that merges and ties come out in scipy's order. */
typedef struct { double *v; size_t *key_at, *at_key, size; } heap;

static void heap_swap(heap *h, size_t i, size_t j)
{
  double t = h->v[i];
  h->v[i] = h->v[j];
  h->v[j] = t;
  size_t ki = h->key_at[i], kj = h->key_at[j];
  h->key_at[i] = kj;
  h->key_at[j] = ki;
  h->at_key[ki] = j;
  h->at_key[kj] = i;
}

static void heap_down(heap *h, size_t i)
{
  for (size_t c = 2 * i + 1; c < h->size; c = 2 * i + 1) {
    if (c + 1 < h->size && h->v[c + 1] < h->v[c]) c++;
    if (!(h->v[i] > h->v[c])) break;
    heap_swap(h, i, c);
    i = c;
  }
}

static void heap_change(heap *h, size_t key, double value)
{
  size_t i = h->at_key[key];
  double old = h->v[i];
  h->v[i] = value;
  if (value < old) {
    while (i > 0 && h->v[(i - 1) / 2] > h->v[i]) {
      heap_swap(h, i, (i - 1) / 2);
      i = (i - 1) / 2;
    }
  } else {
    heap_down(h, i);
  }
}

/* The nearest active cluster above x: (index, distance), index n if none. */
static size_t find_min_dist(const double *D, size_t n, const double *size, size_t x, double *dist)
{
  double best = INFINITY;
  size_t y = n;
  for (size_t i = x + 1; i < n; i++) {
    if (size[i] == 0.0) continue;
    double v = D[cidx(n, x, i)];
    if (v < best) { best = v; y = i; }
  }
  *dist = best;
  return y;
}

/* Z in merge order with scipy's cluster numbers (no sorting: heights may
 * decrease). scipy's _centroid and _median updates on Euclidean distances. */
static void linkage_generic(double *D, size_t n, nl_cluster_linkage_method method, double *Z)
{
  double *size = nl_xmalloc(n * sizeof(double)), *min_dist = nl_xmalloc(n * sizeof(double));
  size_t *id = nl_xmalloc(n * sizeof(size_t)), *nbr = nl_xmalloc(n * sizeof(size_t));
  heap h = {nl_xmalloc(n * sizeof(double)), nl_xmalloc(n * sizeof(size_t)),
            nl_xmalloc(n * sizeof(size_t)), n - 1};
  for (size_t i = 0; i < n; i++) { size[i] = 1.0; id[i] = i; }
  for (size_t x = 0; x + 1 < n; x++) {
    nbr[x] = find_min_dist(D, n, size, x, &min_dist[x]);
    h.v[x] = min_dist[x];
    h.key_at[x] = h.at_key[x] = x;
  }
  for (size_t i = h.size / 2; i-- > 0;) heap_down(&h, i);
  for (size_t k = 0; k + 1 < n; k++) {
    size_t x = 0, y = 0;
    double dist = 0.0;
    for (size_t i = 0; i < n - k; i++) {   /* at most n - k refreshes, as scipy */
      x = h.key_at[0];
      dist = h.v[0];
      y = nbr[x];
      if (dist == D[cidx(n, x, y)]) break;
      y = find_min_dist(D, n, size, x, &dist);
      nbr[x] = y;
      min_dist[x] = dist;
      heap_change(&h, x, dist);
    }
    heap_swap(&h, 0, h.size - 1);   /* remove the minimum */
    h.size--;
    heap_down(&h, 0);
    size_t ix = id[x] < id[y] ? id[x] : id[y], iy = id[x] < id[y] ? id[y] : id[x];
    double nx = size[x], ny = size[y];
    Z[4 * k] = (double)ix;
    Z[4 * k + 1] = (double)iy;
    Z[4 * k + 2] = dist;
    Z[4 * k + 3] = nx + ny;
    size[x] = 0.0;
    size[y] = nx + ny;
    id[y] = n + k;
    for (size_t z = 0; z < n; z++) {
      if (size[z] == 0.0 || z == y) continue;
      double dx = D[cidx(n, z, x)], dy = D[cidx(n, z, y)], v;
      if (method == NL_LINKAGE_CENTROID)
        v = sqrt(((nx * dx * dx) + (ny * dy * dy) - (nx * ny * dist * dist) / (nx + ny))
                 / (nx + ny));
      else
        v = sqrt(0.5 * (dx * dx + dy * dy) - 0.25 * dist * dist);
      D[cidx(n, z, y)] = v;
    }
    for (size_t z = 0; z < x; z++)
      if (size[z] > 0.0 && nbr[z] == x) nbr[z] = y;
    for (size_t z = 0; z < y; z++) {
      if (size[z] == 0.0) continue;
      double v = D[cidx(n, z, y)];
      if (v < min_dist[z]) {
        nbr[z] = y;
        min_dist[z] = v;
        heap_change(&h, z, v);
      }
    }
    if (y + 1 < n) {
      size_t z = find_min_dist(D, n, size, y, &dist);
      if (z < n) {
        nbr[y] = z;
        min_dist[y] = dist;
        heap_change(&h, y, dist);
      }
    }
  }
  free(size); free(min_dist); free(id); free(nbr);
  free(h.v); free(h.key_at); free(h.at_key);
}

/* Refuses points whose bounding box's diagonal, an upper bound on every
 * pairwise distance, exceeds NL_CLUSTER_MAX_SPAN (nl_cluster.h). Half-widths
 * keep the subtraction finite for coordinates near +-DBL_MAX, and hypot
 * keeps the sum of their squares from overflowing before the comparison, so
 * the message gives the real span. */
static nl_status check_span(const double *x, size_t n, size_t d, double *span_out, nl_error *err)
{
  double half_span = 0.0;
  for (size_t j = 0; j < d; j++) {
    double lo = x[j], hi = x[j];
    for (size_t i = 1; i < n; i++) {
      lo = fmin(lo, x[i * d + j]);
      hi = fmax(hi, x[i * d + j]);
    }
    half_span = hypot(half_span, hi / 2 - lo / 2);
  }
  double span = 2 * half_span;
  *span_out = span;
  if (span <= NL_CLUSTER_MAX_SPAN) return NL_OK;
  return nl_fail(err, NL_EINVAL, "the points span a distance of %.3g; distances above %g overflow "
                 "in the linkage: rescale the data", span, NL_CLUSTER_MAX_SPAN);
}

nl_status nl_cluster_linkage(const double *x, size_t n, size_t d, nl_cluster_linkage_method method,
                             double *Z, nl_error *err)
{
  return nl_cluster_linkage_metric(x, n, d, method, NL_METRIC_EUCLIDEAN, Z, err);
}

nl_status nl_cluster_linkage_metric(const double *x, size_t n, size_t d,
                                    nl_cluster_linkage_method method, nl_cluster_metric metric,
                                    double *Z, nl_error *err)
{
  if (n < 2) return nl_fail(err, NL_EINVAL, "clustering needs at least 2 points, got %zu", n);
  if (d < 1) return nl_fail(err, NL_EINVAL, "points have no coordinates");
  int geometric = method == NL_LINKAGE_WARD || method == NL_LINKAGE_CENTROID
                  || method == NL_LINKAGE_MEDIAN;
  if (geometric && metric != NL_METRIC_EUCLIDEAN)
    return nl_fail(err, NL_EINVAL, "%s linkage needs the Euclidean metric, not %s (its update "
                   "is geometry in Euclidean space; scipy refuses it too)",
                   method_names[method], metric_names[metric]);
  for (size_t i = 0; i < n * d; i++)
    if (!isfinite(x[i]))
      return nl_fail(err, NL_EINVAL, "point %zu, coordinate %zu is not finite", i / d + 1, i % d + 1);
  double span;
  nl_status s = check_span(x, n, d, &span, err);
  if (s) return s;
  s = check_ratio_metric(x, n, d, metric, err);
  if (s) return s;
  /* Euclidean distances need no check: the span bounds them (check_span). */
  int shift = 0;
  double *prep = prepare_rows(x, n, d, metric, span, &shift);
  const double *px = prep ? prep : x;
  if (method == NL_LINKAGE_SINGLE) {
    s = linkage_single(px, n, d, metric, Z, err);
    free(prep);
    if (s) return s;
  } else {
    /* Checked before trying: malloc may grant what the machine cannot hold
     * (overcommit), and the O(n^2) fill would run for minutes first. */
    double need = (double)n * (double)(n - 1) / 2 * sizeof(double);
    char b1[32], b2[32];
    if (!nl_mem_fits(need)) {
      free(prep);
      return nl_fail(err, NL_ENOMEM, "%zu rows need %s for the distance matrix; %s is available",
                     n, nl_format_bytes(b1, need), nl_format_bytes(b2, nl_mem_available()));
    }
    /* Euclidean chain linkages: the square matrix straight from the points
     * when it fits (linkage_nn_chain_square), else the condensed chain. */
    int chain = method != NL_LINKAGE_CENTROID && method != NL_LINKAGE_MEDIAN;
    double *M = chain && metric == NL_METRIC_EUCLIDEAN ? sq_alloc(n) : NULL;
    if (M) {
      sq_distances(px, n, d, M, sq_columns(n));
      free(prep);
      linkage_nn_chain_square(M, n, method, Z);
      sort_and_label(Z, n);
      unscale_heights(Z, n, shift);
      return NL_OK;
    }
    col_top *cm = nl_xmalloc(n * sizeof *cm);
    double *D = metric == NL_METRIC_EUCLIDEAN ? condensed_distances(px, n, d, cm)
                                              : condensed_metric(px, n, d, metric, cm, &s, err);
    free(prep);
    if (s) {
      free(D);
      free(cm);
      return s;
    }
    if (!D) {
      free(cm);
      return nl_fail(err, NL_ENOMEM, "%zu rows need %s for the distance matrix; allocating it failed",
                     n, nl_format_bytes(b1, need));
    }
    if (method == NL_LINKAGE_CENTROID || method == NL_LINKAGE_MEDIAN) {
      linkage_generic(D, n, method, Z);
      free(D);
      free(cm);
      unscale_heights(Z, n, shift);
      return NL_OK;   /* scipy's order and numbers already; no sorting (inversions) */
    }
    /* other metrics: the square matrix from the condensed one, if it fits beside it */
    if ((M = sq_alloc(n))) {
      sq_from_condensed(D, n, M, sq_columns(n));
      free(D);
      free(cm);
      linkage_nn_chain_square(M, n, method, Z);
    } else {
      linkage_nn_chain(D, n, method, cm, Z);
      free(D);
      free(cm);
    }
  }
  sort_and_label(Z, n);
  unscale_heights(Z, n, shift);
  return NL_OK;
}

/* Single linkage on a condensed matrix: linkage_single's Prim loop, its
 * distances read instead of computed, so ties resolve the same way. */
static void linkage_single_condensed(const double *D, size_t n, double *Z)
{
  double *dmin = nl_xmalloc(n * sizeof(double));
  unsigned char *merged = nl_xcalloc(n, 1);
  for (size_t i = 0; i < n; i++) dmin[i] = INFINITY;
  size_t cur = 0;
  for (size_t k = 0; k + 1 < n; k++) {
    merged[cur] = 1;
    double best = INFINITY;
    size_t y = cur;
    for (size_t i = 0; i < n; i++) {
      if (merged[i]) continue;
      double dist = D[cidx(n, cur, i)];
      if (dist < dmin[i]) dmin[i] = dist;
      if (dmin[i] < best || y == cur) { best = dmin[i]; y = i; }
    }
    Z[4 * k] = (double)cur;
    Z[4 * k + 1] = (double)y;
    Z[4 * k + 2] = best;
    cur = y;
  }
  free(dmin);
  free(merged);
}

nl_status nl_cluster_linkage_condensed(const double *y, size_t n, nl_cluster_linkage_method method,
                                       double *Z, nl_error *err)
{
  if (n < 2) return nl_fail(err, NL_EINVAL, "clustering needs at least 2 points, got %zu", n);
  size_t m = n * (n - 1) / 2;
  for (size_t k = 0; k < m; k++)
    if (!(isfinite(y[k]) && y[k] >= 0))
      return nl_fail(err, NL_EINVAL, "distance %zu is %g: distances must be finite and >= 0",
                     k + 1, y[k]);
  if (method == NL_LINKAGE_SINGLE) {
    linkage_single_condensed(y, n, Z);
    sort_and_label(Z, n);
    return NL_OK;
  }
  char b1[32], b2[32];
  double need = (double)m * sizeof(double);
  if (!nl_mem_fits(need))
    return nl_fail(err, NL_ENOMEM, "%zu rows need %s for the distance matrix; %s is available",
                   n, nl_format_bytes(b1, need), nl_format_bytes(b2, nl_mem_available()));
  /* the chain on the square matrix when it fits beside y (linkage_nn_chain_square) */
  double *M = method != NL_LINKAGE_CENTROID && method != NL_LINKAGE_MEDIAN ? sq_alloc(n) : NULL;
  if (M) {
    sq_from_condensed(y, n, M, sq_columns(n));
    linkage_nn_chain_square(M, n, method, Z);
    sort_and_label(Z, n);
    return NL_OK;
  }
  double *D = condensed_alloc(m);
  if (!D)
    return nl_fail(err, NL_ENOMEM, "%zu rows need %s for the distance matrix; allocating it failed",
                   n, nl_format_bytes(b1, need));
  memcpy(D, y, m * sizeof(double));
  if (method == NL_LINKAGE_CENTROID || method == NL_LINKAGE_MEDIAN) {
    linkage_generic(D, n, method, Z);
    free(D);
    return NL_OK;
  }
  /* the column lists in condensed_metric's order: rows increasing per column */
  col_top *cm = nl_xmalloc(n * sizeof *cm);
  for (size_t j = 0; j < n; j++) { cm[j].cnt = 0; cm[j].full = 1; }
  for (size_t i = 0; i + 1 < n; i++)
    for (size_t j = i + 1; j < n; j++) col_offer(&cm[j], D[cidx(n, i, j)], i);
  linkage_nn_chain(D, n, method, cm, Z);
  free(D);
  free(cm);
  sort_and_label(Z, n);
  return NL_OK;
}

/* ---- flat clusters ------------------------------------------------------------- */

static nl_status check_Z(const double *Z, size_t n, nl_error *err)
{
  if (n < 2) return nl_fail(err, NL_EINVAL, "a linkage needs at least 2 points");
  for (size_t i = 0; i + 1 < n; i++)
    if (!(Z[4 * i] >= 0 && Z[4 * i] < (double)(n + i) && Z[4 * i + 1] >= 0 &&
          Z[4 * i + 1] < (double)(n + i) && Z[4 * i + 2] >= 0))
      return nl_fail(err, NL_EINVAL, "linkage row %zu is not a valid merge", i + 1);
  return NL_OK;
}

/* Largest merge height in each subtree (scipy's get_max_dist_for_each_cluster);
 * equals the node's own height for monotone linkages, computed for safety. */
static double *max_dists(const double *Z, size_t n)
{
  double *md = nl_xmalloc((n - 1) * sizeof(double));
  for (size_t i = 0; i + 1 < n; i++) {
    double m = Z[4 * i + 2];
    for (int s = 0; s < 2; s++) {
      size_t c = (size_t)Z[4 * i + s];
      if (c >= n) m = fmax(m, md[c - n]);
    }
    md[i] = m;
  }
  return md;
}

/* scipy's cluster_monocrit: depth-first from the root, left child first;
 * the first node on a path with md <= cutoff starts a cluster holding all
 * its leaves; leaves outside any such node are singletons. */
static size_t monocrit(const double *Z, const double *md, size_t n, double cutoff, int *T)
{
  size_t *stack = nl_xmalloc(n * sizeof(size_t));
  unsigned char *visited = nl_xcalloc(2 * n, 1);
  long k = 0, leader = -1;
  size_t ncl = 0;
  stack[0] = 2 * n - 2;
  while (k >= 0) {
    size_t root = stack[k] - n, lc = (size_t)Z[4 * root], rc = (size_t)Z[4 * root + 1];
    if (leader == -1 && md[root] <= cutoff) { leader = (long)root; ncl++; }
    if (lc >= n && !visited[lc]) { visited[lc] = 1; stack[++k] = lc; continue; }
    if (rc >= n && !visited[rc]) { visited[rc] = 1; stack[++k] = rc; continue; }
    if (lc < n) { if (leader == -1) ncl++; T[lc] = (int)ncl; }
    if (rc < n) { if (leader == -1) ncl++; T[rc] = (int)ncl; }
    if (leader == (long)root) leader = -1;
    k--;
  }
  free(stack);
  free(visited);
  return ncl;
}

nl_status nl_cluster_fcluster_distance(const double *Z, size_t n, double t, int *labels,
                                       size_t *nclusters, nl_error *err)
{
  if (!(t >= 0.0) || !isfinite(t))
    return nl_fail(err, NL_EINVAL, "cutoff distance %g must be finite and >= 0", t);
  nl_status s = check_Z(Z, n, err);
  if (s) return s;
  double *md = max_dists(Z, n);
  size_t k = monocrit(Z, md, n, t, labels);
  free(md);
  if (nclusters) *nclusters = k;
  return NL_OK;
}

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

nl_status nl_cluster_fcluster_maxclust(const double *Z, size_t n, size_t k, int *labels,
                                       size_t *nclusters, nl_error *err)
{
  if (k < 1) return nl_fail(err, NL_EINVAL, "number of clusters must be >= 1");
  nl_status s = check_Z(Z, n, err);
  if (s) return s;
  double *md = max_dists(Z, n), *sorted = nl_xmalloc((n - 1) * sizeof(double));
  memcpy(sorted, md, (n - 1) * sizeof(double));
  qsort(sorted, n - 1, sizeof(double), cmp_double);
  /* cutting at height t leaves n - #{md <= t} clusters (md is monotone up
   * the tree), so the lowest cut with at most k clusters is the (n-k)th
   * smallest md; k >= n cuts below every merge */
  double t = k >= n ? -1.0 : sorted[n - k - 1];
  size_t got = monocrit(Z, md, n, t, labels);
  free(md);
  free(sorted);
  if (nclusters) *nclusters = got;
  return NL_OK;
}
