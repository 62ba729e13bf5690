/* dense_em.h - one EM step of a Gaussian mixture written out plainly, as a
 * test oracle for src/stats/nl_gmm.c.
 *
 * E-step: for every point and component, log w_k + log N(x; mu_k, Sigma_k)
 * with log N = -(d log 2 pi + log det Sigma_k + |L_k^-1 (x - mu_k)|^2) / 2,
 * L_k the Cholesky factor (computed here, column by column) and L^-1 (x -
 * mu) by forward substitution; responsibilities by log-sum-exp. No BLAS,
 * no blocks, no rows left out.
 * M-step: N_k = 10 eps + sum_i r_ik, mu_k = sum_i r_ik x_i / N_k,
 * Sigma_k = sum_i r_ik (x_i - mu_k)(x_i - mu_k)^T / N_k + reg I (diagonal:
 * its diagonal only), w_k = N_k / sum N (by_total) or N_k / n (the first
 * M-step from labels: scikit-learn's _initialize).
 */
#ifndef DENSE_EM_H
#define DENSE_EM_H

#include <stddef.h>

/* cov: k d x d matrices (full) or k x d variances (diag). */
void dense_m_step(const double *x, size_t n, size_t d, size_t k, const double *R, double reg,
                  int diag, int by_total, double *w, double *mu, double *cov);
/* Returns sum_i log p(x_i); R (n x k, may be NULL) gets the responsibilities. */
double dense_e_step(const double *x, size_t n, size_t d, size_t k, int diag, const double *w,
                    const double *mu, const double *cov, double *R);

#endif
