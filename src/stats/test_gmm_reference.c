/* test_gmm_reference.c - EM of nl_gmm_fit against EM written out densely
 * (tests/reference/dense_em.c: plain loops, its own Cholesky, no BLAS, no
 * rows left out), from the same initial labels.
 *
 * 400 fits: n 20..300 points in 1..4 dimensions, 1..4 components, blobs of
 * random centres and scales (some overlapping, some far apart, some around
 * 1e3), random labels with every component holding at least two points,
 * full and diagonal covariances, 1, 2 or 5 iterations (tol 0, so exactly
 * that many). Compared after the last M-step: every weight, mean and
 * covariance entry, and the log-likelihood of the final parameters.
 *
 * Tolerance: 1e-9, relative to the data's scale (weights: absolute;
 * means: over max |x|; covariances: over max |x - mean|^2 + reg;
 * log-likelihood: over n (1 + |mean log p|)). The library sums with BLAS
 * (dgemm, dsyrk: blocked, any order the kernel picks), leaves out rows
 * with r_ik < 1e-20 max r (each changes Sigma_k by < 1e-20 of its scale),
 * and forms L^-1 explicitly; each step's rounding is a few 1e-16 of the
 * scale, and EM carries it on: an iterate's error can grow by the
 * conditioning of the fixed-point map from one step to the next. Measured:
 * 2.8e-13 (weights, means, covariances), 4.8e-11 (log-likelihood); a wrong
 * term is O(1e-3) or more.
 *
 * The E-step alone (the library's final parameters through the oracle's
 * E-step): 1e-10 on the same scale. The library multiplies x - mu by the
 * explicit inverse factor L^-1, the oracle solves L z = x - mu: the two
 * differ by about cond(L) eps |z|^2, and full 4-D covariances fitted from
 * 22-27 points in 3-4 components are nearly singular (rank-deficient plus
 * reg I): measured 5.6e-12 there, below 1e-13 for every diagonal fit.
 */
#include "stats/nl_gmm.h"
#include "nl_test.h"
#include "reference/dense_em.h"

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NFITS 400
#define TOL 1e-9

NL_TEST(em_matches_dense_em)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 1977);
  double worst[5] = {0};   /* weights, means, covariances, loglik, E-step alone */
  long fits = 0;
  for (int t = 0; t < NFITS; t++) {
    size_t n = 20 + gsl_rng_uniform_int(r, 281), d = 1 + gsl_rng_uniform_int(r, 4);
    size_t k = 1 + gsl_rng_uniform_int(r, 4);
    int diag = t % 2, iters = t % 3 == 0 ? 1 : t % 3 == 1 ? 2 : 5;
    double offset = t % 5 == 4 ? 1e3 : 0, spread = t % 7 == 0 ? 0.5 : 6;
    double centre[4][4], sd[4];
    for (size_t c = 0; c < 4; c++) {
      sd[c] = 0.2 + 2 * gsl_rng_uniform(r);
      for (size_t a = 0; a < d; a++)
        centre[c][a] = offset + gsl_ran_gaussian(r, spread);
    }
    double *x = malloc(n * d * sizeof *x), xmax = 0;
    int *lab = malloc(n * sizeof *lab);
    for (size_t i = 0; i < n; i++) {
      size_t c = gsl_rng_uniform_int(r, 4);
      for (size_t a = 0; a < d; a++) {
        x[i * d + a] = centre[c][a] + gsl_ran_gaussian(r, sd[c]);
        xmax = fmax(xmax, fabs(x[i * d + a]));
      }
      lab[i] = i < 2 * k ? (int)(i % k) : (int)gsl_rng_uniform_int(r, k);
    }
    nl_gmm_options o;
    nl_gmm_options_default(&o);
    o.covariance = diag ? NL_GMM_DIAG : NL_GMM_FULL;
    o.tol = 0;
    o.max_iter = (size_t)iters;
    o.init_labels = lab;
    nl_gmm *g = nl_gmm_alloc(k, d, o.covariance);
    NL_CHECK(nl_gmm_fit(g, x, n, &o, NULL) == NL_OK);
    NL_CHECK(g->iterations == (size_t)iters);

    size_t nc = diag ? k * d : k * d * d;
    double *R = calloc(n * k, sizeof *R), *w = malloc(k * sizeof *w);
    double *mu = malloc(k * d * sizeof *mu), *cov = malloc(nc * sizeof *cov);
    for (size_t i = 0; i < n; i++)
      R[i * k + (size_t)lab[i]] = 1;
    dense_m_step(x, n, d, k, R, o.reg_covar, diag, 0, w, mu, cov);
    for (int it = 0; it < iters; it++) {
      dense_e_step(x, n, d, k, diag, w, mu, cov, R);
      dense_m_step(x, n, d, k, R, o.reg_covar, diag, 1, w, mu, cov);
    }
    double ll = dense_e_step(x, n, d, k, diag, w, mu, cov, NULL);

    double cscale = o.reg_covar;
    for (size_t i = 0; i < n; i++)
      for (size_t a = 0; a < d; a++)
        for (size_t c = 0; c < k; c++)
          cscale = fmax(cscale, pow(x[i * d + a] - mu[c * d + a], 2) + o.reg_covar);
    for (size_t c = 0; c < k; c++) {
      worst[0] = fmax(worst[0], fabs(g->weights[c] - w[c]));
      for (size_t a = 0; a < d; a++)
        worst[1] = fmax(worst[1], fabs(g->means[c * d + a] - mu[c * d + a]) / xmax);
    }
    for (size_t q = 0; q < nc; q++)
      worst[2] = fmax(worst[2], fabs(g->covs[q] - cov[q]) / cscale);
    worst[3] = fmax(worst[3], fabs(g->loglik - ll) / ((double)n * (1 + fabs(ll) / (double)n)));
    /* the E-step alone: the library's final parameters through the oracle */
    double same = dense_e_step(x, n, d, k, diag, g->weights, g->means, g->covs, NULL);
    double e4 = fabs(g->loglik - same) / ((double)n * (1 + fabs(same) / (double)n));
    worst[4] = fmax(worst[4], e4);
    fits++;
    nl_gmm_free(g);
    free(x); free(lab); free(R); free(w); free(mu); free(cov);
  }
  printf("  %ld fits: max error (scaled, see above) weights %.3g, means %.3g, covariances %.3g,"
         " log-likelihood %.3g, at the same parameters %.3g\n", fits, worst[0], worst[1],
         worst[2], worst[3], worst[4]);
  for (int q = 0; q < 4; q++)
    NL_CHECK(worst[q] <= TOL);
  NL_CHECK(worst[4] <= 1e-10);
  gsl_rng_free(r);
}

int main(void) { return nl_test_run(); }
