/* naive_linkage.h - agglomerative clustering by its definition, O(n^3), as
 * a test oracle for src/stats/nl_cluster.c.
 *
 * At every step every pair of current clusters is scored from the points
 * themselves, not from a distance matrix updated by Lance-Williams:
 *   single    the smallest distance between a point of A and one of B
 *   complete  the largest
 *   average   the mean of the |A| |B| distances (UPGMA)
 *   ward      sqrt(2 (ESS(A u B) - ESS(A) - ESS(B))) written as
 *             sqrt(2 |A| |B| / (|A| + |B|)) |c_A - c_B|, c the centroids
 *             (Ward 1963: the increase of the within-cluster sum of squares),
 *             the centroids summed relative to the first point (the
 *             formula is translation-free; coordinates far from 0 keep
 *             their digits)
 * and the closest pair merges (the first in (a, b) order on equal scores).
 * Distances are sqrt(sum_j (x_j - y_j)^2) summed in j order. Row i of Z is
 * {a, b, height, size} with a < b, the points 0..n-1 and the cluster of row
 * j numbered n + j: scipy's linkage matrix. The four linkages are monotone,
 * so the merges come in order of height and no sorting is needed.
 */
#ifndef NAIVE_LINKAGE_H
#define NAIVE_LINKAGE_H

#include <stddef.h>

enum { NAIVE_SINGLE, NAIVE_COMPLETE, NAIVE_AVERAGE, NAIVE_WARD };

/* x: n rows of d, row-major; Z: 4 (n - 1) doubles. *gap (may be NULL)
 * gets the smallest relative margin, over the merges, between the pair
 * that merged and the next closest pair: near 0 means a near-tie whose order
 * rounding may decide. */
void naive_linkage(const double *x, size_t n, size_t d, int method, double *Z, double *gap);

#endif
