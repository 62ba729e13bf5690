/* The model of the solution pool (Cheng sec. 3.5.2-3.5.3): circular
 * representation, complete-linkage clustering for the initial K, Gaussian
 * mixture by EM with the AIC rule, and reproduction by sampling (readings in
 * nl_cheng_repro.h). */
#include "cheng/nl_cheng_internal.h"
#include "stats/nl_cluster.h"

#include <gsl/gsl_randist.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- representation ----------------------------------------------------- */

size_t nl_cheng_rep_dim(nl_cheng_rep rep, size_t nlow) { return rep == NL_CHENG_REP_COSSIN ? 2 * nlow : nlow; }

/* mu_j opposite the middle of the widest empty arc of column j: unwrapping
 * around it cuts where the pool has no angles (a cut opposite the circular
 * mean splits clusters when the column spans much of the circle). */
void nl_cheng_circular_centre(const double *theta, size_t n, size_t nlow, double *mu)
{
  double *a = nl_xmalloc((n ? n : 1) * sizeof *a);
  for (size_t j = 0; j < nlow; j++) {
    for (size_t i = 0; i < n; i++) a[i] = theta[i * nlow + j];
    gsl_sort(a, 1, n);
    double gap = n ? a[0] + NL_TWO_PI - a[n - 1] : NL_TWO_PI, cut = n ? a[n - 1] + 0.5 * gap : 0;
    for (size_t i = 1; i < n; i++)
      if (a[i] - a[i - 1] > gap) { gap = a[i] - a[i - 1]; cut = a[i - 1] + 0.5 * gap; }
    mu[j] = nl_wrap_angle(cut + NL_PI);
  }
  free(a);
}

void nl_cheng_rep_encode(nl_cheng_rep rep, const double *theta, size_t n, size_t nlow,
                         const double *mu, double *x)
{
  for (size_t i = 0; i < n; i++)
    for (size_t j = 0; j < nlow; j++) {
      double t = theta[i * nlow + j];
      if (rep == NL_CHENG_REP_COSSIN) { x[i * 2 * nlow + 2 * j] = cos(t); x[i * 2 * nlow + 2 * j + 1] = sin(t); }
      else   /* (mu - pi, mu + pi] */
        x[i * nlow + j] = mu[j] + (nl_wrap_angle(t - mu[j] + NL_PI) - NL_PI);
    }
}

void nl_cheng_rep_decode(nl_cheng_rep rep, const double *x, size_t n, size_t nlow,
                         const double *mu, double *theta)
{
  (void)mu;
  for (size_t i = 0; i < n; i++)
    for (size_t j = 0; j < nlow; j++)
      theta[i * nlow + j] = rep == NL_CHENG_REP_COSSIN   /* cos, sin onto the circle */
        ? nl_wrap_angle(atan2(x[i * 2 * nlow + 2 * j + 1], x[i * 2 * nlow + 2 * j]))
        : nl_wrap_angle(x[i * nlow + j]);
}

nl_status nl_cheng_rep_parse(const char *s, nl_cheng_rep *out, nl_error *err)
{
  if (!strcmp(s, "cossin")) *out = NL_CHENG_REP_COSSIN;
  else if (!strcmp(s, "unwrap")) *out = NL_CHENG_REP_UNWRAP;
  else return nl_fail(err, NL_EINVAL, "unknown representation '%s' (cossin, unwrap)", s);
  return NL_OK;
}

const char *nl_cheng_rep_name(nl_cheng_rep rep) { return rep == NL_CHENG_REP_COSSIN ? "cossin" : "unwrap"; }

/* ---- clustering --------------------------------------------------------- */

static nl_status complete_linkage(const double *x, size_t n, size_t d, double **Z, nl_error *err)
{
  *Z = nl_xmalloc((n - 1) * 4 * sizeof **Z);
  nl_status st = nl_cluster_linkage(x, n, d, NL_LINKAGE_COMPLETE, *Z, err);
  if (st) { free(*Z); *Z = NULL; }
  return st;
}

nl_status nl_cheng_initial_k(const double *x, size_t n, size_t d, double cutoff, int *labels,
                             size_t *k, nl_error *err)
{
  if (n < 2) return nl_fail(err, NL_EINVAL, "clustering needs at least 2 points, got %zu", n);
  double *Z;
  nl_status st = complete_linkage(x, n, d, &Z, err);
  if (st) return st;
  int *lab = labels ? labels : nl_xmalloc(n * sizeof *lab);
  st = nl_cluster_fcluster_distance(Z, n, cutoff, lab, k, err);
  if (!labels) free(lab);
  free(Z);
  return st;
}

double nl_cheng_cutoff_for_k(const double *Z, size_t n, size_t k)
{
  /* k clusters = the first n - k merges done, merge n - k not. */
  if (k >= n) return 0.5 * Z[2];
  if (k <= 1) return Z[(n - 2) * 4 + 2] * 1.01 + 1e-12;
  return 0.5 * (Z[(n - k - 1) * 4 + 2] + Z[(n - k) * 4 + 2]);
}

/* ---- the model ---------------------------------------------------------- */

static const char *const status_names[] = {"ok", "pool_too_small", "one_cluster", "one_per_point",
                                           "em_not_converged", "em_failed", "k_max_reached"};
const char *nl_cheng_model_status_name(nl_cheng_model_status s) { return status_names[s]; }

void nl_cheng_model_options_default(nl_cheng_model_options *o)
{
  *o = (nl_cheng_model_options){.rep = NL_CHENG_REP_COSSIN, .samples = 1000, .cutoff = -1,
                                .target_k = 30, .threshold = 0, .k_extra = 30};
  nl_gmm_options_default(&o->gmm);
}

static void set_status(nl_cheng_model *m, nl_cheng_model_status s, const char *what)
{
  m->status = s;
  snprintf(m->msg, sizeof m->msg, "%.150s", what);
}

/* k pool rows without replacement (ascending) from the stream (seed,
 * "cheng.model.subsample", 0): equal k give equal rows; k >= n gives all. */
static size_t *choose_rows(size_t n, size_t k, unsigned long seed)
{
  size_t *in = nl_xmalloc((k ? k : 1) * sizeof *in), *all = nl_xmalloc((n ? n : 1) * sizeof *all);
  for (size_t i = 0; i < n; i++) all[i] = i;
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(seed, "cheng.model.subsample", 0));
  if (k) gsl_ran_choose(rng, in, k, all, n, sizeof *all);
  gsl_rng_free(rng);
  free(all);
  return in;
}

/* Rows of the pool's angles, encoded in representation rep (or raw angles
 * when raw): n x d. */
static double *encode_rows(const nl_cheng_model *m, const nl_cheng_pool *pool, const size_t *rows, size_t n,
                           nl_cheng_rep rep, int raw)
{
  double *th = nl_xmalloc((n ? n : 1) * m->nlow * sizeof *th);
  for (size_t i = 0; i < n; i++) memcpy(th + i * m->nlow, pool->theta + rows[i] * m->nlow, m->nlow * sizeof *th);
  if (raw) return th;
  double *x = nl_xmalloc((n ? n : 1) * nl_cheng_rep_dim(rep, m->nlow) * sizeof *x);
  nl_cheng_rep_encode(rep, th, n, m->nlow, m->mu, x);
  free(th);
  return x;
}

/* Input samples: n_in pool rows for the mixture (samples, 0 = all) and n_cl
 * rows for the clustering (cluster_samples, 0 = the same rows), encoded. */
static double *model_inputs(nl_cheng_model *m, const nl_cheng_pool *pool, const nl_cheng_model_options *o,
                            unsigned long seed, double **clx)
{
  size_t samples = o->samples, cs = o->cluster_samples ? o->cluster_samples : samples;
  m->n_in = samples == 0 || samples > pool->n ? pool->n : samples;
  m->n_cl = cs == 0 || cs > pool->n ? pool->n : cs;
  m->in = choose_rows(pool->n, m->n_in, seed);
  m->cl = choose_rows(pool->n, m->n_cl, seed);
  *clx = encode_rows(m, pool, m->cl, m->n_cl, NL_CHENG_REP_COSSIN, m->cluster_angles);
  return encode_rows(m, pool, m->in, m->n_in, m->rep, 0);
}

/* Clusters the clustering rows (chords of (cos, sin), whatever the mixture's
 * representation, or raw angles) at the options' cutoff; sets cutoff, k0,
 * status. */
static nl_status model_cluster(nl_cheng_model *m, const double *clx, const nl_cheng_model_options *o,
                               nl_error *err)
{
  double t0 = nl_time_now(), *Z;
  size_t n = m->n_cl, dc = m->cluster_angles ? m->nlow : 2 * m->nlow;
  nl_status st = complete_linkage(clx, n, dc, &Z, err);
  if (st) return st;
  m->cluster_bytes = n * (n - 1) / 2 * sizeof(double) + (n - 1) * 4 * sizeof(double);
  m->cutoff = o->cutoff >= 0 ? o->cutoff : nl_cheng_cutoff_for_k(Z, n, o->target_k);
  int *lab = nl_xmalloc(n * sizeof *lab);
  st = nl_cluster_fcluster_distance(Z, n, m->cutoff, lab, &m->k0, err);
  free(lab);
  free(Z);
  m->seconds_cluster = nl_time_now() - t0;
  if (st) return st;
  if (m->k0 >= m->n_in) set_status(m, NL_CHENG_MODEL_ONE_PER_POINT, "the cutoff leaves one cluster per point: no mixture fitted");
  else if (m->k0 == 1) set_status(m, NL_CHENG_MODEL_ONE_CLUSTER, "the cutoff leaves one cluster: AIC path starts at K = 1");
  return NL_OK;
}

/* AIC path from k0 (nl_gmm_select_aic); status for failures and limits. */
static void model_mixture(nl_cheng_model *m, const double *x, const nl_cheng_model_options *o,
                          size_t k_max)
{
  double t0 = nl_time_now();
  nl_error e2;
  m->path = nl_xmalloc((k_max - m->k0 + 1) * sizeof *m->path);
  nl_status st = nl_gmm_select_aic(x, m->n_in, m->d, m->k0, o->threshold, k_max, &o->gmm,
                                   &m->gmm, m->path, &m->npath, &e2);
  m->seconds_gmm = nl_time_now() - t0;
  if (st) { m->gmm = NULL; set_status(m, NL_CHENG_MODEL_EM_FAILED, e2.msg); return; }
  m->k = m->gmm->k;
  if (m->status) return;   /* a degenerate cut is the first thing to report */
  if (!m->gmm->converged) {
    char w[128];
    snprintf(w, sizeof w, "EM did not converge in %zu iterations at K = %zu", o->gmm.max_iter, m->k);
    set_status(m, NL_CHENG_MODEL_NOT_CONVERGED, w);
  } else if (m->k == k_max && m->npath == k_max - m->k0 + 1)
    set_status(m, NL_CHENG_MODEL_K_MAX, "AIC still improving at the cap K0 + k_extra");
}

static nl_status check_model_options(const nl_cheng_model_options *o, nl_error *err)
{
  if (o->rep != NL_CHENG_REP_COSSIN && o->rep != NL_CHENG_REP_UNWRAP) return nl_fail(err, NL_EINVAL, "bad representation");
  if (o->cutoff < 0 && o->target_k < 1) return nl_fail(err, NL_EINVAL, "target_k must be >= 1");
  if (!(o->threshold >= 0)) return nl_fail(err, NL_EINVAL, "AIC threshold T must be >= 0");
  return NL_OK;
}

nl_status nl_cheng_model_fit(const nl_cheng_pool *pool, const nl_cheng_model_options *o,
                             unsigned long seed, nl_cheng_model **out, nl_error *err)
{
  *out = NULL;
  if (check_model_options(o, err)) return NL_EINVAL;
  nl_cheng_model *m = nl_xcalloc(1, sizeof *m);
  m->rep = o->rep;
  m->cluster_angles = o->cluster_angles;
  m->nlow = pool->nlow;
  m->d = nl_cheng_rep_dim(o->rep, pool->nlow);
  m->low = nl_xmalloc(pool->nlow * sizeof *m->low);
  memcpy(m->low, pool->low, pool->nlow * sizeof *m->low);
  m->mu = nl_xmalloc(pool->nlow * sizeof *m->mu);
  nl_cheng_circular_centre(pool->theta, pool->n, pool->nlow, m->mu);
  set_status(m, NL_CHENG_MODEL_OK, "ok");
  *out = m;
  double *chord, *x = model_inputs(m, pool, o, seed, &chord);
  nl_status st = NL_OK;
  if (m->n_in < 2 || m->n_cl < 2 || (o->cutoff < 0 && (o->target_k >= m->n_in || o->target_k >= m->n_cl))) {
    char w[128];
    snprintf(w, sizeof w, "%zu input samples: too few for a mixture (target K %zu)", m->n_in, o->target_k);
    set_status(m, NL_CHENG_MODEL_TOO_SMALL, w);
  } else if (!(st = model_cluster(m, chord, o, err)) && m->status != NL_CHENG_MODEL_ONE_PER_POINT) {
    size_t k_max = m->k0 + o->k_extra < m->n_in ? m->k0 + o->k_extra : m->n_in;
    model_mixture(m, x, o, k_max);
  }
  free(x);
  free(chord);
  if (st) { nl_cheng_model_free(m); *out = NULL; }
  return st;
}

void nl_cheng_model_free(nl_cheng_model *m)
{
  if (!m) return;
  free(m->low); free(m->mu); free(m->in); free(m->cl); free(m->path);
  nl_gmm_free(m->gmm);
  free(m);
}

/* ---- reproduction ------------------------------------------------------- */

nl_status nl_cheng_reproduce(const nl_noise_grad2 *opt, const nl_cheng_model *m, double swap_fraction,
                             gsl_rng *rng, nl_noise_grad2 *out, nl_error *err)
{
  if (!m->gmm) return nl_fail(err, NL_EINVAL, "no mixture to sample (%s)", m->msg);
  if (out->m != opt->m) return nl_fail(err, NL_EINVAL, "table sizes differ");
  nl_noise_grad2_copy(out, opt);
  double *x = nl_xmalloc(m->d * sizeof *x), *th = nl_xmalloc(m->nlow * sizeof *th);
  nl_gmm_sample(m->gmm, rng, 1, x, NULL);
  nl_cheng_rep_decode(m->rep, x, 1, m->nlow, m->mu, th);
  unsigned char *is_low = nl_xcalloc(opt->m, 1);
  for (size_t j = 0; j < m->nlow; j++) { nl_noise_grad2_set_angle(out, m->low[j], th[j]); is_low[m->low[j]] = 1; }
  /* Sec. 3.5.3: swap high entries at random; a permutation keeps their angles. */
  size_t nh = 0, *high = nl_xmalloc(opt->m * sizeof *high);
  for (size_t k = 0; k < opt->m; k++) if (!is_low[k]) high[nh++] = k;
  size_t ns = (size_t)floor(fmin(fmax(swap_fraction, 0), 1) * (double)nh + 0.5);
  if (ns >= 2) {
    size_t *pick = nl_xmalloc(ns * sizeof *pick);
    double *a = nl_xmalloc(ns * sizeof *a);
    gsl_ran_choose(rng, pick, ns, high, nh, sizeof *high);
    for (size_t q = 0; q < ns; q++) a[q] = opt->angle[pick[q]];
    gsl_ran_shuffle(rng, a, ns, sizeof *a);
    for (size_t q = 0; q < ns; q++) nl_noise_grad2_set_angle(out, pick[q], a[q]);
    free(pick);
    free(a);
  }
  free(high); free(is_low); free(x); free(th);
  return NL_OK;
}

/* ---- does the mixture describe the pool? -------------------------------- */

static double mean_loglik(const nl_cheng_model *m, const nl_cheng_pool *pool, const size_t *rows,
                          size_t n, nl_error *err, nl_status *st)
{
  if (n == 0) return NAN;
  double *th = nl_xmalloc(n * m->nlow * sizeof *th), *x = nl_xmalloc(n * m->d * sizeof *x), ll = NAN;
  for (size_t i = 0; i < n; i++) memcpy(th + i * m->nlow, pool->theta + rows[i] * m->nlow, m->nlow * sizeof *th);
  nl_cheng_rep_encode(m->rep, th, n, m->nlow, m->mu, x);
  if (!*st) *st = nl_gmm_loglik(m->gmm, x, n, &ll, NULL, err);
  free(th); free(x);
  return ll / (double)n;
}

/* Per-dimension two-sample KS between nd draws and nd pool rows evenly
 * spaced through the pool (all runs), angles measured from mu_j - pi (the
 * cut in the widest empty arc). Equal sizes keep the exact p-value cheap. */
static void ks_per_dim(const nl_cheng_model *m, const nl_cheng_pool *pool, const double *draw,
                       size_t nd, nl_cheng_model_check *out, nl_error *err, nl_status *st)
{
  size_t np = nd < pool->n ? nd : pool->n;
  double *a = nl_xmalloc(np * sizeof *a), *b = nl_xmalloc(nd * sizeof *b);
  double *dv = nl_xmalloc(m->nlow * sizeof *dv);
  size_t rej = 0;
  for (size_t j = 0; j < m->nlow && !*st; j++) {
    for (size_t i = 0; i < np; i++) {
      double t = pool->theta[(i * pool->n / np) * m->nlow + j];
      a[i] = nl_wrap_angle(t - m->mu[j] + NL_PI);
    }
    for (size_t i = 0; i < nd; i++) b[i] = nl_wrap_angle(draw[i * m->nlow + j] - m->mu[j] + NL_PI);
    nl_stats_ks_result r;
    *st = nl_stats_ks2_test(a, np, b, nd, &r, err);
    dv[j] = r.d;
    rej += r.p < 0.05;
  }
  gsl_sort(dv, 1, m->nlow);
  out->ks_median = gsl_stats_median_from_sorted_data(dv, 1, m->nlow);
  out->ks_reject = (double)rej / (double)m->nlow;
  free(a); free(b); free(dv);
}

nl_status nl_cheng_model_assess(const nl_cheng_pool *pool, const nl_cheng_model *m, size_t n_draw,
                                gsl_rng *rng, nl_cheng_model_check *out, nl_error *err)
{
  if (!m->gmm) return nl_fail(err, NL_EINVAL, "no mixture to assess (%s)", m->msg);
  if (n_draw < 1 || pool->n < 1) return nl_fail(err, NL_EINVAL, "nothing to compare");
  unsigned char *used = nl_xcalloc(pool->n, 1);
  for (size_t i = 0; i < m->n_in; i++) used[m->in[i]] = 1;
  size_t *held = nl_xmalloc(pool->n * sizeof *held);
  out->n_held = 0;
  for (size_t i = 0; i < pool->n; i++) if (!used[i]) held[out->n_held++] = i;
  nl_status st = NL_OK;
  out->ll_train = mean_loglik(m, pool, m->in, m->n_in, err, &st);
  out->ll_held = mean_loglik(m, pool, held, out->n_held, err, &st);
  double *x = nl_xmalloc(n_draw * m->d * sizeof *x), *th = nl_xmalloc(n_draw * m->nlow * sizeof *th);
  nl_gmm_sample(m->gmm, rng, n_draw, x, NULL);
  nl_cheng_rep_decode(m->rep, x, n_draw, m->nlow, m->mu, th);
  if (!st) ks_per_dim(m, pool, th, n_draw, out, err, &st);
  free(x); free(th); free(used); free(held);
  return st;
}

nl_status nl_cheng_k_curve(const nl_cheng_pool *pool, const nl_cheng_model *m, const double *cut,
                           size_t ncut, size_t *k, nl_error *err)
{
  if (m->n_cl < 2) return nl_fail(err, NL_EINVAL, "fewer than 2 clustered rows");
  size_t n = m->n_cl, dc = m->cluster_angles ? pool->nlow : 2 * pool->nlow;
  double *x = encode_rows(m, pool, m->cl, n, NL_CHENG_REP_COSSIN, m->cluster_angles);
  double *Z = nl_xmalloc((n - 1) * 4 * sizeof *Z);
  int *lab = nl_xmalloc(n * sizeof *lab);
  nl_status st = nl_cluster_linkage(x, n, dc, NL_LINKAGE_COMPLETE, Z, err);
  for (size_t q = 0; q < ncut && !st; q++) st = nl_cluster_fcluster_distance(Z, n, cut[q], lab, &k[q], err);
  free(x); free(Z); free(lab);
  return st;
}
