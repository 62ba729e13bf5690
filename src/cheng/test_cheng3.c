#include "cheng/nl_cheng3.h"
#include "stats/nl_stats.h"
#include "nl_test.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static double rel(double a, double b) { return fabs(a - b) / fmax(1.0, fabs(b)); }

/* After every move of a random sequence (half of them undone): incremental
 * E, E_stat and E_Con == full recomputation to 1e-12, undo exact. */
NL_TEST(incremental_equals_full_3d)
{
  nl_cheng3_pattern *pat;
  nl_error err;
  NL_CHECK(nl_cheng3_pattern_shape("torus", 8, &pat, &err) == NL_OK);
  nl_cheng3_config c = nl_cheng3_config_default();
  c.w1 = 0.6; c.w2 = 0.4;   /* both terms visible in E */
  nl_noise_grad3 *t = nl_noise_grad3_alloc(c.m);
  nl_noise_grad3_seed(t, 7);
  nl_cheng3_problem *p = nl_cheng3_problem_alloc(&c, pat, t, &err);
  NL_CHECK(p != NULL);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 99);
  double worst = 0;
  for (int m = 0; m < 2000; m++) {
    size_t k = gsl_rng_uniform_int(r, c.m);
    double before = nl_cheng3_energy(p, NULL, NULL), u[3];
    nl_cheng3_propose(t->v + 3 * k, NL_PI * gsl_rng_uniform(r), r, u);
    nl_cheng3_move(p, k, u);
    if (gsl_rng_uniform(r) < 0.5) {
      nl_cheng3_undo(p);
      NL_CHECK(nl_cheng3_energy(p, NULL, NULL) == before);
    }
    double es, ec, fs, fc, e = nl_cheng3_energy(p, &es, &ec), f = nl_cheng3_energy_full(p, &fs, &fc);
    worst = fmax(worst, fmax(rel(e, f), fmax(rel(es, fs), rel(ec, fc))));
    if (m % 500 == 499) nl_cheng3_resum(p);
  }
  NL_CHECK(worst < 1e-12);
  /* The stored corners agree with the noise kernel: E_Con of nl_cheng3_evaluate
   * (nl_noise_grad3_eval per point) == the problem's. */
  nl_cheng3_eval ev;
  NL_CHECK(nl_cheng3_evaluate(t, &c, pat, &ev, &err) == NL_OK);
  double ec;
  nl_cheng3_energy(p, NULL, &ec);
  NL_CHECK(rel(ev.e_con, ec) < 1e-12);
  gsl_rng_free(r);
  nl_cheng3_problem_free(p);
  nl_noise_grad3_free(t);
  nl_cheng3_pattern_free(pat);
}

/* The proposal keeps unit length, moves by at most sigma, and is symmetric
 * in the sense that matters: many steps from one direction spread uniformly
 * (the ensemble of 4000 walkers after 50 steps passes KS on z and phi). */
NL_TEST(proposal_on_the_sphere)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 3);
  enum { N = 4000 };
  double *z = malloc(N * sizeof *z), *ph = malloc(N * sizeof *ph), worst_len = 0, worst_ang = 0;
  for (int w = 0; w < N; w++) {
    double v[3] = {0, 0, 1}, u[3];
    for (int s = 0; s < 50; s++) {
      double sigma = 0.7;
      nl_cheng3_propose(v, sigma, r, u);
      double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2], len = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      worst_len = fmax(worst_len, fabs(len - 1));
      worst_ang = fmax(worst_ang, acos(fmin(1.0, dot)) - sigma);
      for (int a = 0; a < 3; a++) v[a] = u[a];
    }
    z[w] = v[2];
    ph[w] = atan2(v[1], v[0]);
    if (ph[w] < 0) ph[w] += NL_TWO_PI;
  }
  if (!(worst_len < 1e-12)) fprintf(stderr, "worst_len %g\n", worst_len);
  NL_CHECK(worst_len < 1e-12);
  NL_CHECK(worst_ang < 1e-9);
  nl_stats_ks_result rz, rp;
  NL_CHECK(nl_stats_ks_test_uniform(z, N, -1, 1, &rz, NULL) == NL_OK);
  NL_CHECK(nl_stats_ks_test_uniform(ph, N, 0, NL_TWO_PI, &rp, NULL) == NL_OK);
  NL_CHECK(rz.p > 0.001 && rp.p > 0.001);
  free(z); free(ph);
  gsl_rng_free(r);
}

/* Rayleigh's p is P(chi2_3 > 3 n R^2): all entries pointing one way gives
 * R = 1 and p ~ 0; a seeded table is not rejected (p > 0.001). A wrong-size
 * config is refused. */
NL_TEST(evaluate_and_refusals)
{
  nl_cheng3_pattern *pat;
  nl_error err;
  NL_CHECK(nl_cheng3_pattern_shape("ball", 4, &pat, &err) == NL_OK);
  NL_CHECK(nl_cheng3_pattern_shape("cube", 4, &pat, &err) == NL_EINVAL);
  nl_cheng3_config c = nl_cheng3_config_default();
  nl_noise_grad3 *t = nl_noise_grad3_alloc(c.m);
  nl_cheng3_eval ev;
  NL_CHECK(nl_cheng3_evaluate(t, &c, pat, &ev, &err) == NL_OK);   /* all (0, 0, 1) */
  NL_CHECK(fabs(ev.rayleigh_r - 1) < 1e-15 && ev.p_rayleigh < 1e-100);
  nl_noise_grad3_seed(t, 11);
  NL_CHECK(nl_cheng3_evaluate(t, &c, pat, &ev, &err) == NL_OK);
  NL_CHECK(ev.p_rayleigh > 0.001 && ev.p_z > 0.001 && ev.p_phi > 0.001);
  /* E_Con's three parts add up to it (an identity of the moments: rounding only) */
  double parts = ev.e_con_offset + ev.e_con_contrast + ev.e_con_shape;
  NL_CHECK(fabs(parts - ev.e_con) <= 1e-10 * ev.e_con);
  NL_CHECK(ev.e_con_offset >= 0 && ev.e_con_contrast >= 0 && ev.e_con_shape >= 0);
  c.m = 256;
  NL_CHECK(nl_cheng3_problem_alloc(&c, pat, t, &err) == NULL);
  size_t counts[3];
  c = nl_cheng3_config_default();
  nl_cheng3_level_entries(t, &c, counts);
  NL_CHECK(counts[0] + counts[1] + counts[2] <= c.m && counts[0] > 0);
  nl_noise_grad3_free(t);
  nl_cheng3_pattern_free(pat);
}

int main(void) { return nl_test_run(); }
