/* maxnoise.c - A1's premise checks (maxnoise.h). */
#include "maxnoise.h"
#include "base/nl_base.h"
#include "bounds/nl_bounds.h"

#include <gsl/gsl_multimin.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

long a1_octave_over(const nl_noise_perm3 *p, int n, long npoints, unsigned long seed)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, nl_seed_stream(seed, "bounds.points", 0)); /* nl_bounds_check_random's points */
  long over = 0;
  for (long s = 0; s < npoints; s++) {
    double x[3];
    for (int a = 0; a < 3; a++) x[a] = 200.0 * gsl_rng_uniform(r) - 100.0;
    for (int i = 0; i < n; i++) {
      double f = ldexp(1.0, i);
      if (fabs(nl_noise_perm3_eval(p, f * x[0], f * x[1], f * x[2])) > 1.0) {
        over++;
        break;
      }
    }
  }
  gsl_rng_free(r);
  return over;
}

/* What a climb maximises: |Fnoise_n(x)| / S_{n-1} (eq. 4.2's ratio; n = 1
 * is |noise|, eq. 4.1's at every octave). */
typedef struct {
  const nl_noise_perm3 *p;
  int n;
} sum_ctx;

static double sum_ratio(const sum_ctx *c, const double *x)
{
  double s = 0;
  for (int i = 0; i < c->n; i++) {
    double f = ldexp(1.0, i);
    s += nl_noise_perm3_eval(c->p, f * x[0], f * x[1], f * x[2]) / f;
  }
  return fabs(s) / nl_bounds_fractal(c->n);
}

static double neg_ratio(const gsl_vector *v, void *ctx)
{
  double x[3] = { gsl_vector_get(v, 0), gsl_vector_get(v, 1), gsl_vector_get(v, 2) };
  return -sum_ratio(ctx, x);
}

/* Climbs from x; returns the ratio reached and leaves the point in x. */
static double climb(const sum_ctx *c, double x[3])
{
  gsl_multimin_function fn = { neg_ratio, 3, (void *)c };
  gsl_vector *v = gsl_vector_alloc(3), *step = gsl_vector_alloc(3);
  for (int a = 0; a < 3; a++) gsl_vector_set(v, a, x[a]);
  gsl_vector_set_all(step, 0.05);
  gsl_multimin_fminimizer *m = gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, 3);
  gsl_multimin_fminimizer_set(m, &fn, v, step);
  for (int it = 0; it < 400; it++) {
    if (gsl_multimin_fminimizer_iterate(m)) break;
    if (gsl_multimin_test_size(gsl_multimin_fminimizer_size(m), 1e-8) == GSL_SUCCESS) break;
  }
  for (int a = 0; a < 3; a++) x[a] = gsl_vector_get(m->x, a);
  double best = -m->fval;
  gsl_multimin_fminimizer_free(m);
  gsl_vector_free(v);
  gsl_vector_free(step);
  return best;
}

double a1_local_max(const nl_noise_perm3 *p, long candidates, int starts, unsigned long seed,
                    double xyz[3], double *sampled)
{
  a1_climbs c;
  a1_climb_sum(p, 1, candidates, starts, seed, &c);
  for (int a = 0; a < 3; a++) xyz[a] = c.xyz[a];
  *sampled = c.sampled;
  return c.best;
}

void a1_climb_sum(const nl_noise_perm3 *p, int n, long candidates, int starts, unsigned long seed,
                  a1_climbs *out)
{
  sum_ctx ctx = { p, n };
  out->candidates_over = 0;
  out->climbs_over = 0;
  /* the `starts` largest candidates, kept sorted, largest first */
  double(*top)[4] = nl_xcalloc((size_t)starts, sizeof *top);
  int kept = 0;
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  /* n = 1 keeps the stream of the climbs of |noise| alone */
  gsl_rng_set(r, nl_seed_stream(seed, "a1.max_candidates", n == 1 ? 0ul : (unsigned long)n));
  for (long c = 0; c < candidates; c++) {
    double x[3];
    for (int a = 0; a < 3; a++) x[a] = 256.0 * gsl_rng_uniform(r);
    double v = sum_ratio(&ctx, x);
    if (v > 1.0) out->candidates_over++;
    if (kept == starts && v <= top[starts - 1][3]) continue;
    int k = kept < starts ? kept++ : starts - 1;
    for (; k > 0 && top[k - 1][3] < v; k--)
      for (int a = 0; a < 4; a++) top[k][a] = top[k - 1][a];
    top[k][0] = x[0];
    top[k][1] = x[1];
    top[k][2] = x[2];
    top[k][3] = v;
  }
  gsl_rng_free(r);
  out->sampled = kept ? top[0][3] : 0.0;
  out->best = -1.0;
  for (int k = 0; k < kept; k++) {
    double x[3] = { top[k][0], top[k][1], top[k][2] };
    double v = climb(&ctx, x);
    if (v > 1.0) out->climbs_over++;
    if (v > out->best) {
      out->best = v;
      for (int a = 0; a < 3; a++) out->xyz[a] = x[a];
    }
  }
  free(top);
}

void a1_printed_over(const nl_noise_perm3 *p, int nmax, long npoints, unsigned long seed,
                     long *printed, long *dropped)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, nl_seed_stream(seed, "bounds.points", 0)); /* nl_bounds_check_random's points */
  *printed = *dropped = 0;
  double part[NL_MAX_OCTAVES + 1];
  for (long s = 0; s < npoints; s++) {
    double x[3];
    for (int a = 0; a < 3; a++) x[a] = 200.0 * gsl_rng_uniform(r) - 100.0;
    part[0] = 0;
    for (int i = 0; i < nmax; i++) {
      double f = ldexp(1.0, i);
      part[i + 1] = part[i] + nl_noise_perm3_eval(p, f * x[0], f * x[1], f * x[2]) / f;
    }
    double full = fabs(part[nmax]), sn1 = nl_bounds_fractal(nmax); /* S_{Nmax-1} */
    int bad_p = 0, bad_d = 0;
    for (int n = 1; n < nmax; n++) {
      /* eq. 5.4 as printed: |Fnoise_Nmax| <= |Fnoise_n + S_{Nmax-1} - S_n|, S_n = 2 - 2^-n */
      double sn = 2.0 - ldexp(1.0, -n);
      if (full > fabs(part[n] + sn1 - sn) + 1e-12) bad_p = 1;
      if (full > fabs(part[n]) + 1e-12) bad_d = 1;
    }
    *printed += bad_p;
    *dropped += bad_d;
  }
  gsl_rng_free(r);
}
