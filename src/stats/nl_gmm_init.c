/* nl_gmm_init.c - EM's starting labels: k-means++ seeding (Arthur &
 * Vassilvitskii 2007) and Lloyd iterations, as scikit-learn's KMeans
 * initialises GaussianMixture. */
#include "stats/nl_gmm_internal.h"
#include "stats/nl_stats_gsl.h"
#include "stats/nl_cluster.h"

#include <float.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_randist.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- initialisation: k-means++ and Lloyd ------------------------------------ */

/* Squared distances of every row to every centre, D = |x|^2 - 2 X C^T + |c|^2
 * (dgemm; only used to pick the nearest centre). */
static void sq_dists(const double *x, size_t n, size_t d, const double *c, size_t K,
                     const double *xx, double *D)
{
  gsl_matrix_const_view Xv = gsl_matrix_const_view_array(x, n, d);
  gsl_matrix_const_view Cv = gsl_matrix_const_view_array(c, K, d);
  gsl_matrix_view Dv = gsl_matrix_view_array(D, n, K);
  gsl_blas_dgemm(CblasNoTrans, CblasTrans, -2.0, &Xv.matrix, &Cv.matrix, 0.0, &Dv.matrix);
  for (size_t k = 0; k < K; k++) {
    double cc = 0.0;
    for (size_t j = 0; j < d; j++) cc += c[k * d + j] * c[k * d + j];
    for (size_t i = 0; i < n; i++) D[i * K + k] += xx[i] + cc;
  }
}

/* k-means++ seeding: each new centre is a row drawn with probability
 * proportional to its squared distance to the nearest centre so far. */
static void kmeanspp(const double *x, size_t n, size_t d, size_t K, gsl_rng *rng, double *c)
{
  double *dmin = nl_xmalloc(n * sizeof(double)), total = 0.0;
  size_t first = gsl_rng_uniform_int(rng, n);
  memcpy(c, x + first * d, d * sizeof(double));
  for (size_t i = 0; i < n; i++) {
    double s = 0.0;
    for (size_t j = 0; j < d; j++) s += (x[i * d + j] - c[j]) * (x[i * d + j] - c[j]);
    dmin[i] = s;
  }
  for (size_t k = 1; k < K; k++) {
    total = 0.0;
    for (size_t i = 0; i < n; i++) total += dmin[i];
    double r = gsl_rng_uniform(rng) * total;
    size_t pick = n - 1;
    for (size_t i = 0; i < n; i++) { r -= dmin[i]; if (r < 0.0) { pick = i; break; } }
    if (total <= 0.0) pick = gsl_rng_uniform_int(rng, n);   /* all points on centres */
    memcpy(c + k * d, x + pick * d, d * sizeof(double));
    for (size_t i = 0; i < n; i++) {
      double s = 0.0;
      for (size_t j = 0; j < d; j++) s += (x[i * d + j] - c[k * d + j]) * (x[i * d + j] - c[k * d + j]);
      dmin[i] = fmin(dmin[i], s);
    }
  }
  free(dmin);
}

/* Lloyd's k-means from k-means++ seeds; stops when no label changes or
 * after 300 iterations (sklearn's max_iter). Writes labels. */
void gmm_kmeans_labels(const double *x, size_t n, size_t d, size_t K, unsigned long seed,
                          int *labels)
{
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(seed, "gmm.kmeans", 0));
  double *c = nl_xmalloc(K * d * sizeof(double)), *D = nl_xmalloc(n * K * sizeof(double));
  double *xx = nl_xmalloc(n * sizeof(double)), *cnt = nl_xmalloc(K * sizeof(double));
  double *old = nl_xmalloc(K * d * sizeof(double));
  for (size_t i = 0; i < n; i++) {
    xx[i] = 0.0;
    for (size_t j = 0; j < d; j++) xx[i] += x[i * d + j] * x[i * d + j];
    labels[i] = -1;
  }
  kmeanspp(x, n, d, K, rng, c);
  for (int it = 0; it < 300; it++) {
    sq_dists(x, n, d, c, K, xx, D);
    size_t changed = 0;
    for (size_t i = 0; i < n; i++) {
      size_t best = 0;
      for (size_t k = 1; k < K; k++) if (D[i * K + k] < D[i * K + best]) best = k;
      changed += labels[i] != (int)best;
      labels[i] = (int)best;
    }
    if (!changed) break;
    memset(cnt, 0, K * sizeof(double));
    memcpy(old, c, K * d * sizeof(double));
    memset(c, 0, K * d * sizeof(double));
    for (size_t i = 0; i < n; i++) {
      cnt[labels[i]] += 1.0;
      for (size_t j = 0; j < d; j++) c[labels[i] * d + j] += x[i * d + j];
    }
    for (size_t k = 0; k < K; k++)   /* an emptied cluster keeps its centre */
      for (size_t j = 0; j < d; j++) c[k * d + j] = cnt[k] > 0 ? c[k * d + j] / cnt[k] : old[k * d + j];
  }
  free(c); free(D); free(xx); free(cnt); free(old);
  gsl_rng_free(rng);
}

