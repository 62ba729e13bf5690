/* dense_em.c - see dense_em.h. */
#include "reference/dense_em.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

void dense_m_step(const double *x, size_t n, size_t d, size_t k, const double *R, double reg,
                  int diag, int by_total, double *w, double *mu, double *cov)
{
  double total = 0;
  for (size_t c = 0; c < k; c++) {
    double nk = 10 * DBL_EPSILON;
    for (size_t i = 0; i < n; i++)
      nk += R[i * k + c];
    for (size_t a = 0; a < d; a++) {
      double s = 0;
      for (size_t i = 0; i < n; i++)
        s += R[i * k + c] * x[i * d + a];
      mu[c * d + a] = s / nk;
    }
    for (size_t a = 0; a < d; a++)
      for (size_t b = 0; b < d; b++) {
        if (diag && b != a)
          continue;
        double s = 0;
        for (size_t i = 0; i < n; i++)
          s += R[i * k + c] * (x[i * d + a] - mu[c * d + a]) * (x[i * d + b] - mu[c * d + b]);
        double v = s / nk + (a == b ? reg : 0);
        if (diag)
          cov[c * d + a] = v;
        else
          cov[(c * d + a) * d + b] = v;
      }
    w[c] = nk;
    total += nk;
  }
  for (size_t c = 0; c < k; c++)
    w[c] /= by_total ? total : (double)n;
}

/* log N(x; mu, S) for S = L L^T given by L (lower, d x d). */
static double log_normal(const double *x, const double *mu, const double *L, size_t d)
{
  double z[64], logdet = 0, maha = 0;
  for (size_t a = 0; a < d; a++) {
    double s = x[a] - mu[a];
    for (size_t b = 0; b < a; b++)
      s -= L[a * d + b] * z[b];
    z[a] = s / L[a * d + a];
    maha += z[a] * z[a];
    logdet += 2 * log(L[a * d + a]);
  }
  return -0.5 * ((double)d * log(2 * M_PI) + logdet + maha);
}

double dense_e_step(const double *x, size_t n, size_t d, size_t k, int diag, const double *w,
                    const double *mu, const double *cov, double *R)
{
  double *L = calloc(k * d * d, sizeof *L), *lp = malloc(k * sizeof *lp), total = 0;
  for (size_t c = 0; c < k; c++) {   /* Cholesky, Cholesky-Banachiewicz order */
    double *l = L + c * d * d;
    for (size_t a = 0; a < d; a++)
      for (size_t b = 0; b <= a; b++) {
        double s = diag ? (a == b ? cov[c * d + a] : 0) : cov[(c * d + a) * d + b];
        for (size_t q = 0; q < b; q++)
          s -= l[a * d + q] * l[b * d + q];
        l[a * d + b] = a == b ? sqrt(s) : s / l[b * d + b];
      }
  }
  for (size_t i = 0; i < n; i++) {
    double top = -INFINITY, sum = 0;
    for (size_t c = 0; c < k; c++) {
      lp[c] = log(w[c]) + log_normal(x + i * d, mu + c * d, L + c * d * d, d);
      top = fmax(top, lp[c]);
    }
    for (size_t c = 0; c < k; c++)
      sum += exp(lp[c] - top);
    double lse = top + log(sum);
    total += lse;
    if (R)
      for (size_t c = 0; c < k; c++)
        R[i * k + c] = exp(lp[c] - lse);
  }
  free(L);
  free(lp);
  return total;
}
