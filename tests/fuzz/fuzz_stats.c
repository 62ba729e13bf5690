/* libFuzzer target: the statistics `stat` runs on a table a user gives it.
 * The first byte picks the options (below); the rest is the file, read as
 * `stat` reads it (optional header, blanks or commas). On a table read:
 *   hclust (nl_cluster.h): linkage, then flat clusters by count and by a
 *     cutoff; a linkage that succeeded must give valid merges, so the flat
 *     clusters must succeed, with every label in 1..k;
 *   gmm (nl_gmm.h): a fit of 1..4 components, full or diagonal, few
 *     iterations (the cost of a unit, not EM's convergence, is bounded),
 *     then an AIC selection from 1 up to that many components (`stat gmm
 *     --select-aic`): the selected model must be one of its path's;
 *   ks, kuiper and ks2 (nl_stats.h) on the first column, against the
 *     uniform on its range and a normal, and chisq on 2..9 equal bins of
 *     that range; a p-value must be in [0, 1].
 * Rows beyond MAX_ROWS are not clustered or fitted, and tables wider than
 * GMM_MAX_COLS are not fitted: a unit stays well under a second (hclust is
 * O(n^2) in time and memory, a full covariance's Cholesky O(d^3)).
 *
 * Option byte: bits 0-1 linkage (single, complete, average, ward), bits 2-3
 * gmm components - 1, bit 4 diagonal covariance, bits 5-7 the number of
 * flat clusters asked for (1..8), one less than chisq's bins. */
#include "stats/nl_cluster.h"
#include "stats/nl_gmm.h"
#include "stats/nl_stats.h"
#include "table/nl_table.h"
#include "nl_fuzz.h"

#include <math.h>

enum { MAX_ROWS = 300, GMM_MAX_COLS = 16, GMM_ITER = 10 };

static void check_p(const char *what, double p)
{
  if (!(p >= 0.0 && p <= 1.0)) {
    fprintf(stderr, "nl_fuzz: %s p-value %g outside [0, 1]\n", what, p);
    abort();
  }
}

static void fuzz_hclust(const double *x, size_t n, size_t d, int method, size_t k)
{
  nl_error err = {{0}};
  double *Z = nl_xmalloc((n - 1) * 4 * sizeof *Z);
  int *lab = nl_xmalloc(n * sizeof *lab);
  nl_status st = nl_cluster_linkage(x, n, d, (nl_cluster_linkage_method)method, Z, &err);
  nl_fuzz_check_error(st, &err);
  if (st == NL_OK) {
    size_t got;
    for (int pass = 0; pass < 2; pass++) {
      /* the second pass cuts at the median merge height */
      double median = Z[4 * ((n - 1) / 2) + 2];
      st = pass == 0 ? nl_cluster_fcluster_maxclust(Z, n, k, lab, &got, &err)
                     : nl_cluster_fcluster_distance(Z, n, median, lab, &got, &err);
      if (st != NL_OK) {
        fprintf(stderr, "nl_fuzz: a linkage of %zu points gave merges fcluster refuses: %s\n",
                n, err.msg);
        abort();
      }
      for (size_t i = 0; i < n; i++)
        if (lab[i] < 1 || (size_t)lab[i] > got) {
          fprintf(stderr, "nl_fuzz: point %zu has label %d of %zu clusters\n", i, lab[i], got);
          abort();
        }
    }
  }
  free(Z);
  free(lab);
}

static void fuzz_gmm(const double *x, size_t n, size_t d, size_t k, int diag)
{
  nl_gmm_options o;
  nl_gmm_options_default(&o);
  o.covariance = diag ? NL_GMM_DIAG : NL_GMM_FULL;
  o.max_iter = GMM_ITER;
  nl_error err = {{0}};
  if (k > n) k = n;
  nl_status st = nl_gmm_check_size(n, d, k, o.covariance, &err);
  nl_fuzz_check_error(st, &err);
  if (st) return;
  nl_gmm *g = nl_gmm_alloc(k, d, o.covariance);
  st = nl_gmm_fit(g, x, n, &o, &err);
  nl_fuzz_check_error(st, &err);
  if (st == NL_OK) {
    double w = 0;
    for (size_t j = 0; j < k; j++) w += g->weights[j];
    if (!(fabs(w - 1.0) < 1e-9)) {
      fprintf(stderr, "nl_fuzz: gmm weights sum to %.17g\n", w);
      abort();
    }
  }
  nl_gmm_free(g);
  nl_gmm_step path[4];
  size_t np = 0;
  g = NULL;
  st = nl_gmm_select_aic(x, n, d, 1, 0.0, k, &o, &g, path, &np, &err);
  nl_fuzz_check_error(st, &err);
  if (st == NL_OK) {
    int found = 0;
    for (size_t i = 0; i < np; i++) found |= g && path[i].k == g->k;
    if (!found || np < 1 || np > k) {
      fprintf(stderr, "nl_fuzz: AIC selection of %zu models did not select one of them\n", np);
      abort();
    }
  } else if (g) {
    fprintf(stderr, "nl_fuzz: a failed AIC selection returned a model\n");
    abort();
  }
  nl_gmm_free(g);
}

static void fuzz_ks(const double *x, size_t n, size_t bins)
{
  nl_error err = {{0}};
  double lo = x[0], hi = x[0];
  for (size_t i = 1; i < n; i++) {
    lo = fmin(lo, x[i]);
    hi = fmax(hi, x[i]);
  }
  nl_stats_ks_result r;
  nl_status st = nl_stats_ks_test_uniform(x, n, lo, hi, &r, &err);
  nl_fuzz_check_error(st, &err);
  if (st == NL_OK) check_p("ks uniform", r.p);
  nl_stats_dist dist;
  if (nl_stats_dist_init(&dist, NL_DIST_NORM, 0.0, 1.0, &err) != NL_OK) abort();
  st = nl_stats_ks_test(x, n, nl_stats_dist_cdf, &dist, &r, &err);
  nl_fuzz_check_error(st, &err);
  if (st == NL_OK) check_p("ks norm", r.p);
  nl_stats_kuiper_result kr;
  st = nl_stats_kuiper_test_uniform(x, n, lo, hi, &kr, &err);
  nl_fuzz_check_error(st, &err);
  if (st == NL_OK) check_p("kuiper", kr.p);
  if (n >= 2) {
    st = nl_stats_ks2_test(x, n / 2, x + n / 2, n - n / 2, &r, &err);
    nl_fuzz_check_error(st, &err);
    if (st == NL_OK) check_p("ks2", r.p);
  }
  nl_stats_chisq_result cr;
  st = nl_stats_chisq_test_uniform(x, n, bins, lo, hi, &cr, &err);
  nl_fuzz_check_error(st, &err);
  if (st == NL_OK) check_p("chisq", cr.p);
  if (st == NL_OK && cr.n != n) {
    fprintf(stderr, "nl_fuzz: chisq binned %zu of %zu values\n", cr.n, n);
    abort();
  }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  if (size < 1) return 0;
  int opt = data[0];
  const char *path = nl_fuzz_file(data + 1, size - 1, "tsv");
  nl_table *t = NULL;
  nl_error err = {{0}};
  int flags = NL_TABLE_HEADER_AUTO | NL_TABLE_WHITESPACE | NL_TABLE_CSV_AUTO;
  nl_status st = nl_table_read(path, flags, &t, &err);
  nl_fuzz_check_error(st, &err);
  if (st != NL_OK) return 0;
  size_t n = t->nrows < MAX_ROWS ? t->nrows : MAX_ROWS, d = t->ncols;
  double *col = nl_xmalloc(t->nrows * sizeof *col);
  for (size_t i = 0; i < t->nrows; i++) col[i] = nl_table_get(t, i, 0);
  fuzz_ks(col, t->nrows, (size_t)(opt >> 5) + 2);
  free(col);
  if (n >= 2) fuzz_hclust(t->num, n, d, opt & 3, (size_t)(opt >> 5) + 1);
  if (d <= GMM_MAX_COLS) fuzz_gmm(t->num, n, d, (size_t)((opt >> 2) & 3) + 1, (opt >> 4) & 1);
  nl_table_free(t);
  return 0;
}
