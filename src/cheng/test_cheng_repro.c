/* Tests of nl_cheng_repro.h, noise reproduction (nl_cheng_pool.c,
 * nl_cheng_model.c): E_R's incremental state, pools independent of
 * threads, the circular representation, recovery of a known mixture's K,
 * sampling, degenerate cases. */
#include "cheng/test_cheng_fixture.h"

#include <gsl/gsl_randist.h>
#include <gsl/gsl_sort.h>
#include <stdlib.h>
#include <string.h>

#define REPRO_PX 64   /* the flower drawn at 64 pixels */

static nl_cheng_config small_config(void)
{
  nl_cheng_config c = nl_cheng_config_default();
  c.sched.n_temps = 6;
  c.sched.moves_per_var = 3;
  return c;
}

NL_TEST(reproduction_mode_is_eq_3_16_to_3_18)
{
  nl_cheng_config c = small_config();
  test_fixture f;
  test_fixture_open(&f, REPRO_PX, 32, &c, 3, 1);
  nl_cheng_problem *p = f.p;
  nl_noise_grad2 *g = f.g;
  const nl_cheng_pattern *pat = f.pat;
  nl_error err;
  nl_cheng_set_reproduction(p, 1);
  size_t nv, n1, n2;
  const size_t *v = nl_cheng_vars(p, &nv);
  size_t *low1 = nl_cheng_low_entries(g, &c, pat, 1, &n1, &err);
  size_t *low2 = nl_cheng_low_entries(g, &c, pat, 2, &n2, &err);
  NL_CHECK(nv == n1 && n1 > 40 && n1 <= 81 && n2 > n1 && memcmp(v, low1, n1 * sizeof *v) == 0);
  /* E_R == the full recomputation (statistic over all M, E_Con over all F) after moves */
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  for (int t = 0; t < 200; t++) {
    double e = nl_cheng_move(p, v[gsl_rng_uniform_int(rng, nv)], NL_TWO_PI * gsl_rng_uniform(rng));
    if (t % 3 == 0) nl_cheng_undo(p);
    else NL_CHECK_NEAR(e, nl_cheng_energy_full(p, NULL, NULL), 1e-10 * fabs(e));
  }
  nl_cheng_eval ev;
  nl_cheng_evaluate(g, &c, pat, &ev, &err);
  double es, ec;
  nl_cheng_set_reproduction(p, 1);
  nl_cheng_energy(p, &es, &ec);
  NL_CHECK_NEAR(es, ev.e_ks, 1e-12);
  NL_CHECK_NEAR(ec, ev.e_con, 1e-9 * ec);
  gsl_rng_free(rng);
  free(low1); free(low2);
  test_fixture_close(&f);
}

NL_TEST(pool_same_for_any_thread_count)
{
  nl_cheng_config c = small_config();
  test_fixture f;
  test_fixture_open(&f, REPRO_PX, 16, &c, 5, 0);
  const nl_noise_grad2 *g = f.g;
  const nl_cheng_pattern *pat = f.pat;
  nl_cheng_pool_options o;
  nl_cheng_pool_options_default(&o);
  o.runs = 5; o.keep = 4;
  nl_cheng_pool *a, *b;
  nl_error err;
  o.threads = 1;
  NL_CHECK(nl_cheng_pool_collect(g, &c, pat, &o, 11, &a, &err) == NL_OK);
  o.threads = 3;
  NL_CHECK(nl_cheng_pool_collect(g, &c, pat, &o, 11, &b, &err) == NL_OK);
  NL_CHECK(a->n == 20 && b->n == 20 && a->excluded == 0);
  NL_CHECK(memcmp(a->theta, b->theta, a->n * a->nlow * sizeof(double)) == 0);
  NL_CHECK(memcmp(a->e, b->e, a->n * sizeof(double)) == 0);
  for (int q = 0; q < 5; q++) NL_CHECK(a->run_best[q] <= a->run_start[q]);   /* annealing improved */
  /* epsilon 0 keeps only states at the run's best */
  nl_cheng_pool *z;
  o.epsilon = 0;
  NL_CHECK(nl_cheng_pool_collect(g, &c, pat, &o, 11, &z, &err) == NL_OK);
  NL_CHECK(z->n + z->excluded == 20 && z->n < 20);
  for (size_t i = 0; i < z->n; i++) NL_CHECK(z->e[i] <= z->run_best[z->run[i]]);
  nl_cheng_pool_free(z);
  o.low_levels = 4;   /* no high level left */
  NL_CHECK(nl_cheng_pool_collect(g, &c, pat, &o, 11, &z, &err) == NL_EINVAL && z == NULL);
  nl_cheng_pool_free(a); nl_cheng_pool_free(b); nl_cheng_pool_free(z);
  test_fixture_close(&f);
}

NL_TEST(circular_representation)
{
  double th[4] = {0.01, NL_TWO_PI - 0.01, 3.0, 1.0}, x[8], back[4], mu[2];
  nl_cheng_circular_centre(th, 2, 2, mu);   /* rows {0.01, 2pi-0.01}, {3, 1} */
  nl_cheng_rep_encode(NL_CHENG_REP_COSSIN, th, 2, 2, mu, x);
  /* 0.01 and 2pi - 0.01 are 0.02 apart on the circle: chord ~0.02, not ~2pi */
  NL_CHECK_NEAR(hypot(x[0] - x[2], x[1] - x[3]) > 0 ? 1 : 0, 1, 0);
  double col0[2] = {0.01, 3.0}, col1[2] = {NL_TWO_PI - 0.01, 1.0}, a[4], b[4];
  nl_cheng_rep_encode(NL_CHENG_REP_COSSIN, col0, 1, 2, mu, a);
  nl_cheng_rep_encode(NL_CHENG_REP_COSSIN, col1, 1, 2, mu, b);
  NL_CHECK_NEAR(hypot(a[0] - b[0], a[1] - b[1]), 2 * sin(0.01), 1e-12);
  for (int r = 0; r < 2; r++) {
    nl_cheng_rep rep = r ? NL_CHENG_REP_UNWRAP : NL_CHENG_REP_COSSIN;
    nl_cheng_rep_encode(rep, th, 2, 2, mu, x);
    nl_cheng_rep_decode(rep, x, 2, 2, mu, back);
    for (int i = 0; i < 4; i++) NL_CHECK_NEAR(back[i], th[i], 1e-12);
    NL_CHECK(nl_cheng_rep_dim(rep, 2) == (r ? 2u : 4u));
  }
  /* unwrap: around mu, so the two angles of column 0 differ by 0.02 */
  double u0[2] = {0.01, 3.0}, u1[2] = {NL_TWO_PI - 0.01, 3.0}, mu0[2] = {0.0, 3.0};
  nl_cheng_rep_encode(NL_CHENG_REP_UNWRAP, u0, 1, 2, mu0, a);
  nl_cheng_rep_encode(NL_CHENG_REP_UNWRAP, u1, 1, 2, mu0, b);
  NL_CHECK_NEAR(a[0] - b[0], 0.02, 1e-12);
}

/* A pool of n rows of nlow angles from k von-Mises-like blobs (sd 0.05); blob
 * 0 sits on the cut at 0 / 2pi. */
static nl_cheng_pool *synthetic_pool(size_t n, size_t nlow, size_t k, unsigned long seed)
{
  nl_cheng_pool *p = calloc(1, sizeof *p);
  p->nlow = nlow; p->n = n; p->runs = 1;
  p->low = malloc(nlow * sizeof *p->low);
  for (size_t j = 0; j < nlow; j++) p->low[j] = j;
  p->theta = malloc(n * nlow * sizeof *p->theta);
  p->e = calloc(n, sizeof *p->e);
  p->run = calloc(n, sizeof *p->run);
  p->run_best = calloc(1, sizeof(double)); p->run_start = calloc(1, sizeof(double));
  p->run_seconds = calloc(1, sizeof(double));
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(seed, "test.synthetic_pool", 0));
  for (size_t i = 0; i < n; i++)
    for (size_t j = 0; j < nlow; j++) {
      double centre = (double)((i % k) * (j + 1) % 5) * 1.25;   /* blob i%k, distinct centres */
      double t = fmod(centre + gsl_ran_gaussian(rng, 0.05) + NL_TWO_PI, NL_TWO_PI);
      p->theta[i * nlow + j] = t;
    }
  gsl_rng_free(rng);
  return p;
}

NL_TEST(clustering_and_aic_recover_k)
{
  nl_cheng_pool *pool = synthetic_pool(600, 4, 3, 7);
  nl_cheng_model_options o;
  nl_cheng_model_options_default(&o);
  o.samples = 450;       /* the other 150 are held out */
  o.cutoff = 1.0;        /* blobs: within ~0.5 (chord), between >= 1.1 */
  o.threshold = 10;
  nl_cheng_model *m;
  nl_error err;
  for (int r = 0; r < 2; r++) {
    o.rep = r ? NL_CHENG_REP_UNWRAP : NL_CHENG_REP_COSSIN;
    NL_CHECK(nl_cheng_model_fit(pool, &o, 1, &m, &err) == NL_OK);
    NL_CHECK(m->k0 == 3 && m->status == NL_CHENG_MODEL_OK && m->n_in == 450);
    if (r) NL_CHECK(m->k == 3 && m->npath == 2 && m->path[1].aic > m->path[0].aic - o.threshold);
    else NL_CHECK(m->k > 3);   /* cos/sin: AIC buys components for the circle's curvature (nl_cheng_repro.h) */
    nl_cheng_model_check ck;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    NL_CHECK(nl_cheng_model_assess(pool, m, 2000, rng, &ck, &err) == NL_OK);
    NL_CHECK(ck.n_held == 150 && fabs(ck.ll_held - ck.ll_train) < 0.1 * fabs(ck.ll_train) + 1);
    NL_CHECK(ck.ks_reject <= 0.5 && ck.ks_median < 0.05);
    gsl_rng_free(rng);
    nl_cheng_model_free(m);
  }
  /* the AIC rule from K0 = 1 climbs to 3 and stops */
  o.rep = NL_CHENG_REP_UNWRAP;
  o.cutoff = 100;
  NL_CHECK(nl_cheng_model_fit(pool, &o, 1, &m, &err) == NL_OK);
  NL_CHECK(m->k0 == 1 && m->k == 3 && m->status == NL_CHENG_MODEL_ONE_CLUSTER);
  nl_cheng_model_free(m);
  /* cutoff from a target K */
  o.cutoff = -1; o.target_k = 3;
  NL_CHECK(nl_cheng_model_fit(pool, &o, 1, &m, &err) == NL_OK);
  NL_CHECK(m->k0 == 3 && m->cutoff > 0.5 && m->cutoff < 2.5);
  nl_cheng_model_free(m);
  nl_cheng_pool_free(pool);
}

NL_TEST(degenerate_cases_are_statuses)
{
  nl_cheng_pool *pool = synthetic_pool(60, 3, 3, 9);
  nl_cheng_model_options o;
  nl_cheng_model_options_default(&o);
  nl_cheng_model *m;
  nl_error err;
  o.cutoff = 0;          /* every point its own cluster */
  NL_CHECK(nl_cheng_model_fit(pool, &o, 1, &m, &err) == NL_OK);
  NL_CHECK(m->status == NL_CHENG_MODEL_ONE_PER_POINT && m->gmm == NULL && m->k0 == 60);
  nl_noise_grad2 *g = nl_noise_grad2_alloc(512), *h = nl_noise_grad2_alloc(512);
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  NL_CHECK(nl_cheng_reproduce(g, m, 1, rng, h, &err) == NL_EINVAL);
  nl_cheng_model_free(m);
  o.cutoff = -1; o.target_k = 60;   /* pool too small for K */
  NL_CHECK(nl_cheng_model_fit(pool, &o, 1, &m, &err) == NL_OK && m->status == NL_CHENG_MODEL_TOO_SMALL);
  nl_cheng_model_free(m);
  o.target_k = 3; o.gmm.max_iter = 1;   /* EM cut short */
  NL_CHECK(nl_cheng_model_fit(pool, &o, 1, &m, &err) == NL_OK && m->status == NL_CHENG_MODEL_NOT_CONVERGED);
  nl_cheng_model_free(m);
  o.gmm.max_iter = 100; o.threshold = -1;
  NL_CHECK(nl_cheng_model_fit(pool, &o, 1, &m, &err) == NL_EINVAL && m == NULL);
  pool->n = 1;
  o.threshold = 0;
  NL_CHECK(nl_cheng_model_fit(pool, &o, 1, &m, &err) == NL_OK && m->status == NL_CHENG_MODEL_TOO_SMALL);
  nl_cheng_model_free(m);
  gsl_rng_free(rng);
  nl_noise_grad2_free(g); nl_noise_grad2_free(h);
  nl_cheng_pool_free(pool);
}

/* Draws of a fitted mixture have its mean and covariance within sampling error. */
NL_TEST(mixture_draws_match_moments)
{
  nl_cheng_pool *pool = synthetic_pool(300, 2, 2, 4);
  nl_cheng_model_options o;
  nl_cheng_model_options_default(&o);
  o.cutoff = -1; o.target_k = 2; o.k_extra = 0;
  nl_cheng_model *m;
  nl_error err;
  NL_CHECK(nl_cheng_model_fit(pool, &o, 1, &m, &err) == NL_OK && m->gmm && m->k == 2);
  const nl_gmm *g = m->gmm;
  size_t d = g->d, n = 40000;
  double mu[4] = {0}, cov[16] = {0};
  for (size_t k = 0; k < g->k; k++)
    for (size_t a = 0; a < d; a++) mu[a] += g->weights[k] * g->means[k * d + a];
  for (size_t k = 0; k < g->k; k++)
    for (size_t a = 0; a < d; a++)
      for (size_t b = 0; b < d; b++)
        cov[a * d + b] += g->weights[k] * (g->covs[(k * d + a) * d + b] +
                          (g->means[k * d + a] - mu[a]) * (g->means[k * d + b] - mu[b]));
  double *x = malloc(n * d * sizeof *x), sm[4] = {0}, sc[16] = {0};
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  nl_gmm_sample(g, rng, n, x, NULL);
  for (size_t i = 0; i < n; i++) for (size_t a = 0; a < d; a++) sm[a] += x[i * d + a] / (double)n;
  for (size_t i = 0; i < n; i++)
    for (size_t a = 0; a < d; a++)
      for (size_t b = 0; b < d; b++) sc[a * d + b] += (x[i * d + a] - sm[a]) * (x[i * d + b] - sm[b]) / (double)(n - 1);
  for (size_t a = 0; a < d; a++) {
    NL_CHECK_NEAR(sm[a], mu[a], 5 * sqrt(cov[a * d + a] / (double)n));
    for (size_t b = 0; b < d; b++)   /* se of a covariance <= sqrt((s_aa s_bb + s_ab^2) / n) */
      NL_CHECK_NEAR(sc[a * d + b], cov[a * d + b],
                    5 * sqrt((cov[a * d + a] * cov[b * d + b] + cov[a * d + b] * cov[a * d + b]) / (double)n) * 1.5);
  }
  free(x);
  gsl_rng_free(rng);
  nl_cheng_model_free(m);
  nl_cheng_pool_free(pool);
}

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

NL_TEST(reproduce_keeps_high_angles)
{
  nl_cheng_pattern *pat = test_flower(REPRO_PX, 16);
  nl_cheng_config c = small_config();
  nl_noise_grad2 *g = nl_noise_grad2_alloc(c.m), *h = nl_noise_grad2_alloc(c.m);
  nl_noise_grad2_seed(g, 8);
  nl_cheng_pool_options po;
  nl_cheng_pool_options_default(&po);
  po.runs = 6; po.keep = 10;
  nl_cheng_pool *pool;
  nl_error err;
  NL_CHECK(nl_cheng_pool_collect(g, &c, pat, &po, 2, &pool, &err) == NL_OK);
  nl_cheng_model_options mo;
  nl_cheng_model_options_default(&mo);
  mo.target_k = 3; mo.gmm.covariance = NL_GMM_DIAG; mo.k_extra = 2;
  nl_cheng_model *m;
  NL_CHECK(nl_cheng_model_fit(pool, &mo, 1, &m, &err) == NL_OK && m->gmm);
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  NL_CHECK(nl_cheng_reproduce(g, m, 1.0, rng, h, &err) == NL_OK);
  unsigned char *low = calloc(c.m, 1);
  for (size_t j = 0; j < m->nlow; j++) low[m->low[j]] = 1;
  double *a = malloc(c.m * sizeof *a), *b = malloc(c.m * sizeof *b);
  size_t nh = 0, moved = 0;
  for (size_t k = 0; k < c.m; k++)
    if (!low[k]) { a[nh] = g->angle[k]; b[nh++] = h->angle[k]; moved += g->angle[k] != h->angle[k]; }
  qsort(a, nh, sizeof *a, cmp_double);
  qsort(b, nh, sizeof *b, cmp_double);
  NL_CHECK(memcmp(a, b, nh * sizeof *a) == 0 && moved > nh / 2);
  NL_CHECK(nl_cheng_reproduce(g, m, 0.0, rng, h, &err) == NL_OK);
  for (size_t k = 0; k < c.m; k++) if (!low[k]) NL_CHECK(g->angle[k] == h->angle[k]);
  free(a); free(b); free(low);
  gsl_rng_free(rng);
  nl_cheng_model_free(m);
  nl_cheng_pool_free(pool);
  nl_noise_grad2_free(g); nl_noise_grad2_free(h);
  nl_cheng_pattern_free(pat);
}

int main(void) { return nl_test_run(); }
