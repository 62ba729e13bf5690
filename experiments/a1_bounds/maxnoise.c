/* maxnoise.c - A1's premise checks (maxnoise.h). */
#include "maxnoise.h"
#include "base/nl_base.h"

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

static double neg_abs_noise(const gsl_vector *v, void *ctx)
{
  const nl_noise_perm3 *p = ctx;
  return -fabs(
      nl_noise_perm3_eval(p, gsl_vector_get(v, 0), gsl_vector_get(v, 1), gsl_vector_get(v, 2)));
}

/* Climbs from x; returns the |noise| reached and leaves the point in x. */
static double climb(const nl_noise_perm3 *p, double x[3])
{
  gsl_multimin_function fn = { neg_abs_noise, 3, (void *)p };
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
  /* the `starts` largest candidates, kept sorted, largest first */
  double(*top)[4] = nl_xcalloc((size_t)starts, sizeof *top);
  int kept = 0;
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, nl_seed_stream(seed, "a1.max_candidates", 0));
  for (long c = 0; c < candidates; c++) {
    double x[3];
    for (int a = 0; a < 3; a++) x[a] = 256.0 * gsl_rng_uniform(r);
    double v = fabs(nl_noise_perm3_eval(p, x[0], x[1], x[2]));
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
  *sampled = kept ? top[0][3] : 0.0;
  double best = -1.0;
  for (int k = 0; k < kept; k++) {
    double x[3] = { top[k][0], top[k][1], top[k][2] };
    double v = climb(p, x);
    if (v > best) {
      best = v;
      for (int a = 0; a < 3; a++) xyz[a] = x[a];
    }
  }
  free(top);
  return best;
}
