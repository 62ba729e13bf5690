/* nl_dist.c - named continuous distributions with scipy's loc/scale
 * convention, and a tabulated CDF, for the one-sample tests (nl_stats.h). */
#include "stats/nl_stats.h"
#include "stats/nl_stats_gsl.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <pthread.h>
#include <math.h>
#include <string.h>

/* In nl_stats_dist_kind's order; the shape parameters as scipy names them. */
static const struct {
  const char *name;
  int nshape;
  const char *shapes;
} dist_info[] = {
  {"uniform", 0, ""}, {"norm", 0, ""}, {"expon", 0, ""}, {"gamma", 1, "a"},
  {"beta", 2, "a,b"}, {"lognorm", 1, "s"}, {"t", 1, "df"}, {"chi2", 1, "df"},
  {"weibull_min", 1, "c"}, {"cauchy", 0, ""}, {"logistic", 0, ""}, {"laplace", 0, ""},
  {"pareto", 1, "b"}, {"rayleigh", 0, ""},
};
#define NDIST (sizeof dist_info / sizeof dist_info[0])

nl_status nl_stats_dist_parse(const char *name, nl_stats_dist_kind *kind, nl_error *err)
{
  for (size_t i = 0; i < NDIST; i++)
    if (!strcmp(name, dist_info[i].name)) { *kind = (nl_stats_dist_kind)i; return NL_OK; }
  return nl_fail(err, NL_EINVAL, "unknown distribution '%s' (uniform, norm, expon, gamma, beta, "
                 "lognorm, t, chi2, weibull_min, cauchy, logistic, laplace, pareto, rayleigh)",
                 name);
}

int nl_stats_dist_nshape(nl_stats_dist_kind kind)
{
  return kind == NL_DIST_TABLE ? 0 : dist_info[kind].nshape;
}

const char *nl_stats_dist_shape_names(nl_stats_dist_kind kind)
{
  return kind == NL_DIST_TABLE ? "" : dist_info[kind].shapes;
}

const char *nl_stats_dist_name(nl_stats_dist_kind kind)
{
  return kind == NL_DIST_TABLE ? "table" : dist_info[kind].name;
}

nl_status nl_stats_dist_init(nl_stats_dist *d, nl_stats_dist_kind kind, double loc, double scale,
                             nl_error *err)
{
  if (nl_stats_dist_nshape(kind))
    return nl_fail(err, NL_EINVAL, "%s needs its shape parameter(s) %s", dist_info[kind].name,
                   dist_info[kind].shapes);
  return nl_stats_dist_init_shape(d, kind, NULL, 0, loc, scale, err);
}

nl_status nl_stats_dist_init_shape(nl_stats_dist *d, nl_stats_dist_kind kind, const double *shape,
                                   size_t nshape, double loc, double scale, nl_error *err)
{
  if ((int)nshape != nl_stats_dist_nshape(kind))
    return nl_fail(err, NL_EINVAL, "%s takes %d shape parameter(s) (%s), got %zu",
                   dist_info[kind].name, nl_stats_dist_nshape(kind), dist_info[kind].shapes,
                   nshape);
  for (size_t i = 0; i < nshape; i++)
    if (!(shape[i] > 0) || !isfinite(shape[i]))
      return nl_fail(err, NL_EINVAL, "shape %g of %s must be positive and finite", shape[i],
                     dist_info[kind].name);
  if (!isfinite(loc)) return nl_fail(err, NL_EINVAL, "loc %g is not finite", loc);
  if (!(scale > 0) || !isfinite(scale))
    return nl_fail(err, NL_EINVAL, "scale %g must be positive and finite", scale);
  memset(d, 0, sizeof *d);
  d->kind = kind;
  d->loc = loc;
  d->scale = scale;
  for (size_t i = 0; i < nshape; i++) d->shape[i] = shape[i];
  return NL_OK;
}

nl_status nl_stats_dist_table(nl_stats_dist *d, const double *x, const double *F, size_t m,
                              nl_error *err)
{
  if (m < 2) return nl_fail(err, NL_EINVAL, "a tabulated CDF needs at least 2 points, got %zu", m);
  for (size_t i = 0; i < m; i++) {
    if (!isfinite(x[i]) || !(F[i] >= 0.0 && F[i] <= 1.0))
      return nl_fail(err, NL_EINVAL, "CDF point %zu: (%g, %g) is not a finite x with F in [0, 1]", i + 1, x[i], F[i]);
    if (i && !(x[i] > x[i - 1]))
      return nl_fail(err, NL_EINVAL, "CDF point %zu: x = %g does not increase (previous %g)", i + 1, x[i], x[i - 1]);
    if (i && F[i] < F[i - 1])
      return nl_fail(err, NL_EINVAL, "CDF point %zu: F = %g decreases (previous %g)", i + 1, F[i], F[i - 1]);
  }
  memset(d, 0, sizeof *d);
  d->kind = NL_DIST_TABLE;
  d->m = m;
  d->x = x;
  d->F = F;
  return NL_OK;
}

/* scipy.special.ndtr (cephes ndtr.c): erf near 0, erfc in the tails, so
 * both tails keep their relative accuracy. */
static double ndtr(double a)
{
  double x = a * M_SQRT1_2, z = fabs(x);
  if (z < M_SQRT1_2) return 0.5 + 0.5 * erf(x);
  double y = 0.5 * erfc(z);
  return x > 0 ? 1.0 - y : y;
}

/* numpy.interp: constant beyond the ends, slope * (t - x_j) + F_j inside. */
static double interp(const nl_stats_dist *d, double t)
{
  size_t m = d->m;
  if (t <= d->x[0]) return d->F[0];
  if (t >= d->x[m - 1]) return d->F[m - 1];
  size_t lo = 0, hi = m - 1;   /* x[lo] <= t < x[hi] */
  while (hi - lo > 1) {
    size_t mid = lo + (hi - lo) / 2;
    if (d->x[mid] <= t) lo = mid; else hi = mid;
  }
  double slope = (d->F[hi] - d->F[lo]) / (d->x[hi] - d->x[lo]);
  return slope * (t - d->x[lo]) + d->F[lo];
}

static pthread_mutex_t handler_lock = PTHREAD_MUTEX_INITIALIZER;
static int handler_users;
static gsl_error_handler_t *handler_saved;

void nl_stats_gsl_quiet_begin(void)
{
  pthread_mutex_lock(&handler_lock);
  if (handler_users++ == 0) handler_saved = gsl_set_error_handler_off();
  pthread_mutex_unlock(&handler_lock);
}

void nl_stats_gsl_quiet_end(void)
{
  pthread_mutex_lock(&handler_lock);
  if (--handler_users == 0) gsl_set_error_handler(handler_saved);
  pthread_mutex_unlock(&handler_lock);
}

/* GSL's CDFs of gamma, beta, t and chi2 meet domain errors at extreme
 * shapes (t with df = 5e-324: lnbeta); with the handler off they return
 * NaN, which the tests refuse ("CDF returned nan"), instead of aborting. */
static double gsl_cdf(nl_stats_dist_kind kind, double z, const double *shape)
{
  nl_stats_gsl_quiet_begin();
  double p = kind == NL_DIST_GAMMA ? gsl_cdf_gamma_P(z, shape[0], 1.0)
             : kind == NL_DIST_BETA ? gsl_cdf_beta_P(z, shape[0], shape[1])
             : kind == NL_DIST_T ? gsl_cdf_tdist_P(z, shape[0])
                                 : gsl_cdf_chisq_P(z, shape[0]);
  nl_stats_gsl_quiet_end();
  return p;
}

double nl_stats_dist_cdf(double x, void *params)
{
  const nl_stats_dist *d = params;
  if (d->kind == NL_DIST_TABLE) return interp(d, x);
  double z = (x - d->loc) / d->scale;   /* scipy's rv_continuous.cdf: standardise first */
  switch (d->kind) {
  case NL_DIST_UNIFORM: return z <= 0.0 ? 0.0 : z >= 1.0 ? 1.0 : z;
  case NL_DIST_NORM: return ndtr(z);
  case NL_DIST_EXPON: return z <= 0.0 ? 0.0 : -expm1(-z);
  case NL_DIST_GAMMA: return z <= 0.0 ? 0.0 : gsl_cdf(d->kind, z, d->shape);
  case NL_DIST_BETA:
    return z <= 0.0 ? 0.0 : z >= 1.0 ? 1.0 : gsl_cdf(d->kind, z, d->shape);
  case NL_DIST_LOGNORM: return z <= 0.0 ? 0.0 : ndtr(log(z) / d->shape[0]);
  case NL_DIST_T: return gsl_cdf(d->kind, z, d->shape);
  case NL_DIST_CHI2: return z <= 0.0 ? 0.0 : gsl_cdf(d->kind, z, d->shape);
  case NL_DIST_WEIBULL_MIN: return z <= 0.0 ? 0.0 : -expm1(-pow(z, d->shape[0]));
  case NL_DIST_CAUCHY: return 0.5 + atan(z) / M_PI;
  case NL_DIST_LOGISTIC: return 1.0 / (1.0 + exp(-z));   /* scipy.special.expit */
  case NL_DIST_LAPLACE: return z > 0.0 ? 1.0 - 0.5 * exp(-z) : 0.5 * exp(z);
  case NL_DIST_PARETO: return z < 1.0 ? 0.0 : -expm1(-d->shape[0] * log(z));
  case NL_DIST_RAYLEIGH: return z <= 0.0 ? 0.0 : -expm1(-0.5 * z * z);
  default: return NAN;
  }
}
