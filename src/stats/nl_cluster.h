/* nl_cluster.h - agglomerative hierarchical clustering (Euclidean).
 *
 *   double *Z = malloc((n - 1) * 4 * sizeof *Z);
 *   nl_cluster_linkage(x, n, d, NL_LINKAGE_COMPLETE, Z, &err);     // x: n rows of d, row-major
 *   int *labels = malloc(n * sizeof *labels);
 *   size_t k;
 *   nl_cluster_fcluster_distance(Z, n, 2.5, labels, &k, &err);     // or nl_cluster_fcluster_maxclust
 *
 * Output is scipy's linkage matrix: row i = {a, b, dist, size} merges clusters
 * a < b (0..n-1 are the points, n+j the cluster made by row j) at height dist
 * into a cluster of size points; rows sorted by dist (stable). The same
 * points give the same Z as scipy.cluster.hierarchy.linkage(x, method) up to
 * the rounding of the distances (1e-12 relative), and the same order unless
 * two merge heights tie to that precision.
 *
 * Algorithms (Muellner, "Modern hierarchical, agglomerative clustering
 * algorithms", arXiv:1109.2378, sec. 3), O(n^2) time but centroid and median:
 *   single:   Prim's minimum spanning tree with distances computed on the
 *             fly: O(n d) memory. (Single linkage = MST, Gower & Ross 1969.)
 *   complete, average: the nearest-neighbour chain, O(n^2) time, with
 *             memory traffic that stays sequential, so that the time per
 *             n^2 stays flat as n grows (bench_stats --only linkage
 *             --scale prints it for n = 1,000 ... 20,000). The Lance-Williams
 *             updates are complete d = max(d_ax, d_bx), average (UPGMA)
 *             d = (n_a d_ax + n_b d_bx) / (n_a + n_b); both are reducible,
 *             which the chain needs. Every cluster has a whole row of a
 *             square matrix, n rows of about 1.25 n doubles (1 GB for
 *             n = 10,000; scipy holds 800 MB): a merged cluster's row is
 *             made from its two parts' rows, and it takes a new column,
 *             written into the other rows eight new columns at a time (one
 *             cache line a row). Where that matrix does not fit in the
 *             available memory, the chain runs on the condensed matrix,
 *             n(n-1)/2 doubles (400 MB for n = 10,000) on 2 MB pages, each
 *             column keeping its 4 smallest entries (56 bytes a point) so
 *             that the nearest-neighbour search rarely scans a column
 *             (strided in that layout); its merges' memory reads go by
 *             columns, a cache miss each, so its time per n^2 grows with n
 *             once the matrix outgrows the caches. Both give the plain
 *             chain's merges, bit for bit, ties resolved as scipy's
 *             nn_chain resolves them.
 *   ward:     the same chain with Ward's Lance-Williams update on Euclidean
 *             distances (Ward 1963; Muellner eq. in table 1), written as
 *             scipy writes it, t = 1 / (n_a + n_b + n_x):
 *             d = sqrt((n_x + n_a) t d_ax^2 + (n_x + n_b) t d_bx^2 - n_x t d_ab^2);
 *             the height is sqrt(2 x the increase of the within-cluster sum
 *             of squares), scipy.cluster.hierarchy.linkage(x, 'ward').
 *   weighted: the chain with WPGMA's d = (d_ax + d_bx) / 2.
 *   centroid, median: not reducible (a merge can be lower than an earlier
 *             one), so Muellner's generic algorithm, O(n^2) to O(n^3), as
 *             scipy's fast_linkage; Z stays in merge order (not sorted),
 *             with scipy's updates on Euclidean distances:
 *             centroid, with n = n_a + n_b,
 *               d = sqrt((n_a d_ax^2 + n_b d_bx^2 - n_a n_b d_ab^2 / n) / n),
 *             median d = sqrt(d_ax^2 / 2 + d_bx^2 / 2 - d_ab^2 / 4).
 * Other metrics (nl_cluster_linkage_metric) give the condensed matrix of
 * scipy.spatial.distance.pdist(x, metric); single linkage computes them on the fly.
 * Distances sum (x_j - y_j)^2 in 8 fixed lanes, then take sqrt: the order of
 * the sum is fixed by the code, so results are identical on every x86-64
 * whether or not the AVX2 clone runs.
 *
 * Flat clusters (labels 1..k, numbered as scipy.cluster.hierarchy.fcluster
 * numbers them: depth-first from the root, left before right):
 *   nl_cluster_fcluster_distance: 'distance' criterion, points in one cluster have
 *     cophenetic distance <= t (t >= 0);
 *   nl_cluster_fcluster_maxclust: the lowest cut that leaves at most k clusters
 *     ('maxclust'; ties in merge height can give fewer than k).
 */
#ifndef NL_CLUSTER_H
#define NL_CLUSTER_H

#include "base/nl_base.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
  NL_LINKAGE_SINGLE,
  NL_LINKAGE_COMPLETE,
  NL_LINKAGE_AVERAGE,
  NL_LINKAGE_WARD,
  NL_LINKAGE_WEIGHTED,   /* WPGMA: d = (d_ax + d_bx) / 2, on the chain */
  NL_LINKAGE_CENTROID,   /* Euclidean only; the generic algorithm (below) */
  NL_LINKAGE_MEDIAN      /* WPGMC; Euclidean only; the generic algorithm */
} nl_cluster_linkage_method;

/* scipy.spatial.distance.pdist's metrics (scipy's formulas and names). */
typedef enum {
  NL_METRIC_EUCLIDEAN,
  NL_METRIC_SQEUCLIDEAN,
  NL_METRIC_CITYBLOCK,
  NL_METRIC_CHEBYSHEV,
  NL_METRIC_COSINE,       /* 1 - u.v / (|u| |v|) */
  NL_METRIC_CORRELATION,  /* cosine of the centred rows */
  NL_METRIC_CANBERRA,     /* sum |u - v| / (|u| + |v|), 0/0 terms left out */
  NL_METRIC_BRAYCURTIS    /* sum |u - v| / sum |u + v| */
} nl_cluster_metric;

/* "single", "complete", "average", "ward", "weighted", "centroid", "median"
 * -> method; NL_EINVAL otherwise. */
nl_status nl_cluster_linkage_method_parse(const char *name, nl_cluster_linkage_method *m, nl_error *err);
const char *nl_cluster_linkage_method_name(nl_cluster_linkage_method m);
/* scipy's metric name -> metric; NL_EINVAL otherwise. */
nl_status nl_cluster_metric_parse(const char *name, nl_cluster_metric *m, nl_error *err);
const char *nl_cluster_metric_name(nl_cluster_metric m);

/* Euclidean distance between rows a and b of length d, and sum of squares
 * of a (summed in 8 fixed lanes: see above). */
double nl_cluster_euclidean(const double *a, const double *b, size_t d);
double nl_cluster_sumsq(const double *a, size_t d);

/* The largest distance between two points the linkages accept: squared
 * distances overflow to infinity past about 1.34e154, and Ward's update
 * squares cluster distances up to sqrt(n) times the largest point distance;
 * with 1e150 (squared 1e300) its three terms stay finite for any n whose
 * distance matrix fits in memory (n < 1e7: 3 x 1e7 x 1e300 < DBL_MAX). */
#define NL_CLUSTER_MAX_SPAN 1e150

/* Clusters n >= 2 points of dimension d >= 1 (finite values). Z has
 * (n - 1) * 4 doubles. NL_EINVAL if a value is not finite or the points'
 * bounding box has a diagonal above NL_CLUSTER_MAX_SPAN (rescale such data);
 * NL_ENOMEM if the distance matrix cannot be had. */
nl_status nl_cluster_linkage(const double *x, size_t n, size_t d, nl_cluster_linkage_method method,
                             double *Z, nl_error *err);
/* As nl_cluster_linkage with another metric: scipy.cluster.hierarchy.linkage(x,
 * method, metric). Ward, centroid and median need Euclidean (NL_EINVAL
 * otherwise, as scipy). NL_EINVAL, the first such pair named, where a
 * distance is not finite and scipy's linkage refuses: cosine with a zero row,
 * correlation with a constant row, Bray-Curtis of u and -u (or of two zero
 * rows). Coordinates too small to square (1e-200) give the true heights:
 * cosine and correlation rows, and Euclidean points spanning under 2^-400,
 * are scaled by powers of two first (exact; scipy's bits elsewhere). */
nl_status nl_cluster_linkage_metric(const double *x, size_t n, size_t d,
                                    nl_cluster_linkage_method method, nl_cluster_metric metric,
                                    double *Z, nl_error *err);

/* scipy.cluster.hierarchy.linkage(y, method) on a condensed distance matrix
 * y (scipy.spatial.distance.pdist's layout: the n(n-1)/2 entries i < j row
 * by row), taken as given: every method, ward, centroid and median reading
 * the distances as Euclidean ones, as scipy does. NL_EINVAL, the first
 * named, for a distance that is negative or not finite. */
nl_status nl_cluster_linkage_condensed(const double *y, size_t n, nl_cluster_linkage_method method,
                                       double *Z, nl_error *err);

/* labels: n ints, 1-based. *nclusters (may be NULL) receives k. */
nl_status nl_cluster_fcluster_distance(const double *Z, size_t n, double t, int *labels,
                                       size_t *nclusters, nl_error *err);
nl_status nl_cluster_fcluster_maxclust(const double *Z, size_t n, size_t k, int *labels,
                                       size_t *nclusters, nl_error *err);

#ifdef __cplusplus
}
#endif

#endif
