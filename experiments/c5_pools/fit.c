/* C5's fit check of the mixture on held-out pool rows (fit.h). */
#include "fit.h"
#include "stats/nl_gmm.h"
#include "stats/nl_stats.h"

#include <math.h>
#include <stdlib.h>

double c5_params_per_component(double d) { return d * (d + 1) / 2 + d + 1; }

/* Per angle: KS between column j of a (na rows) and of b (nb rows), angles
 * from mu_j - pi; Bonferroni p, median D and the fraction p < 0.05. */
static nl_status ks_columns(const double *a, size_t na, const double *b, size_t nb, size_t nlow,
                            const double *mu, double *p_bonf, double *med, double *rej,
                            nl_error *err)
{
  double *x = nl_xmalloc((na + nb + nlow) * sizeof *x), *y = x + na, *d = y + nb, pmin = 1;
  size_t r = 0;
  nl_status st = NL_OK;
  for (size_t j = 0; j < nlow && !st; j++) {
    for (size_t i = 0; i < na; i++) x[i] = nl_wrap_angle(a[i * nlow + j] - mu[j] + NL_PI);
    for (size_t i = 0; i < nb; i++) y[i] = nl_wrap_angle(b[i * nlow + j] - mu[j] + NL_PI);
    nl_stats_ks_result k;
    st = nl_stats_ks2_test(x, na, y, nb, &k, err);
    d[j] = k.d;
    pmin = fmin(pmin, k.p);
    r += k.p < 0.05;
  }
  nl_stats_sort(d, nlow);
  *med = nlow % 2 ? d[nlow / 2] : 0.5 * (d[nlow / 2 - 1] + d[nlow / 2]);
  *p_bonf = fmin(1.0, (double)nlow * pmin);
  *rej = (double)r / (double)nlow;
  free(x);
  return st;
}

nl_status c5_fit_check(const nl_cheng_pool *pool, const nl_cheng_model *m, size_t n_draw,
                       gsl_rng *rng, c5_fit *out, nl_error *err)
{
  if (!m->gmm) return nl_fail(err, NL_EINVAL, "no mixture to check (%s)", m->msg);
  size_t nlow = m->nlow;
  unsigned char *used = nl_xcalloc(pool->n, 1);
  for (size_t i = 0; i < m->n_in; i++) used[m->in[i]] = 1;
  size_t *held = nl_xmalloc(pool->n * sizeof *held), nh = 0;
  for (size_t i = 0; i < pool->n; i++)
    if (!used[i]) held[nh++] = i;
  free(used);
  if (nh == 0) {
    free(held);
    return nl_fail(err, NL_EINVAL, "no held-out pool rows");
  }
  size_t np = n_draw < nh ? n_draw : nh;
  double *h = nl_xmalloc(np * nlow * sizeof *h), *th = nl_xmalloc(n_draw * nlow * sizeof *th);
  double *x = nl_xmalloc(n_draw * m->d * sizeof *x);
  for (size_t i = 0; i < np; i++)
    for (size_t j = 0; j < nlow; j++) h[i * nlow + j] = pool->theta[held[i * nh / np] * nlow + j];
  nl_gmm_sample(m->gmm, rng, n_draw, x, NULL);
  nl_cheng_rep_decode(m->rep, x, n_draw, nlow, m->mu, th);
  out->n_held = nh;
  out->n_compared = np;
  nl_status st = ks_columns(h, np, th, n_draw, nlow, m->mu, &out->p_bonf, &out->ks_median,
                            &out->ks_reject, err);
  for (size_t i = 0; i < n_draw * nlow; i++) th[i] = NL_TWO_PI * gsl_rng_uniform(rng);
  if (!st)
    st = ks_columns(h, np, th, n_draw, nlow, m->mu, &out->p_bonf_uniform,
                    &out->ks_median_uniform, &out->ks_reject_uniform, err);
  free(h);
  free(th);
  free(x);
  free(held);
  return st;
}
