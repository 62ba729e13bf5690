/* Tests of nl_cluster.h against scipy.cluster.hierarchy 1.10
 * (tests/reference/make_stats_vectors.py: 200 points in 6-D, 5 blobs).
 * Tolerances: merge heights 1e-12 relative (distances are summed in another
 * order than pdist's); merged ids and sizes exact; flat-cluster labels exact
 * (we number clusters in scipy's order; a relabelling would also be a
 * correct answer, but equal labels are the stronger check).
 */
#include "stats/nl_cluster.h"
#include "nl_test.h"
#include "test_vectors.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

static const char *methods[] = {"single", "complete", "average"};

NL_TEST(linkage_matches_scipy)
{
  size_t n, d;
  double *x = vec_matrix("hclust_X.tsv", &n, &d), *Z = nl_xmalloc((n - 1) * 4 * sizeof(double));
  for (int m = 0; m < 3; m++) {
    nl_cluster_linkage_method lm;
    NL_CHECK(nl_cluster_linkage_method_parse(methods[m], &lm, NULL) == NL_OK);
    NL_CHECK(nl_cluster_linkage(x, n, d, lm, Z, NULL) == NL_OK);
    char name[64];
    snprintf(name, sizeof name, "hclust_%s_Z.tsv", methods[m]);
    nl_table *t = vec_read(name);
    NL_CHECK(t->nrows == n - 1);
    int bad = 0;
    for (size_t i = 0; i + 1 < n; i++) {
      bad += Z[4 * i] != nl_table_get(t, i, 0) || Z[4 * i + 1] != nl_table_get(t, i, 1);
      bad += !vec_close(Z[4 * i + 2], nl_table_get(t, i, 2), 1e-12, 0);
      bad += Z[4 * i + 3] != nl_table_get(t, i, 3);
    }
    if (bad) fprintf(stderr, "  %s: %d mismatches\n", methods[m], bad);
    NL_CHECK(bad == 0);
    nl_table_free(t);
  }
  free(x);
  free(Z);
}

NL_TEST(fcluster_matches_scipy)
{
  size_t n, d;
  double *x = vec_matrix("hclust_X.tsv", &n, &d), *Z = nl_xmalloc((n - 1) * 4 * sizeof(double));
  int *lab = nl_xmalloc(n * sizeof(int));
  for (int m = 0; m < 3; m++) {
    nl_cluster_linkage_method lm = (nl_cluster_linkage_method)m;
    nl_cluster_linkage(x, n, d, lm, Z, NULL);
    char name[64];
    snprintf(name, sizeof name, "hclust_%s_labels.tsv", methods[m]);
    nl_table *t = vec_read(name);
    for (size_t c = 0; c < t->ncols; c++) {
      size_t k;
      if (strncmp(t->names[c], "cut_", 4) == 0)
        NL_CHECK(nl_cluster_fcluster_distance(Z, n, atof(t->names[c] + 4), lab, &k, NULL) == NL_OK);
      else
        NL_CHECK(nl_cluster_fcluster_maxclust(Z, n, (size_t)atol(t->names[c] + 9), lab, &k, NULL) == NL_OK);
      int bad = 0, kmax = 0;
      for (size_t i = 0; i < n; i++) {
        bad += lab[i] != (int)nl_table_get(t, i, c);
        kmax = lab[i] > kmax ? lab[i] : kmax;
      }
      if (bad) fprintf(stderr, "  %s %s: %d labels differ\n", methods[m], t->names[c], bad);
      NL_CHECK(bad == 0 && (size_t)kmax == k);
    }
    nl_table_free(t);
  }
  free(x); free(Z); free(lab);
}

NL_TEST(bad_input)
{
  nl_error err;
  double x[] = {0, 1, NAN, 2}, Z[8];
  int lab[3];
  NL_CHECK(nl_cluster_linkage(x, 1, 2, NL_LINKAGE_SINGLE, Z, &err) == NL_EINVAL);
  NL_CHECK(nl_cluster_linkage(x, 2, 2, NL_LINKAGE_SINGLE, Z, &err) == NL_EINVAL);
  double y[] = {0, 1, 3};
  NL_CHECK(nl_cluster_linkage(y, 3, 1, NL_LINKAGE_AVERAGE, Z, &err) == NL_OK);
  NL_CHECK(nl_cluster_fcluster_distance(Z, 3, -1.0, lab, NULL, &err) == NL_EINVAL && strstr(err.msg, ">= 0"));
  NL_CHECK(nl_cluster_fcluster_maxclust(Z, 3, 0, lab, NULL, &err) == NL_EINVAL);
  nl_cluster_linkage_method m;
  NL_CHECK(nl_cluster_linkage_method_parse("medoid", &m, &err) == NL_EINVAL);
  NL_CHECK(nl_cluster_linkage_method_parse("ward", &m, &err) == NL_OK && m == NL_LINKAGE_WARD);
}

/* Points far enough apart that their squared distances overflow: every
 * linkage refuses them with a line saying so instead of clustering
 * infinities (nearest() then had no candidate and indexed past the
 * matrix). Just below the limit, Ward's squared cluster distances (the
 * largest terms) stay finite and the heights are exact multiples of the
 * small case's. */
NL_TEST(huge_values_refused)
{
  double pairs[][3] = {{0, 1e160, 0}, {0, 1e200, 3e200}, {-DBL_MAX, DBL_MAX, 0}, {0, 1.1e150, 0}};
  double Z[8];
  for (int m = 0; m < 4; m++)
    for (int p = 0; p < 4; p++) {
      nl_error err;
      err.msg[0] = 0;
      size_t n = pairs[p][2] != 0 ? 3 : 2;
      nl_cluster_linkage_method lm = (nl_cluster_linkage_method)m;
      NL_CHECK(nl_cluster_linkage(pairs[p], n, 1, lm, Z, &err) == NL_EINVAL);
      NL_CHECK(strstr(err.msg, "rescale the data") != NULL);
    }
  double big[] = {0, 1e149, 3e149, 4e149}, small[] = {0, 1, 3, 4}, Zb[12], Zs[12];
  for (int m = 0; m < 4; m++) {
    NL_CHECK(nl_cluster_linkage(big, 4, 1, (nl_cluster_linkage_method)m, Zb, NULL) == NL_OK);
    NL_CHECK(nl_cluster_linkage(small, 4, 1, (nl_cluster_linkage_method)m, Zs, NULL) == NL_OK);
    for (int i = 0; i < 3; i++) {
      NL_CHECK(isfinite(Zb[4 * i + 2]));
      NL_CHECK_NEAR(Zb[4 * i + 2] / 1e149, Zs[4 * i + 2], 1e-12);
    }
  }
}

/* Ward on four points of a line, worked by hand: {0,1} and {10,11} merge at
 * sqrt(2 * 0.5) = 1 each (the height is sqrt(2 x the increase in the sum
 * of squares, 1/2)); the last merge joins two pairs whose centres are 10
 * apart: increase 2*2/4 * 100 = 100, height sqrt(200). */
NL_TEST(ward_by_hand)
{
  double x[] = {0, 1, 10, 11}, Z[12];
  nl_error err;
  NL_CHECK(nl_cluster_linkage(x, 4, 1, NL_LINKAGE_WARD, Z, &err) == NL_OK);
  NL_CHECK_NEAR(Z[2], 1.0, 1e-15);
  NL_CHECK_NEAR(Z[6], 1.0, 1e-15);
  NL_CHECK_NEAR(Z[10], sqrt(200.0), 1e-13);
  NL_CHECK(Z[11] == 4.0);
}

/* ---- both chains against a plain NN-chain ---------------------------------
 * nl_cluster.c runs the chain on a square matrix whose new clusters take new
 * columns (and whose ties are decided by scipy's indices, not the slots'),
 * or, where that matrix does not fit, on the condensed matrix with each
 * column's smallest entries cached; the merges of both must be the ones the
 * plain chain makes, bit for bit, ties included. The condensed chain is run
 * by capping the memory the library sees (nl_mem_cap) between the condensed
 * matrix's size and the square one's. The reference
 * below is that plain chain (full scans, the same tie rule: prev first,
 * else the lowest index at the minimum) with scipy's stable sort and
 * relabelling. Points on a small integer grid give many equal distances
 * and duplicate points, so ties decide most merges. */

static int ref_cmp(const void *pa, const void *pb)
{
  const double *a = pa, *b = pb;   /* {height, order} */
  if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
  return (a[1] > b[1]) - (a[1] < b[1]);
}

static void ref_linkage(const double *x, size_t n, size_t d, nl_cluster_linkage_method m, double *Z)
{
  double *D = nl_xmalloc(n * n * sizeof *D), *size = nl_xmalloc(n * sizeof *size);
  double *raw = nl_xmalloc(4 * n * sizeof *raw), *key = nl_xmalloc(2 * n * sizeof *key);
  size_t *chain = nl_xmalloc(n * sizeof *chain), len = 0, *parent = nl_xmalloc(2 * n * sizeof *parent);
  unsigned char *on = nl_xmalloc(n);
  for (size_t i = 0; i < n; i++) {
    size[i] = 1.0; on[i] = 1;
    for (size_t j = 0; j < n; j++) D[i * n + j] = nl_cluster_euclidean(x + i * d, x + j * d, d);
  }
  for (size_t k = 0; k + 1 < n; k++) {
    size_t a = 0, b, prev;
    while (!on[a]) a++;
    if (len == 0) chain[len++] = a;
    double dmin;
    for (;;) {
      a = chain[len - 1];
      prev = len > 1 ? chain[len - 2] : n;
      dmin = prev < n ? D[a * n + prev] : INFINITY;
      b = prev;
      for (size_t i = 0; i < n; i++)
        if (on[i] && i != a && D[a * n + i] < dmin) { dmin = D[a * n + i]; b = i; }
      if (len > 1 && b == prev) break;
      chain[len++] = b;
    }
    len -= 2;
    size_t lo = a < b ? a : b, hi = a < b ? b : a;
    double nx = size[lo], ny = size[hi];
    raw[4 * k] = (double)lo; raw[4 * k + 1] = (double)hi; raw[4 * k + 2] = dmin;
    on[lo] = 0; size[lo] = 0.0; size[hi] = nx + ny;
    for (size_t i = 0; i < n; i++) {
      if (!on[i] || i == hi) continue;
      double dx = D[i * n + lo], dy = D[i * n + hi], v, ni = size[i], t = 1.0 / (nx + ny + ni);
      if (m == NL_LINKAGE_COMPLETE) v = dx > dy ? dx : dy;
      else if (m == NL_LINKAGE_AVERAGE) v = (nx * dx + ny * dy) / (nx + ny);
      else v = sqrt((ni + nx) * t * dx * dx + (ni + ny) * t * dy * dy - ni * t * dmin * dmin);
      D[i * n + hi] = D[hi * n + i] = v;
    }
  }
  for (size_t k = 0; k + 1 < n; k++) { key[2 * k] = raw[4 * k + 2]; key[2 * k + 1] = (double)k; }
  qsort(key, n - 1, 2 * sizeof *key, ref_cmp);
  double *csize = nl_xmalloc(2 * n * sizeof *csize);
  for (size_t i = 0; i < 2 * n; i++) { parent[i] = i; csize[i] = 1.0; }
  for (size_t k = 0; k + 1 < n; k++) {
    const double *r = raw + 4 * (size_t)key[2 * k + 1];
    size_t root[2];
    for (int s = 0; s < 2; s++) {
      size_t c = (size_t)r[s];
      while (parent[c] != c) c = parent[c];
      root[s] = c;
    }
    size_t a = root[0] < root[1] ? root[0] : root[1], b = root[0] < root[1] ? root[1] : root[0];
    parent[a] = parent[b] = n + k;
    csize[n + k] = csize[a] + csize[b];
    Z[4 * k] = (double)a; Z[4 * k + 1] = (double)b; Z[4 * k + 2] = r[2]; Z[4 * k + 3] = csize[n + k];
  }
  free(D); free(size); free(raw); free(key); free(chain); free(parent); free(on); free(csize);
}

/* The number of values of Z (complete, average, Ward) that differ from the
 * plain chain's. */
static size_t differ_from_plain_chain(const double *x, size_t n, size_t d, const char *what)
{
  double *Z = nl_xmalloc(4 * n * sizeof *Z), *R = nl_xmalloc(4 * n * sizeof *R);
  size_t total = 0;
  /* condensed: n(n-1)/2 doubles; square: n rows of at least n + n/4 */
  double condensed = (double)n * (double)(n - 1) / 2 * sizeof(double);
  for (int layout = 0; layout < 2; layout++)
    for (int m = NL_LINKAGE_COMPLETE; m <= NL_LINKAGE_WARD; m++) {
      ref_linkage(x, n, d, (nl_cluster_linkage_method)m, R);
      nl_mem_cap(layout ? 1.5 * condensed : 0);
      nl_status st = nl_cluster_linkage(x, n, d, (nl_cluster_linkage_method)m, Z, NULL);
      nl_mem_cap(0);
      if (st != NL_OK) return SIZE_MAX;
      size_t bad = 0;
      for (size_t i = 0; i < 4 * (n - 1); i++) bad += memcmp(&Z[i], &R[i], sizeof *Z) != 0;
      if (bad)
        fprintf(stderr, "  %s, method %d, %s chain: %zu values differ from the plain chain\n", what, m,
                layout ? "condensed" : "square", bad);
      total += bad;
    }
  free(Z); free(R);
  return total;
}

NL_TEST(linkage_column_lists_match_plain_chain)
{
  /* n, d, grid size: duplicates (400 points on 4^3 cells), ties in 2-D,
   * and a finer grid. */
  const size_t cases[][3] = {{400, 3, 4}, {300, 2, 6}, {500, 4, 9}};
  for (size_t c = 0; c < 3; c++) {
    size_t n = cases[c][0], d = cases[c][1];
    double *x = nl_xmalloc(n * d * sizeof *x);
    for (size_t i = 0; i < n * d; i++) x[i] = (double)(nl_seed_stream(17, "test.cluster.grid", c * 100000 + i) % cases[c][2]);
    char what[64];
    snprintf(what, sizeof what, "%zu points on a %zu^%zu grid", n, cases[c][2], d);
    NL_CHECK(differ_from_plain_chain(x, n, d, what) == 0);
    free(x);
  }
  /* A column whose list overflows and is then emptied: P (row 6) has four
   * points j at 1 on the y and z axes, Q (1.2) and L (1.05) above it in the
   * matrix; each j has a twin t (rows 7..10) 0.5 further out, which it
   * merges with first, so P's column loses every listed entry while L
   * stays unlisted. The chain then stands at Q -> P, and P's nearest is L
   * (1.05), not Q (1.2) nor a pair (1.5 complete): a list that forgot it
   * had dropped L would merge P with Q. Two row orders: L and Q offered
   * after the four j (they fall off the end of a full list), or before
   * them (pushed off by the j). */
  const double Q[3] = {1.2, 0, 0}, L[3] = {-1.05, 0, 0}, J[4][3] = {{0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const double *order[2][7] = {{J[0], J[1], J[2], J[3], Q, L, NULL}, {Q, L, J[0], J[1], J[2], J[3], NULL}};
  for (int o = 0; o < 2; o++) {
    double pts[11 * 3] = {0};   /* P = origin at row 6 */
    for (int r = 0; r < 6; r++) memcpy(pts + 3 * r, order[o][r], 3 * sizeof(double));
    for (int k = 0; k < 4; k++)
      for (int c = 0; c < 3; c++) pts[3 * (7 + k) + c] = 1.5 * J[k][c];
    NL_CHECK(differ_from_plain_chain(pts, 11, 3, o ? "overflow by insertion" : "overflow at the end") == 0);
  }
}

/* 3 million rows need ~36 TB of distances: refused at once with the size
 * named, instead of running for minutes (13.7). */
NL_TEST(linkage_refuses_what_the_machine_cannot_hold)
{
  size_t n = 3000000;
  double *x = calloc(n, sizeof *x);
  double *Z = malloc(4 * sizeof *Z);   /* never written: refused first */
  nl_error err = {{0}};
  NL_CHECK(nl_cluster_linkage(x, n, 1, NL_LINKAGE_COMPLETE, Z, &err) == NL_ENOMEM);
  NL_CHECK(strstr(err.msg, "3000000 rows need 36 TB for the distance matrix; ") != NULL);
  if (!strstr(err.msg, "36 TB")) fprintf(stderr, "  %s\n", err.msg);
  free(x); free(Z);
}

/* Every metric with single, complete, average and weighted linkage against
 * scipy.cluster.hierarchy.linkage(X, method, metric) on 14 points with
 * negative coordinates (hclust_metrics_*.tsv), and the same points times
 * 2^-664 (1.05e-200, an exact scaling): the scale-free metrics (cosine,
 * correlation, canberra, braycurtis) must give scipy's heights there too
 * (scipy itself gives 0/0 for cosine and correlation, and 0 for every
 * Euclidean height: its squares underflow), the others scipy's heights
 * times 2^-664 (sqeuclidean's 1e-400 underflows: skipped).
 * Tolerance: a, b and size exact; heights 1e-12 relative (measured: 0). */
NL_TEST(metrics_match_scipy_at_any_scale)
{
  size_t n, d;
  double *x = vec_matrix("hclust_metrics_X.tsv", &n, &d), *xs = nl_xmalloc(n * d * sizeof *xs);
  double *Z = nl_xmalloc((n - 1) * 4 * sizeof *Z), worst[2] = {0, 0};
  for (size_t i = 0; i < n * d; i++) xs[i] = ldexp(x[i], -664);
  nl_table *t = vec_read("hclust_metrics_Z.tsv");
  NL_CHECK(t->nrows == 32 * (n - 1));
  for (size_t c = 0; c < 32; c++) {
    nl_cluster_linkage_method lm;
    nl_cluster_metric mt;
    size_t r0 = c * (n - 1);
    NL_CHECK(nl_cluster_linkage_method_parse(vec_text(t, r0, "method"), &lm, NULL) == NL_OK);
    NL_CHECK(nl_cluster_metric_parse(vec_text(t, r0, "metric"), &mt, NULL) == NL_OK);
    int scale_free = mt == NL_METRIC_COSINE || mt == NL_METRIC_CORRELATION
                     || mt == NL_METRIC_CANBERRA || mt == NL_METRIC_BRAYCURTIS;
    for (int pass = 0; pass < 2; pass++) {
      if (pass == 1 && mt == NL_METRIC_SQEUCLIDEAN) continue;
      nl_error err = {{0}};
      nl_status st = nl_cluster_linkage_metric(pass ? xs : x, n, d, lm, mt, Z, &err);
      if (st) fprintf(stderr, "  %s %s x%s: %s\n", vec_text(t, r0, "method"), vec_text(t, r0, "metric"),
                      pass ? "1e-200" : "1", err.msg);
      NL_CHECK(st == NL_OK);
      if (st) continue;
      int bad = 0;
      for (size_t i = 0; i + 1 < n; i++) {
        double want = vec_get(t, r0 + i, "dist"), got = Z[4 * i + 2];
        if (pass && !scale_free) got = ldexp(got, 664);
        double rel = fabs(got - want) / fabs(want);
        worst[pass] = fmax(worst[pass], rel);
        bad += Z[4 * i] != vec_get(t, r0 + i, "a") || Z[4 * i + 1] != vec_get(t, r0 + i, "b");
        bad += Z[4 * i + 3] != vec_get(t, r0 + i, "size") || !(rel <= 1e-12);
      }
      if (bad) fprintf(stderr, "  %s %s x%s: %d mismatches\n", vec_text(t, r0, "method"),
                       vec_text(t, r0, "metric"), pass ? "1e-200" : "1", bad);
      NL_CHECK(bad == 0);
    }
  }
  if (getenv("NL_TEST_VERBOSE"))
    fprintf(stderr, "  worst relative height error: %.2g at scale 1, %.2g at 1e-200\n", worst[0], worst[1]);
  nl_table_free(t);
  free(x); free(xs); free(Z);
}

/* Where scipy's distances are not finite its linkage refuses ("The condensed
 * distance matrix must contain only finite values"): every linkage refuses
 * with the pair named, and never reaches the chain with a NaN (complete,
 * average and weighted then corrupted the heap). Where scipy's are finite,
 * they are given: a zero row is at Bray-Curtis distance 1 from any other
 * (scipy: linkage([[0,0],[1,2],[3,1]], 'average', 'braycurtis') merges 1
 * and 2 at 3/7, then 0 at 1). */
NL_TEST(metrics_refuse_where_scipy_does)
{
  struct { double x[6]; nl_cluster_metric m; const char *want; } bad[] = {
    {{1, 2, -1, -2, 3, 1}, NL_METRIC_BRAYCURTIS, "points 1 and 2: the braycurtis distance is x/0"},
    {{3, 1, 0, 0, -0.0, 0}, NL_METRIC_BRAYCURTIS, "points 2 and 3: the braycurtis distance is 0/0"},
    {{1, 2, 0, 0, 3, 1}, NL_METRIC_COSINE, "points 1 and 2: the cosine distance is 0/0 (point 2 is zero)"},
    {{1, 2, 3, 1, 0, 0}, NL_METRIC_COSINE, "points 1 and 3: the cosine distance is 0/0 (point 3 is zero)"},
    {{0.1, 0.1, 1, 2, 3, 1}, NL_METRIC_CORRELATION, "points 1 and 2: the correlation distance is 0/0 (point 1 is constant)"},
  };
  double Z[8];
  for (size_t c = 0; c < sizeof bad / sizeof bad[0]; c++)
    for (int m = 0; m < 5; m++) {
      if (m == NL_LINKAGE_WARD) continue;
      nl_error err = {{0}};
      NL_CHECK(nl_cluster_linkage_metric(bad[c].x, 3, 2, (nl_cluster_linkage_method)m, bad[c].m, Z, &err) == NL_EINVAL);
      if (!strstr(err.msg, bad[c].want)) fprintf(stderr, "  case %zu: %s\n", c, err.msg);
      NL_CHECK(strstr(err.msg, bad[c].want) != NULL);
    }
  double zero[] = {0, 0, 1, 2, 3, 1};
  NL_CHECK(nl_cluster_linkage_metric(zero, 3, 2, NL_LINKAGE_AVERAGE, NL_METRIC_BRAYCURTIS, Z, NULL) == NL_OK);
  NL_CHECK(Z[0] == 1 && Z[1] == 2 && Z[2] == 3.0 / 7.0 && Z[4] == 0 && Z[5] == 3 && Z[6] == 1.0);
}

/* The condensed entry point on pdist's matrix of the points gives the points'
 * linkage bit for bit (the same distances, the same algorithms and ties). */
NL_TEST(condensed_distances_give_the_points_linkage)
{
  size_t n, d;
  double *x = vec_matrix("hclust_X.tsv", &n, &d);
  double *y = nl_xmalloc(n * (n - 1) / 2 * sizeof(double));
  double *Z = nl_xmalloc((n - 1) * 4 * sizeof(double)), *Zc = nl_xmalloc((n - 1) * 4 * sizeof(double));
  for (size_t i = 0, k = 0; i < n; i++)
    for (size_t j = i + 1; j < n; j++) y[k++] = nl_cluster_euclidean(x + i * d, x + j * d, d);
  for (int m = 0; m <= NL_LINKAGE_MEDIAN; m++) {
    NL_CHECK(nl_cluster_linkage(x, n, d, (nl_cluster_linkage_method)m, Z, NULL) == NL_OK);
    NL_CHECK(nl_cluster_linkage_condensed(y, n, (nl_cluster_linkage_method)m, Zc, NULL) == NL_OK);
    size_t bad = 0;
    for (size_t i = 0; i < (n - 1) * 4; i++) bad += Z[i] != Zc[i];
    if (bad) fprintf(stderr, "  %s: %zu entries differ\n", nl_cluster_linkage_method_name((nl_cluster_linkage_method)m), bad);
    NL_CHECK(bad == 0);
  }
  nl_error err = {{0}};
  double neg[] = {1.0, -0.5, 2.0};
  NL_CHECK(nl_cluster_linkage_condensed(neg, 3, NL_LINKAGE_SINGLE, Zc, &err) == NL_EINVAL);
  NL_CHECK(strstr(err.msg, "distance 2 is -0.5") != NULL);
  NL_CHECK(nl_cluster_linkage_condensed(neg, 1, NL_LINKAGE_SINGLE, Zc, NULL) == NL_EINVAL);
  free(x);
  free(y);
  free(Z);
  free(Zc);
}

int main(void) { return nl_test_run(); }
