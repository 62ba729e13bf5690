/* libFuzzer target: the statistics `stat` runs on a table a user gives it,
 * with every option `stat` passes to them. The first four bytes pick the
 * options (below); the rest is the file, read as `stat` reads it (optional
 * header, blanks or commas). On a table read:
 *   hclust (nl_cluster.h): every linkage with every metric (ward, centroid
 *     and median refuse all but Euclidean), then flat clusters by count and
 *     by a cutoff; a linkage that succeeded must give finite, non-negative
 *     heights and valid merges, so the flat clusters must succeed, with
 *     every label in 1..k;
 *   gmm (nl_gmm.h): a fit of 1..4 components with each covariance type
 *     (full, diag, tied, spherical), few iterations (the cost of a unit, not
 *     EM's convergence, is bounded), a seed and reg_covar from the options,
 *     then an AIC selection from 1 up to that many components (`stat gmm
 *     --select-aic`): the selected model must be one of its path's;
 *   ks, kuiper and ks2 (nl_stats.h) on the first column, against the
 *     uniform on its range and against a distribution of `--dist` (each of
 *     scipy's names, shapes, loc and scale from the options) or `--cdf` (the
 *     table's first two columns as x and F), with each `--alternative`; and
 *     chisq on 2..9 equal bins of that range; a p-value must be in [0, 1].
 * Rows beyond MAX_ROWS are not clustered or fitted, and tables wider than
 * GMM_MAX_COLS are not fitted: a unit stays well under a second (hclust is
 * O(n^2) in time and memory, a full covariance's Cholesky O(d^3)).
 *
 * A table of at most ALL_PAIRS_ROWS rows is clustered with every linkage
 * and metric (56 small linkages cost about what one of 300 rows does), so
 * that every pair is reached whatever the corpus keeps; a larger one with
 * the linkage and metric of the options.
 *
 * Option bytes: o0 bits 0-2 linkage (single, complete, average, ward,
 * weighted, centroid, median; 7 is single), bits 3-5 metric (euclidean,
 * sqeuclidean, cityblock, chebyshev, cosine, correlation, canberra,
 * braycurtis); o1 bits 0-1 gmm components - 1, bits 2-3 covariance, bits
 * 4-6 the number of flat clusters asked for (1..8), one less than chisq's
 * bins, bit 7 the gmm seed (0 or 1); o2 bits 0-1 the ks alternative
 * (two-sided, less, greater; 3 is two-sided), bits 2-5 the distribution
 * (nl_stats_dist_kind; 14, the table, takes --cdf; 15 none), bits 6-7
 * reg_covar (1e-6, 0, 1e-300, 1); o3 bits 0-2 and 3-5 the two shapes, bits
 * 6-7 the scale, each from a few values (the smallest subnormal to 1e300). */
#include "stats/nl_cluster.h"
#include "stats/nl_gmm.h"
#include "stats/nl_stats.h"
#include "table/nl_table.h"
#include "nl_fuzz.h"

#include <math.h>

enum { MAX_ROWS = 300, ALL_PAIRS_ROWS = 16, GMM_MAX_COLS = 16, GMM_ITER = 10 };

static void check_p(const char *what, double p)
{
  if (!(p >= 0.0 && p <= 1.0)) {
    fprintf(stderr, "nl_fuzz: %s p-value %g outside [0, 1]\n", what, p);
    abort();
  }
}

static void fuzz_hclust(const double *x, size_t n, size_t d, int method, int metric, size_t k)
{
  nl_error err = {{0}};
  double *Z = nl_xmalloc((n - 1) * 4 * sizeof *Z);
  int *lab = nl_xmalloc(n * sizeof *lab);
  nl_status st = nl_cluster_linkage_metric(x, n, d, (nl_cluster_linkage_method)method,
                                           (nl_cluster_metric)metric, Z, &err);
  nl_fuzz_check_error(st, &err);
  if (st == NL_OK) {
    for (size_t i = 0; i + 1 < n; i++)
      if (!(Z[4 * i + 2] >= 0.0 && isfinite(Z[4 * i + 2]))) {
        fprintf(stderr, "nl_fuzz: %s linkage, %s metric: merge %zu of %zu points at height %g\n",
                nl_cluster_linkage_method_name((nl_cluster_linkage_method)method),
                nl_cluster_metric_name((nl_cluster_metric)metric), i + 1, n, Z[4 * i + 2]);
        abort();
      }
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

static void fuzz_gmm(const double *x, size_t n, size_t d, size_t k, int covariance, unsigned long seed,
                     double reg_covar)
{
  nl_gmm_options o;
  nl_gmm_options_default(&o);
  o.covariance = (nl_gmm_covariance)covariance;
  o.max_iter = GMM_ITER;
  o.seed = seed;
  o.reg_covar = reg_covar;
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

/* The values --shape and --scale are fuzzed with: the smallest subnormal,
 * the smallest normal, ordinary ones and the largest `stat` accepts. */
static const double shape_values[8] = {4.9406564584124654e-324, 2.2250738585072014e-308, 1e-8,
                                       0.5, 1.0, 2.5, 1e8, 1e300};

/* ks (with the alternative), kuiper against a named distribution or a
 * tabulated CDF; a refused distribution is fine (with a one-line message). */
static void fuzz_dist(const double *x, size_t n, const nl_table *t, int kind, int alt, int o3)
{
  nl_stats_dist dist;
  nl_error err = {{0}};
  nl_status st;
  double *xF = NULL;
  if (kind == NL_DIST_TABLE) {
    if (t->ncols < 2) return;
    xF = nl_xmalloc(2 * t->nrows * sizeof *xF);
    for (size_t i = 0; i < t->nrows; i++) {
      xF[i] = nl_table_get(t, i, 0);
      xF[t->nrows + i] = nl_table_get(t, i, 1);
    }
    st = nl_stats_dist_table(&dist, xF, xF + t->nrows, t->nrows, &err);
  } else {
    double shape[2] = {shape_values[o3 & 7], shape_values[(o3 >> 3) & 7]};
    double scale = shape_values[3 + ((o3 >> 6) & 3)], loc = x[0];
    int ns = nl_stats_dist_nshape((nl_stats_dist_kind)kind);
    st = ns ? nl_stats_dist_init_shape(&dist, (nl_stats_dist_kind)kind, shape, (size_t)ns, loc, scale, &err)
            : nl_stats_dist_init(&dist, (nl_stats_dist_kind)kind, loc, scale, &err);
  }
  nl_fuzz_check_error(st, &err);
  if (st == NL_OK) {
    nl_stats_ks_result r;
    st = nl_stats_ks_test(x, n, nl_stats_dist_cdf, &dist, &r, &err);
    nl_fuzz_check_error(st, &err);
    if (st == NL_OK) {
      nl_stats_ks_one_sided(&r, (nl_stats_ks_alternative)alt);
      check_p("ks dist", r.p);
    }
    nl_stats_kuiper_result kr;
    st = nl_stats_kuiper_test(x, n, nl_stats_dist_cdf, &dist, &kr, &err);
    nl_fuzz_check_error(st, &err);
    if (st == NL_OK) check_p("kuiper dist", kr.p);
  }
  free(xF);
}

static void fuzz_ks(const double *x, size_t n, size_t bins, int alt)
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
  if (st == NL_OK) {
    nl_stats_ks_one_sided(&r, (nl_stats_ks_alternative)alt);
    check_p("ks uniform", r.p);
  }
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
    if (st == NL_OK) {
      nl_stats_ks_one_sided(&r, (nl_stats_ks_alternative)alt);
      check_p("ks2", r.p);
    }
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
  if (size < 4) return 0;
  int o0 = data[0], o1 = data[1], o2 = data[2], o3 = data[3];
  const char *path = nl_fuzz_file(data + 4, size - 4, "tsv");
  nl_table *t = NULL;
  nl_error err = {{0}};
  int flags = NL_TABLE_HEADER_AUTO | NL_TABLE_WHITESPACE | NL_TABLE_CSV_AUTO;
  nl_status st = nl_table_read(path, flags, &t, &err);
  nl_fuzz_check_error(st, &err);
  if (st != NL_OK) return 0;
  size_t n = t->nrows < MAX_ROWS ? t->nrows : MAX_ROWS, d = t->ncols;
  int alt = (o2 & 3) % 3, kind = (o2 >> 2) & 15;
  static const double reg_values[4] = {1e-6, 0.0, 1e-300, 1.0};
  double *col = nl_xmalloc(t->nrows * sizeof *col);
  for (size_t i = 0; i < t->nrows; i++) col[i] = nl_table_get(t, i, 0);
  fuzz_ks(col, t->nrows, (size_t)((o1 >> 4) & 7) + 2, alt);
  if (kind <= NL_DIST_TABLE) fuzz_dist(col, t->nrows, t, kind, alt, o3);
  free(col);
  size_t k = (size_t)((o1 >> 4) & 7) + 1;
  if (n >= 2 && n <= ALL_PAIRS_ROWS) {
    for (int m = 0; m < 7; m++)
      for (int metric = 0; metric < 8; metric++) fuzz_hclust(t->num, n, d, m, metric, k);
  } else if (n >= 2) {
    fuzz_hclust(t->num, n, d, (o0 & 7) % 7, (o0 >> 3) & 7, k);
  }
  if (d <= GMM_MAX_COLS)
    fuzz_gmm(t->num, n, d, (size_t)(o1 & 3) + 1, (o1 >> 2) & 3, (unsigned long)(o1 >> 7),
             reg_values[(o2 >> 6) & 3]);
  nl_table_free(t);
  return 0;
}
