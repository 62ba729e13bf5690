/* Measures of a 3D table (uniformity on the sphere, control), values on a
 * raster, the one-run loop and the level counts (nl_cheng3.h). */
#include "cheng/nl_cheng3.h"
#include "stats/nl_stats.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CONTRAST_N 32

static double scale(const nl_cheng3_config *c)
{
  double a = c->a1, asum = 0;
  for (int l = 0; l < c->octaves; l++, a *= 2) asum += 1 / a;
  return 1 / (NL_NOISE_GRAD3_BOUND * asum);
}

/* c = (1 + V) / 2 at p with the noise kernel itself (not the optimiser's
 * stored corners: an independent path). */
static double value_at(const nl_noise_grad3 *t, const nl_cheng3_config *c, double s, double x,
                       double y, double z)
{
  double f = c->f1, a = c->a1, v = 0;
  for (int l = 0; l < c->octaves; l++, f *= 2, a *= 2)
    v += nl_noise_grad3_eval(t, f * x, f * y, f * z) / a;
  return 0.5 * (1 + s * v);
}

double nl_cheng3_value(const nl_noise_grad3 *t, const nl_cheng3_config *c, double x, double y,
                       double z)
{
  return value_at(t, c, scale(c), x, y, z);
}

void nl_cheng3_value_grid(const nl_noise_grad3 *t, const nl_cheng3_config *c, int n, double *out)
{
  double s = scale(c);
  for (int k = 0; k < n; k++)
    for (int j = 0; j < n; j++)
      for (int i = 0; i < n; i++)
        out[((size_t)k * n + j) * n + i] = value_at(t, c, s, (i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n);
}

/* E_Con, Pearson's r of c and D and E_Con's three parts (into out):
 *   sum (c - D)^2 = n (mc - mD)^2 + n (sc - sD)^2 + 2 n sc sD (1 - r)
 * with population means and sds, so "worse than a flat volume" is
 * explained by which part dominates. */
static double control_error(const nl_noise_grad3 *t, const nl_cheng3_config *c,
                            const nl_cheng3_pattern *pat, nl_cheng3_eval *out)
{
  double s = scale(c), e = 0, sv = 0, sd = 0, svv = 0, sdd = 0, svd = 0, n = (double)pat->n;
  for (size_t i = 0; i < pat->n; i++) {
    double v = value_at(t, c, s, pat->x[i], pat->y[i], pat->z[i]), d = v - pat->d[i];
    e += d * d;
    sv += v; sd += pat->d[i]; svv += v * v; sdd += pat->d[i] * pat->d[i]; svd += v * pat->d[i];
  }
  double cov = svd - sv * sd / n, vv = svv - sv * sv / n, dd = sdd - sd * sd / n;
  double r = vv > 0 && dd > 0 ? cov / sqrt(vv * dd) : 0;
  double sc = sqrt(fmax(vv, 0) / n), sD = sqrt(fmax(dd, 0) / n), dm = (sv - sd) / n;
  out->r_pattern = r;
  out->e_con_offset = n * dm * dm;
  out->e_con_contrast = n * (sc - sD) * (sc - sD);
  out->e_con_shape = 2 * n * sc * sD * (1 - r);
  return e;
}

nl_status nl_cheng3_evaluate(const nl_noise_grad3 *t, const nl_cheng3_config *c,
                             const nl_cheng3_pattern *pat, nl_cheng3_eval *out, nl_error *err)
{
  memset(out, 0, sizeof *out);
  nl_stats_ks_result rz, rp;
  nl_stats_kuiper_result kv;
  if (nl_stats_ks_test_uniform(t->z, t->m, -1, 1, &rz, err) != NL_OK ||
      nl_stats_ks_test_uniform(t->phi, t->m, 0, NL_TWO_PI, &rp, err) != NL_OK ||
      nl_stats_kuiper_test_uniform(t->phi, t->m, 0, NL_TWO_PI, &kv, err) != NL_OK)
    return NL_EINVAL;
  out->d_z = rz.d; out->p_z = rz.p; out->d_phi = rp.d; out->p_phi = rp.p;
  out->e_stat = fmax(rz.d, rp.d);
  out->p_stat = fmin(1.0, 2 * fmin(rz.p, rp.p));   /* Bonferroni over the two margins */
  out->kuiper_v = kv.v; out->p_kuiper = kv.p;
  double m[3] = {0, 0, 0};
  for (size_t k = 0; k < t->m; k++)
    for (int a = 0; a < 3; a++) m[a] += t->v[3 * k + a];
  double R = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]) / (double)t->m;
  out->rayleigh_r = R;
  out->p_rayleigh = gsl_cdf_chisq_Q(3 * (double)t->m * R * R, 3);   /* Rayleigh: 3 n R^2 ~ chi2_3 */
  out->e_con = control_error(t, c, pat, out);
  out->e = nl_cheng_objective(c, out->e_stat, out->e_con);
  out->rms_con = sqrt(out->e_con / (double)pat->n);
  double md = 0, ec = 0;
  for (size_t i = 0; i < pat->n; i++) md += pat->d[i];
  md /= (double)pat->n;
  for (size_t i = 0; i < pat->n; i++) ec += (pat->d[i] - md) * (pat->d[i] - md);
  out->e_con_const = ec;
  size_t nn = (size_t)CONTRAST_N * CONTRAST_N * CONTRAST_N;
  double *v = nl_xmalloc(nn * sizeof *v), mv = 0, q = 0;
  nl_cheng3_value_grid(t, c, CONTRAST_N, v);
  for (size_t i = 0; i < nn; i++) mv += v[i];
  mv /= (double)nn;
  for (size_t i = 0; i < nn; i++) q += (v[i] - mv) * (v[i] - mv);
  out->contrast = sqrt(q / (double)nn);
  out->e_con_random = NAN;
  free(v);
  return NL_OK;
}

nl_status nl_cheng3_run(const nl_cheng3_config *c, const nl_cheng3_pattern *pat, unsigned long seed,
                        nl_cheng3_eval *ev, nl_cheng3_eval *start, nl_cheng_level_stats *st,
                        nl_noise_grad3 **table_out, nl_error *err)
{
  if (nl_cheng_config_check(c, err) != NL_OK) return NL_EINVAL;
  nl_noise_grad3 *t = nl_noise_grad3_alloc(c->m);
  nl_noise_grad3_seed(t, seed);
  nl_cheng3_eval e0;
  nl_status rc = nl_cheng3_evaluate(t, c, pat, &e0, err);
  nl_cheng3_problem *p = rc == NL_OK ? nl_cheng3_problem_alloc(c, pat, t, err) : NULL;
  if (!p) { nl_noise_grad3_free(t); return NL_EINVAL; }
  e0.e_con_random = e0.e_con;
  if (start) *start = e0;
  nl_cheng3_optimise(p, seed, st);
  nl_cheng3_problem_free(p);
  rc = nl_cheng3_evaluate(t, c, pat, ev, err);
  ev->e_con_random = e0.e_con;
  if (table_out && rc == NL_OK) *table_out = t;
  else nl_noise_grad3_free(t);
  return rc;
}

void nl_cheng3_level_entries(const nl_noise_grad3 *t, const nl_cheng3_config *c, size_t *counts)
{
  unsigned char *seen = nl_xcalloc(t->m, 1);
  double f = c->f1;
  for (int l = 0; l < c->octaves; l++, f *= 2) {
    long L = (long)ceil(f);
    counts[l] = 0;
    for (long k = 0; k <= L; k++)
      for (long j = 0; j <= L; j++)
        for (long i = 0; i <= L; i++) {
          size_t e = nl_noise_grad3_index(t, i, j, k);
          if (!seen[e]) { seen[e] = 1; counts[l]++; }
        }
  }
  free(seen);
}
