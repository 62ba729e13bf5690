/* Tests of nl_gmm.h against scikit-learn 1.2 GaussianMixture started from the
 * same k-means labels (tests/reference/make_stats_vectors.py: 750 points in
 * 4-D from 3 correlated Gaussians; k = 1..4, full, diagonal, tied and spherical).
 * Tolerances: log-likelihood, AIC, BIC 1e-8 relative (EM from the same
 * responsibilities; only rounding differs); iteration count and converged
 * flag exact; k = 3 weights and means 1e-6 absolute (data scale ~5), and
 * predict's labels equal sklearn's on every row up to renaming the components.
 */
#include "stats/nl_gmm.h"
#include "nl_test.h"
#include "test_vectors.h"

#include <string.h>
#include <sys/resource.h>

static int *load_labels(size_t k, size_t n)
{
  char name[64];
  snprintf(name, sizeof name, "gmm_labels_k%zu.tsv", k);
  nl_table *t = vec_read(name);
  int *lab = nl_xmalloc(n * sizeof(int));
  for (size_t i = 0; i < n; i++) lab[i] = (int)nl_table_get(t, i, 0);
  nl_table_free(t);
  return lab;
}

/* nl_gmm_predict's labels against sklearn's predict, up to a renaming of
 * the components (one-to-one): every row must agree. */
static int predict_matches(const nl_gmm *g, const double *x, size_t n, const char *file)
{
  nl_table *t = vec_read(file);
  int *lab = nl_xmalloc(n * sizeof(int)), map[64], back[64], ok = t->nrows == n;
  for (int c = 0; c < 64; c++) map[c] = back[c] = -1;
  ok = ok && nl_gmm_predict(g, x, n, lab, NULL) == NL_OK;
  for (size_t i = 0; i < n && ok; i++) {
    int a = lab[i], b = (int)nl_table_get(t, i, 0);
    if (map[a] < 0 && back[b] < 0) { map[a] = b; back[b] = a; }
    ok = map[a] == b && back[b] == a;
  }
  free(lab);
  nl_table_free(t);
  return ok;
}

NL_TEST(em_matches_sklearn_from_same_labels)
{
  size_t n, d;
  double *x = vec_matrix("gmm_X.tsv", &n, &d);
  nl_table *t = vec_read("gmm_fit.tsv");
  for (size_t r = 0; r < t->nrows; r++) {
    size_t k = (size_t)vec_get(t, r, "k");
    nl_gmm_options o;
    nl_gmm_options_default(&o);
    NL_CHECK(nl_gmm_covariance_parse(vec_text(t, r, "covariance"), &o.covariance, NULL) == NL_OK);
    int *lab = load_labels(k, n);
    o.init_labels = lab;
    nl_gmm *g = nl_gmm_alloc(k, d, o.covariance);
    nl_error err;
    NL_CHECK(nl_gmm_fit(g, x, n, &o, &err) == NL_OK);
    NL_CHECK(vec_close(g->loglik, vec_get(t, r, "loglik"), 1e-8, 0));
    NL_CHECK(vec_close(g->aic, vec_get(t, r, "aic"), 1e-8, 0));
    NL_CHECK(vec_close(g->bic, vec_get(t, r, "bic"), 1e-8, 0));
    NL_CHECK(g->iterations == (size_t)vec_get(t, r, "iterations"));
    NL_CHECK(g->converged == (int)vec_get(t, r, "converged"));
    if (k == 3) {
      char name[64];
      snprintf(name, sizeof name, "gmm_params_k3_%s.tsv", vec_text(t, r, "covariance"));
      nl_table *p = vec_read(name);
      for (size_t c = 0; c < k; c++) {
        NL_CHECK_NEAR(g->weights[c], nl_table_get(p, c, 0), 1e-6);
        for (size_t j = 0; j < d; j++) NL_CHECK_NEAR(g->means[c * d + j], nl_table_get(p, c, 1 + j), 1e-6);
      }
      nl_table_free(p);
      snprintf(name, sizeof name, "gmm_predict_k3_%s.tsv", vec_text(t, r, "covariance"));
      NL_CHECK(predict_matches(g, x, n, name));
    }
    nl_gmm_free(g);
    free(lab);
  }
  nl_table_free(t);
  free(x);
}

NL_TEST(kmeans_init_sampling_and_selection)
{
  /* sample 3000 points from a known 3-component mixture, refit from
   * k-means++: the fit must recover weights, and AIC selection must stop at 3 */
  nl_gmm *truth = nl_gmm_alloc(3, 2, NL_GMM_FULL);
  double w[] = {0.5, 0.3, 0.2}, mu[] = {0, 0, 8, 0, 0, 8};
  double cov[] = {1, 0.5, 0.5, 1, 1, 0, 0, 0.25, 0.5, -0.2, -0.2, 1};
  memcpy(truth->weights, w, sizeof w);
  memcpy(truth->means, mu, sizeof mu);
  for (int k = 0; k < 3; k++) {   /* 2x2 Cholesky by hand */
    double *c = cov + 4 * k, *L = truth->chol + 4 * k;
    L[0] = sqrt(c[0]); L[1] = 0; L[2] = c[2] / L[0]; L[3] = sqrt(c[3] - L[2] * L[2]);
  }
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  size_t n = 3000;
  double *x = nl_xmalloc(n * 2 * sizeof(double));
  nl_gmm_sample(truth, rng, n, x, NULL);
  nl_gmm_options o;
  nl_gmm_options_default(&o);
  o.seed = 5;
  nl_gmm *best;
  nl_gmm_step path[8];
  size_t np;
  NL_CHECK(nl_gmm_select_aic(x, n, 2, 1, 10.0, 8, &o, &best, path, &np, NULL) == NL_OK);
  NL_CHECK(best && best->k == 3 && np == 4);
  double wsum = 0, wmin = 1;
  for (size_t k = 0; best && k < best->k; k++) { wsum += best->weights[k]; wmin = fmin(wmin, best->weights[k]); }
  NL_CHECK_NEAR(wsum, 1.0, 1e-12);
  NL_CHECK(fabs(wmin - 0.2) < 0.03);
  for (size_t i = 1; i < np; i++) NL_CHECK(path[i].k == path[i - 1].k + 1);
  nl_gmm_free(best);
  nl_gmm_free(truth);
  free(x);
  gsl_rng_free(rng);
}

NL_TEST(constant_column_stays_finite_and_bad_input_fails)
{
  double x[40];
  for (int i = 0; i < 20; i++) { x[2 * i] = i % 7; x[2 * i + 1] = 3.0; }
  nl_gmm_options o;
  nl_gmm_options_default(&o);
  nl_gmm *g = nl_gmm_alloc(2, 2, NL_GMM_FULL);
  nl_error err;
  NL_CHECK(nl_gmm_fit(g, x, 20, &o, &err) == NL_OK);
  NL_CHECK(isfinite(g->loglik) && isfinite(g->aic));
  NL_CHECK(fabs(g->covs[3] - 1e-6) < 1e-9);   /* the constant column's variance is reg_covar */
  nl_gmm_free(g);
  g = nl_gmm_alloc(30, 2, NL_GMM_FULL);
  NL_CHECK(nl_gmm_fit(g, x, 20, &o, &err) == NL_EINVAL && strstr(err.msg, "components"));
  nl_gmm_free(g);
  g = nl_gmm_alloc(2, 2, NL_GMM_FULL);
  o.reg_covar = 0.0;
  NL_CHECK(nl_gmm_fit(g, x, 20, &o, &err) == NL_ENUM && strstr(err.msg, "positive definite"));
  /* `stat gmm`'s ranges: an infinite tol would stop EM after one step */
  o.reg_covar = 1e-6;
  o.tol = INFINITY;
  NL_CHECK(nl_gmm_fit(g, x, 20, &o, &err) == NL_EINVAL && !strcmp(err.msg, "--tol: inf is not a finite number"));
  o.tol = 1e-3;
  o.reg_covar = -1;
  NL_CHECK(nl_gmm_fit(g, x, 20, &o, &err) == NL_EINVAL && !strncmp(err.msg, "--reg-covar: -1 is outside", 26));
  o.reg_covar = 1e-6;
  o.max_iter = (size_t)NL_GMM_MAX_ITER + 1;
  NL_CHECK(nl_gmm_fit(g, x, 20, &o, &err) == NL_EINVAL && !strncmp(err.msg, "--max-iter: ", 12));
  o.max_iter = 100;
  x[5] = NAN;
  NL_CHECK(nl_gmm_fit(g, x, 20, &o, &err) == NL_EINVAL);
  nl_gmm_free(g);
}

/* EM's steps on threads (o.threads): the same bytes as one thread, on 3000
 * rows (three E-step blocks) of the 750-point vectors repeated, k = 4. */
NL_TEST(threads_give_the_same_fit)
{
  size_t n, d;
  double *x0 = vec_matrix("gmm_X.tsv", &n, &d);
  double *x = nl_xmalloc(4 * n * d * sizeof(double));
  for (int r = 0; r < 4; r++)
    for (size_t i = 0; i < n * d; i++) x[r * n * d + i] = x0[i] + 1e-3 * r;
  nl_gmm *g[2];
  for (int t = 0; t < 2; t++) {
    nl_gmm_options o;
    nl_gmm_options_default(&o);
    o.seed = 3;
    o.threads = t ? 3 : 1;
    g[t] = nl_gmm_alloc(4, d, NL_GMM_FULL);
    NL_CHECK(nl_gmm_fit(g[t], x, 4 * n, &o, NULL) == NL_OK);
  }
  NL_CHECK(g[0]->loglik == g[1]->loglik && g[0]->iterations == g[1]->iterations);
  NL_CHECK(!memcmp(g[0]->means, g[1]->means, 4 * d * sizeof(double)));
  NL_CHECK(!memcmp(g[0]->covs, g[1]->covs, 4 * d * d * sizeof(double)));
  nl_gmm_free(g[0]); nl_gmm_free(g[1]);
  free(x); free(x0);
}

NL_TEST(gmm_size_checked_against_memory)
{
  nl_error err = {{0}};
  NL_CHECK(nl_gmm_check_size(100, 3, 2, NL_GMM_FULL, &err) == NL_OK);
  NL_CHECK(nl_gmm_check_size(200000, 30000, 100, NL_GMM_FULL, &err) == NL_ENOMEM);
  NL_CHECK(strstr(err.msg, "200000 rows of 30000 columns with 100 components need") != NULL);
  NL_CHECK(strstr(err.msg, "is available") != NULL);
}

/* The memo of fits (o.memo): paths from K0 = 1 and K0 = 2 on the same rows
 * give the same path entries and selected model, bytes for bytes, as
 * without it, and the second path takes its overlap from the memo. */
NL_TEST(memo_gives_the_same_paths)
{
  size_t n, d;
  double *x = vec_matrix("gmm_X.tsv", &n, &d);
  nl_gmm_options o;
  nl_gmm_options_default(&o);
  o.seed = 3;
  nl_gmm_memo *memo = nl_gmm_memo_alloc();
  for (size_t k0 = 1; k0 <= 2; k0++) {
    nl_gmm *a, *b;
    nl_gmm_step pa[6], pb[6];
    size_t na, nb;
    o.memo = NULL;
    NL_CHECK(nl_gmm_select_aic(x, n, d, k0, 0.0, 5, &o, &a, pa, &na, NULL) == NL_OK);
    o.memo = memo;
    NL_CHECK(nl_gmm_select_aic(x, n, d, k0, 0.0, 5, &o, &b, pb, &nb, NULL) == NL_OK);
    NL_CHECK(na == nb);
    for (size_t i = 0; i < na && i < nb; i++)   /* field by field: the struct has padding */
      NL_CHECK(pa[i].k == pb[i].k && pa[i].loglik == pb[i].loglik && pa[i].aic == pb[i].aic &&
               pa[i].bic == pb[i].bic && pa[i].iterations == pb[i].iterations && pa[i].converged == pb[i].converged);
    NL_CHECK(a && b && a->k == b->k && a->loglik == b->loglik);
    NL_CHECK(a && b && !memcmp(a->means, b->means, a->k * d * sizeof(double)) &&
             !memcmp(a->covs, b->covs, a->k * d * d * sizeof(double)) &&
             !memcmp(a->prec, b->prec, a->k * d * d * sizeof(double)));
    nl_gmm_free(a);
    nl_gmm_free(b);
  }
  size_t fitted, reused;
  nl_gmm_memo_counts(memo, &fitted, &reused);
  NL_CHECK(reused >= 1 && fitted >= 1);
  nl_gmm_memo_free(memo);
  free(x);
}

static long minor_faults(void)
{
  struct rusage r;
  getrusage(RUSAGE_SELF, &r);
  return r.ru_minflt;
}

/* Freed K d^2 arrays serve the next models instead of fresh pages when
 * the models come from a workspace: eight full models of 2 x 512^2 (24
 * arrays of 4.2 MB, about what two threads' AIC paths and the memo's
 * models hold at once) freed and allocated again fault in almost no page:
 * fewer than 40 (the small arrays take a few, under ASan 28) or a quarter
 * of the first pass's (each pass makes the models and writes every page). A cache of 8 arrays would miss 16 of the 24,
 * two thirds of the first faults. Without a workspace nothing is kept
 * (no process-wide cache): the second pass faults its pages in again, at
 * least half the first pass's. */
NL_TEST(freed_arrays_serve_the_next_models)
{
  enum { NM = 8 };
  nl_gmm *g[NM];
  nl_gmm_workspace *w = nl_gmm_workspace_alloc();
  for (int with = 0; with < 2; with++) {
    long faults[2];
    for (int pass = 0; pass < 2; pass++) {
      long f0 = minor_faults();
      for (int i = 0; i < NM; i++) {   /* made and used: every page written once */
        g[i] = nl_gmm_alloc_workspace(2, 512, NL_GMM_FULL, with ? w : NULL);
        for (size_t j = 0; j < (size_t)2 * 512 * 512; j += 512)
          g[i]->covs[j] = g[i]->chol[j] = g[i]->prec[j] = 1.0;
      }
      faults[pass] = minor_faults() - f0;
      for (int i = 0; i < NM; i++) nl_gmm_free(g[i]);
    }
    if (with) NL_CHECK(faults[1] < 40 || 4 * faults[1] < faults[0]);
    else NL_CHECK(2 * faults[1] >= faults[0] && faults[0] >= 48);
  }
  NL_CHECK(nl_gmm_workspace_bytes(w) >= (size_t)24 * 4 * 512 * 512 * sizeof(double) / 2);
  nl_gmm_workspace_free(w);
  NL_CHECK(nl_gmm_workspace_bytes(NULL) == 0);
}

int main(void) { return nl_test_run(); }
