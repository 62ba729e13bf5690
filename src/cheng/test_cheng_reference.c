/* test_cheng_reference.c - Cheng's objective (eq. 3.4-3.9, 3.10, 4.1-4.3)
 * as nl_cheng_evaluate reports it, against the definitions written out here
 * on the oracles of tests/reference: the statistics of the M angles by
 * counting (ks_direct.c: KS D and Kuiper's V as sup |F_n - F|; Pearson's
 * chi-square on K equal bins counted here), and E_Con from the noise of
 * eq. 3.1-3.2 (cheng_gradient_noise.c) summed over the octaves of eq. 3.10
 * at every control point, for each control variant, scaled and literal.
 *
 * 120 evaluations: random tables (M = 512), random RGBA patterns (grids 8 to
 * 64, some cells transparent), F = 1..5 octaves, f1 in {8, 4, 6}, a1 in
 * {4, 2, 3}, the three statistics, the four variants, both readings, random
 * weights w1, w2, domain origin 0 and 1. Tolerances: D and V 2e-15 (the same rank fractions less
 * the same theta / 2 pi); chi2 1e-12 relative (the same integer counts, the
 * sum in another order); E_Con 1e-12 relative to n: per point c differs by
 * the noise's 5e-15 (test_noise_grad2_reference.c) times sum 1/a_l scaled,
 * squared differences below 4, summed over up to 4096 points; E formed from
 * those (1e-12 relative). Measured: D, V and chi2 identical, E_Con 5.8e-17
 * n, E 3.5e-16.
 */
#include "cheng/nl_cheng.h"
#include "nl_test.h"
#include "reference/cheng_gradient_noise.h"
#include "reference/ks_direct.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

static double cdf_turn(double x) { return x / (2 * M_PI); }

/* The control value c at one point (nl_cheng.h THE MODEL and READINGS). */
static double control(const nl_cheng_config *c, const nl_noise_grad2 *g, double x, double y)
{
  double sum = 0, sum_abs = 0, inv = 0;
  for (int l = 0; l < c->octaves; l++) {
    double f = c->f1 * ldexp(1.0, l), a = c->a1 * ldexp(1.0, l);
    double v = cheng_gradient_noise(g->angle, g->perm, g->m, f * (c->origin + x), f * (c->origin + y));
    sum += v / a;
    sum_abs += fabs(v) / a;
    inv += 1 / a;
  }
  double s = c->literal ? 1 : 1 / (sqrt(2.0) / 2 * inv), V = s * sum;
  switch (c->con) {
  case NL_CHENG_CON_PLAIN: return c->literal ? V : (1 + V) / 2;
  case NL_CHENG_CON_SIN: return c->literal ? sin(V) : (1 + sin(M_PI * V)) / 2;
  case NL_CHENG_CON_ABS: return fabs(V);
  default: return s * sum_abs;
  }
}

NL_TEST(evaluate_matches_the_definitions)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 2009);
  double w_ks = 0, w_chi = 0, w_con = 0, w_e = 0;
  int runs = 0;
  for (int t = 0; t < 120; t++) {
    int grid = 8 << gsl_rng_uniform_int(r, 4), w = grid * 2, h = grid * 2;
    float *px = malloc((size_t)w * h * 4 * sizeof *px);
    for (int k = 0; k < w * h; k++) {
      px[4 * k] = (float)gsl_rng_uniform(r);
      px[4 * k + 1] = px[4 * k + 2] = 0;
      px[4 * k + 3] = gsl_rng_uniform(r) < 0.8 ? 1.0f : 0.0f;
    }
    nl_cheng_pattern *pat = NULL;
    NL_CHECK(nl_cheng_pattern_from_pixels(px, w, h, 4, grid, &pat, NULL) == NL_OK);
    nl_cheng_config c = nl_cheng_config_default();
    static const double f1s[] = {8, 4, 6}, a1s[] = {4, 2, 3};
    c.octaves = 1 + t % 5;
    c.f1 = f1s[t % 3];
    c.a1 = a1s[t / 3 % 3];
    c.stat = (nl_cheng_stat)(t % 3);
    c.con = (nl_cheng_con)(t / 2 % 4);
    c.literal = t / 8 % 2;
    c.origin = t / 16 % 2;   /* the domain [1, 2]^2 and the alternative [0, 1]^2 */
    c.w1 = gsl_rng_uniform(r);
    c.w2 = 1 - c.w1;
    nl_noise_grad2 *g = nl_noise_grad2_alloc(c.m);
    nl_noise_grad2_seed(g, 100 + (unsigned long)t);
    nl_cheng_eval ev;
    NL_CHECK(nl_cheng_evaluate(g, &c, pat, &ev, NULL) == NL_OK);

    double dp, dm;
    ks_direct_one(g->angle, c.m, cdf_turn, &dp, &dm);
    w_ks = fmax(w_ks, fmax(fabs(ev.e_ks - fmax(dp, dm)), fabs(ev.kuiper_v - (dp + dm))));
    size_t K = c.chisq_bins;
    double *count = calloc(K, sizeof *count), chi2 = 0, E = (double)c.m / (double)K;
    for (size_t k = 0; k < c.m; k++) {
      size_t b = 0;
      while (b + 1 < K && g->angle[k] >= 2 * M_PI * (double)(b + 1) / (double)K)
        b++;
      count[b]++;
    }
    for (size_t b = 0; b < K; b++)
      chi2 += (count[b] - E) * (count[b] - E) / E;
    w_chi = fmax(w_chi, fabs(ev.chi2 - chi2) / chi2);
    double con = 0;
    for (size_t i = 0; i < pat->n; i++) {
      double d = control(&c, g, pat->x[i], pat->y[i]) - pat->d[i];
      con += d * d;
    }
    w_con = fmax(w_con, fabs(ev.e_con - con) / (double)pat->n);
    double stat = c.stat == NL_CHENG_STAT_KS ? fmax(dp, dm)
                : c.stat == NL_CHENG_STAT_KUIPER ? dp + dm
                : sqrt(chi2 / ((double)c.m * (double)(K - 1)));
    double e = c.w1 * stat + c.w2 * con;
    w_e = fmax(w_e, fabs(ev.e - e) / fmax(1, fabs(e)));
    runs++;
    free(count);
    free(px);
    nl_noise_grad2_free(g);
    nl_cheng_pattern_free(pat);
  }
  printf("  %d evaluations: D, V %.3g; chi2 relative %.3g; E_Con / n %.3g; E relative %.3g\n",
         runs, w_ks, w_chi, w_con, w_e);
  NL_CHECK(w_ks <= 2e-15);
  NL_CHECK(w_chi <= 1e-12);
  NL_CHECK(w_con <= 1e-12);
  NL_CHECK(w_e <= 1e-12);
  gsl_rng_free(r);
}

int main(void) { return nl_test_run(); }
