#include "cellular/nl_cellular.h"
#include "nl_test.h"

#include <gsl/gsl_rng.h>
#include <stdlib.h>
#include <string.h>

static nl_cellular *make(nl_cellular_count_rule rule, unsigned long seed)
{
  nl_cellular *c = NULL;
  NL_CHECK(nl_cellular_alloc(4.0, 50, rule, seed, &c, NULL) == NL_OK);
  return c;
}

/* At lambda = 4, p(3) = p(4) exactly in double: the paper's rule ties on
 * every r it maps to the mode; the two tie-breaks give 3 and 4. */
NL_TEST(closest_rule_ties_at_lambda_4)
{
  nl_cellular *first, *last;
  nl_error err;
  NL_CHECK(nl_cellular_alloc(4.0, 50, NL_COUNT_CLOSEST, 1, &first, &err) == NL_OK);
  NL_CHECK(nl_cellular_alloc(4.0, 50, NL_COUNT_CLOSEST_LAST, 1, &last, &err) == NL_OK);
  NL_CHECK(first->pmf[3] == first->pmf[4]);
  NL_CHECK(nl_cellular_count_from_r(first, 0.5) == 3 && nl_cellular_count_from_r(last, 0.5) == 4);
  NL_CHECK(nl_cellular_count_from_r(first, 0.0) == nl_cellular_count_from_r(last, 0.0));   /* no tie there */
  NL_CHECK(strcmp(nl_cellular_count_rule_name(NL_COUNT_CLOSEST_LAST), "closest-last") == 0);
  nl_cellular_free(first); nl_cellular_free(last);
}

NL_TEST(bad_parameters)
{
  nl_cellular *c = NULL;
  nl_error err;
  NL_CHECK(nl_cellular_alloc(-1.0, 50, NL_COUNT_INVERSE_CDF, 1, &c, &err) == NL_EINVAL && !c);
  NL_CHECK(strstr(err.msg, "lambda") != NULL);
  NL_CHECK(nl_cellular_alloc(4.0, 0, NL_COUNT_INVERSE_CDF, 1, &c, NULL) == NL_EINVAL);
  NL_CHECK(nl_cellular_alloc(4.0, 65, NL_COUNT_INVERSE_CDF, 1, &c, NULL) == NL_EINVAL);
}

NL_TEST(count_rules)
{
  nl_cellular *a = make(NL_COUNT_INVERSE_CDF, 1), *b = make(NL_COUNT_CLOSEST, 1);
  NL_CHECK_NEAR(a->pmf[4], 256.0 / 24.0 * exp(-4.0), 1e-15);
  NL_CHECK(nl_cellular_count_from_r(a, 0.0) == 0);
  NL_CHECK(nl_cellular_count_from_r(a, a->cdf[3]) == 4);
  NL_CHECK(nl_cellular_count_from_r(a, nextafter(a->cdf[3], 0)) == 3);
  NL_CHECK(nl_cellular_count_from_r(a, 0.999999999999) > 12);
  /* above max p(m) ~ 0.195 the closest p(m) is p(3) (= p(4)); r near 0 gives M */
  NL_CHECK(nl_cellular_count_from_r(b, 0.9) == 3 || nl_cellular_count_from_r(b, 0.9) == 4);
  NL_CHECK(nl_cellular_count_from_r(b, 0.0) == 50);
  nl_cellular_free(a);
  nl_cellular_free(b);
}

/* F1 <= F2 <= F3 <= F4 on rows and points; rows give the same bits as
 * points; each F_i matches a brute-force search over 5 x 5 x 5 cubes
 * wherever F_i <= 1 (where the 27-cube search is exact). */
/* nl_cellular_points and nl_cellular_gctbf_points give the point calls'
 * bits (nl_cellular_eval, then nl_cellular_gctbf_value) at scattered
 * points, negative ones among them, for n = 1..4 and a GCTBF sum. */
NL_TEST(points_equal_eval_bit_for_bit)
{
  nl_cellular *c = make(NL_COUNT_INVERSE_CDF, 3);
  enum { N = 400 };
  double x[N], y[N], z[N], F[4 * N], v[N];
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 8);
  for (int k = 0; k < N; k++) {
    x[k] = 80 * gsl_rng_uniform(r) - 40;
    y[k] = -60 * gsl_rng_uniform(r);
    z[k] = 1e5 * (gsl_rng_uniform(r) - 0.5);
  }
  long bad = 0;
  for (int n = 1; n <= 4; n++) {
    nl_cellular_points(c, x, y, z, N, n, F);
    for (int k = 0; k < N; k++) {
      double p[3] = {x[k], y[k], z[k]}, q[4];
      nl_cellular_eval(c, p, n, q);
      bad += memcmp(q, F + (size_t)k * n, (size_t)n * sizeof *q) != 0;
    }
  }
  nl_cellular_gctbf g;
  nl_error err;
  NL_CHECK(nl_cellular_gctbf_parse("F3 - 0.5 F1 + F1F2", &g, &err) == NL_OK);
  nl_cellular_gctbf_points(c, &g, x, y, z, N, v);
  for (int k = 0; k < N; k++) {
    double p[3] = {x[k], y[k], z[k]}, q[4];
    nl_cellular_eval(c, p, g.n, q);
    double w = nl_cellular_gctbf_value(&g, q);
    bad += memcmp(&w, &v[k], sizeof w) != 0;
  }
  NL_CHECK(bad == 0);
  gsl_rng_free(r);
  nl_cellular_free(c);
}

NL_TEST(ordering_rows_and_brute_force)
{
  nl_cellular *c = make(NL_COUNT_INVERSE_CDF, 9);
  size_t n = 300;
  double *F = malloc(4 * n * sizeof *F);
  long bad_order = 0, bad_point = 0, bad_brute = 0, compared = 0;
  for (int row = 0; row < 20; row++) {
    double y = -7.3 + 0.77 * row, z = 3.1 - 0.41 * row, x0 = -11.05, dx = 0.071;
    nl_cellular_row(c, x0, dx, y, z, n, 4, F);
    for (size_t s = 0; s < n; s++) {
      const double *f = F + 4 * s;
      bad_order += !(f[0] <= f[1] && f[1] <= f[2] && f[2] <= f[3]);
      double p[3] = {x0 + (double)s * dx, y, z}, q[4];
      nl_cellular_eval(c, p, 4, q);
      bad_point += memcmp(q, f, sizeof q) != 0;
      double d2[4] = {INFINITY, INFINITY, INFINITY, INFINITY}, pts[3 * NL_CELLULAR_MAX_M];
      for (long i = -2; i <= 2; i++) for (long j = -2; j <= 2; j++) for (long k = -2; k <= 2; k++) {
        int m = nl_cellular_cube(c, (long)floor(p[0]) + i, (long)floor(p[1]) + j, (long)floor(p[2]) + k, pts);
        for (int t = 0; t < m; t++) {
          double e = 0;
          for (int a = 0; a < 3; a++) e += (pts[3 * t + a] - p[a]) * (pts[3 * t + a] - p[a]);
          for (int u = 0; u < 4; u++) if (e < d2[u]) { for (int v = 3; v > u; v--) d2[v] = d2[v - 1]; d2[u] = e; break; }
        }
      }
      for (int u = 0; u < 4; u++)
        if (f[u] <= 1.0) { compared++; bad_brute += fabs(sqrt(d2[u]) - f[u]) > 0; }
    }
  }
  NL_CHECK(bad_order == 0);
  NL_CHECK(bad_point == 0);
  NL_CHECK(bad_brute == 0);
  NL_CHECK(compared > 20000);
  /* A sparse row (more cubes than samples) takes the point path. */
  nl_cellular_row(c, 0.5, 5.0, 0.5, 0.5, 10, 2, F);
  for (int s = 0; s < 10; s++) NL_CHECK(F[2 * s] <= F[2 * s + 1]);
  free(F);
  nl_cellular_free(c);
}

/* Counts against Poisson(4) on 32^3 cubes, seeds 1..20. The paper's
 * closest-p rule fails chi-square on every seed. The inverse-CDF rule keeps
 * the mean at lambda but does not pass at the nominal rate: measured over
 * seeds 1..200 (and over the same seeds before the seed rule changed), 9-10%
 * of seeds give p <= 0.01 and 24-30% p <= 0.05, where independent counts
 * would give 1% and 5%: neighbouring cubes' counts are not independent
 * under the PERM hash of step 3. A one-seed "p > 0.01" test passes or fails
 * by the draw, so we test what holds on every seed set: the mean count, and
 * a chi-square far below the closest-p rule's. */
NL_TEST(count_distribution_chisq)
{
  double sum = 0, n = 0;
  for (unsigned long seed = 1; seed <= 20; seed++) {
    nl_cellular *a = make(NL_COUNT_INVERSE_CDF, seed), *b = make(NL_COUNT_CLOSEST, seed);
    double ha[51], hb[51];
    nl_stats_chisq_result ra, rb;
    nl_cellular_count_histogram(a, 0, 32, ha);
    nl_cellular_count_histogram(b, 0, 32, hb);
    NL_CHECK(nl_cellular_count_chisq(a, ha, &ra, NULL) == NL_OK);
    NL_CHECK(nl_cellular_count_chisq(b, hb, &rb, NULL) == NL_OK);
    NL_CHECK(rb.p < 1e-10);
    NL_CHECK(ra.chi2 < rb.chi2 / 100);
    NL_CHECK(ra.df >= 9 && !ra.low_expected);
    for (int m = 0; m <= 50; m++) { sum += m * ha[m]; n += ha[m]; }
    nl_cellular_free(a);
    nl_cellular_free(b);
  }
  /* 655360 counts: sd of the mean 2 / sqrt(n) = 0.0025 if independent;
   * 0.03 leaves room for a doubled variance at 8 sd. */
  NL_CHECK_NEAR(sum / n, 4.0, 0.03);
}

/* F1 follows 1 - exp(-lambda 4/3 pi r^3) under the inverse-CDF rule. */
NL_TEST(f1_nearest_neighbour_law)
{
  nl_cellular *a = make(NL_COUNT_INVERSE_CDF, 2), *b = make(NL_COUNT_CLOSEST, 2);
  nl_stats_ks_result ra, rb;
  double ma;
  NL_CHECK(nl_cellular_f1_ks(a, 3000, 5, &ra, &ma, NULL) == NL_OK);
  NL_CHECK(nl_cellular_f1_ks(b, 3000, 5, &rb, NULL, NULL) == NL_OK);
  NL_CHECK(ra.p > 0.01);
  NL_CHECK(rb.p < 0.01);
  /* mean of the law: Gamma(4/3) (4/3 pi lambda)^(-1/3) = 0.3507 for lambda = 4 */
  NL_CHECK_NEAR(ma, tgamma(4.0 / 3.0) * pow(4.0 / 3.0 * NL_PI * 4.0, -1.0 / 3.0), 0.01);
  nl_cellular_free(a);
  nl_cellular_free(b);
}

NL_TEST(gctbf_parse_and_format)
{
  nl_cellular_gctbf g;
  nl_error err;
  char buf[128];
  NL_CHECK(nl_cellular_gctbf_parse("F2 - F1 - F1F1", &g, &err) == NL_OK);
  NL_CHECK(g.n == 2 && g.c[0] == -1 && g.c[1] == 1 && g.cc[0][0] == -1);
  nl_cellular_gctbf_format(&g, buf, sizeof buf);
  NL_CHECK(strcmp(buf, "-F1 + F2 - F1F1") == 0);
  NL_CHECK(nl_cellular_gctbf_parse(" 0.5*F1 + 2 F1*F2 -f3f4", &g, &err) == NL_OK);
  NL_CHECK(g.n == 4 && g.c[0] == 0.5 && g.cc[0][1] == 2 && g.cc[2][3] == -1);
  double F[4] = {0.1, 0.2, 0.3, 0.4};
  NL_CHECK_NEAR(nl_cellular_gctbf_value(&g, F), 0.05 + 2 * 0.02 - 0.12, 1e-15);
  NL_CHECK(nl_cellular_gctbf_parse("F5", &g, &err) == NL_EINVAL && strstr(err.msg, "1..4"));
  NL_CHECK(nl_cellular_gctbf_parse("F1 + abc", &g, &err) == NL_EINVAL && strstr(err.msg, "abc"));
  NL_CHECK(nl_cellular_gctbf_parse("", &g, &err) == NL_EINVAL);
  NL_CHECK(nl_cellular_gctbf_parse("2", &g, &err) == NL_EINVAL);
  NL_CHECK(nl_cellular_gctbf_parse("F1 F2 F3", &g, &err) == NL_EINVAL);
  NL_CHECK(nl_cellular_gctbf_parse("nan F1", &g, &err) == NL_EINVAL);
  NL_CHECK(nl_cellular_gctbf_add(&g, 0, 1, 1.0, &err) == NL_EINVAL);
}

/* The basis evaluates eq. 1 on rows and never leaves its bound. */
NL_TEST(gctbf_basis)
{
  nl_cellular *c = make(NL_COUNT_INVERSE_CDF, 4);
  nl_cellular_gctbf_basis gb = {c, {0}};
  NL_CHECK(nl_cellular_gctbf_parse("F1F2 + F2F3 - 3 F4", &gb.g, NULL) == NL_OK);
  nl_noise_basis b = nl_cellular_basis_gctbf(&gb);
  double out[200], F[4], worst = 0;
  b.row(b.ctx, 0.3, 0.05, 1.7, 2.2, 200, out);
  for (int s = 0; s < 200; s++) {
    double p[3] = {0.3 + s * 0.05, 1.7, 2.2};
    nl_cellular_eval(c, p, 4, F);
    NL_CHECK(out[s] == nl_cellular_gctbf_value(&gb.g, F));
    worst = fmax(worst, fabs(out[s]));
  }
  NL_CHECK(worst <= b.bound && worst > 0);
  nl_cellular_free(c);
}

NL_TEST(shading_flat_and_tilted)
{
  double h[9] = {0}, out[9], up[3] = {0, 0, 1};
  nl_cellular_heightfield_shade(h, 3, 3, 1.0, up, out);
  for (int k = 0; k < 9; k++) NL_CHECK_NEAR(out[k], 1.0, 1e-15);
  /* surface z = -h with h = x: slope -1 in x, normal (1, 0, 1)/sqrt 2 */
  for (int k = 0; k < 9; k++) h[k] = k % 3;
  nl_cellular_heightfield_shade(h, 3, 3, 1.0, up, out);
  NL_CHECK_NEAR(out[4], 1.0 / sqrt(2.0), 1e-15);
}

NL_TEST(count_moments_and_texture_values)
{
  double hist[4] = {1, 2, 1, 0}, mean, var;   /* counts 0, 1, 1, 2: mean 1, variance 1/2 */
  nl_cellular_count_moments(hist, 3, &mean, &var);
  NL_CHECK_NEAR(mean, 1.0, 1e-15);
  NL_CHECK_NEAR(var, 0.5, 1e-15);
  nl_noise_window w = {0, 0, 0.5, 2.0, 8, 8};
  double v[64], u[64];
  NL_CHECK(nl_cellular_texture_grid(NL_GCTBF_PLAIN, "F1", 2, 2.0, &w, 3, v, NULL) == NL_OK);
  for (int k = 0; k < 64; k++) NL_CHECK(v[k] >= 0.0);
  NL_CHECK(nl_cellular_texture_grid(NL_GCTBF_CLOUD, NULL, 2, 2.0, &w, 3, v, NULL) == NL_OK);
  NL_CHECK(nl_cellular_texture_grid(NL_GCTBF_FLAME, NULL, 2, 2.0, &w, 3, u, NULL) == NL_OK);
  NL_CHECK(nl_cellular_texture_grid(NL_GCTBF_CLOUD, "F9 +", 2, 2.0, &w, 3, v, NULL) == NL_EINVAL);
}

int main(void) { return nl_test_run(); }
