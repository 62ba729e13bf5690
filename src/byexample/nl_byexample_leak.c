/* Leakage-corrected weights (nl_byexample_leak.h): transfer matrix measured
 * on the noise, Tukey (or Hann) taper, non-negative least squares. */
#include "byexample/nl_byexample_leak.h"
#include "spectrum/nl_spectrum.h"
#include "base/nl_parallel.h"

#include <float.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { MAXB = NL_WAVELET_MAX_BANDS };

const char *const nl_byexample_estimator_names[NL_BYEXAMPLE_ESTIMATORS] = {"eq12", "eq12_taper", "nnls_raw", "corrected"};

nl_status nl_byexample_band_power_taper(const double *img, int w, int h, int nbands, double frac,
                                        double *power, nl_error *err)
{
  if (frac <= 0) return nl_byexample_band_power(img, w, h, nbands, power, err);
  double *win = nl_xmalloc((size_t)w * h * sizeof *win);
  nl_spectrum_taper2(img, w, h, frac, win);
  nl_status st = nl_byexample_band_power(win, w, h, nbands, power, err);
  free(win);
  return st;
}

/* Both band powers of one image: one render serves both tapers. The size
 * is a transfer matrix's, which nl_byexample_transfer_measure checked; were
 * it refused all the same, the powers are NaN, never a transform's worth of
 * minutes. */
static void powers(const double *img, int w, int h, int nbands, double frac, double *raw, double *tapered)
{
  if (nl_byexample_band_power_taper(img, w, h, nbands, 0, raw, NULL) ||
      nl_byexample_band_power_taper(img, w, h, nbands, frac, tapered, NULL))
    for (int k = 0; k < nbands; k++) raw[k] = tapered[k] = NAN;
}

/* The transfer measurement's items (s, i): replicate s's noise of unit
 * weight in band i, its powers into its own slot P[s nbands + i]; per-thread
 * tile (reseeded when its replicate changes) and image. */
typedef struct {
  int tile, w, h, nbands;
  double frac;
  unsigned long seed;
  double (*P)[2][MAXB];
  nl_wavelet_tile *t[NL_PARALLEL_MAX];
  long seeded[NL_PARALLEL_MAX];
  double *img[NL_PARALLEL_MAX];
} transfer_job;

static void transfer_item(void *ctx, size_t item, int th)
{
  transfer_job *j = ctx;
  int s = (int)(item / (size_t)j->nbands), i = (int)(item % (size_t)j->nbands);
  unsigned long ss = nl_seed_stream(j->seed, "byexample.transfer", (unsigned long)s);
  if (!j->t[th]) {
    j->t[th] = nl_wavelet_tile_alloc(2, j->tile);
    j->img[th] = nl_xmalloc((size_t)j->w * j->h * sizeof *j->img[th]);
    j->seeded[th] = -1;
  }
  if (j->seeded[th] != s) { nl_wavelet_tile_seed(j->t[th], ss); j->seeded[th] = s; }
  double unit[MAXB];
  nl_wavelet_bands b;
  for (int k = 0; k < j->nbands; k++) unit[k] = k == i;
  nl_wavelet_bands_init(&b, j->nbands, unit, j->tile, ss, NULL);
  nl_wavelet_bands_grid(j->t[th], &b, j->w, j->h, 0, 1, j->img[th]);
  powers(j->img[th], j->w, j->h, j->nbands, j->frac, j->P[item][0], j->P[item][1]);
}

nl_status nl_byexample_transfer_measure(nl_byexample_transfer *T, int tile, int w, int h, int nbands,
                                        double frac, int nseeds, unsigned long seed, int threads,
                                        nl_error *err)
{
  memset(T, 0, sizeof *T);
  if (nl_spectrum_check_size(w, h, err)) return NL_EINVAL;
  T->w = w; T->h = h; T->nbands = nbands; T->tile = tile; T->frac = frac;
  T->sigma2 = nl_byexample_sigma2(tile);
  size_t n = (size_t)nseeds * (size_t)nbands;
  transfer_job *j = nl_xcalloc(1, sizeof *j);
  j->tile = tile; j->w = w; j->h = h; j->nbands = nbands; j->frac = frac; j->seed = seed;
  j->P = nl_xmalloc((n ? n : 1) * sizeof *j->P);
  nl_parallel_for(n, threads, transfer_item, j);
  for (size_t q = 0; q < n; q++) {   /* summed in replicate and band order, as a serial loop sums */
    int i = (int)(q % (size_t)nbands);
    for (int k = 0; k < 2; k++)
      for (int c = 0; c < nbands; c++) T->A[k][i * nbands + c] += j->P[q][k][c] / nseeds;
  }
  for (int t = 0; t < NL_PARALLEL_MAX; t++) {
    if (j->t[t]) nl_wavelet_tile_free(j->t[t]);
    free(j->img[t]);
  }
  free(j->P);
  free(j);
  return NL_OK;
}

/* Least squares on the columns cols[0..np-1] of M (m x n, m >= np) by
 * Householder QR: z[c] for c in cols. */
static void lsq(const double *M, int m, int n, const int *cols, int np, const double *b, double *z)
{
  double *Q = nl_xmalloc((size_t)m * np * sizeof *Q), *y = nl_xmalloc((size_t)m * sizeof *y);
  double *v = nl_xmalloc((size_t)m * sizeof *v);
  for (int i = 0; i < m; i++) {
    y[i] = b[i];
    for (int c = 0; c < np; c++) Q[i * np + c] = M[i * n + cols[c]];
  }
  for (int k = 0; k < np && k < m; k++) {   /* reflector v zeroes column k below row k */
    double norm = 0, vv = 0;
    for (int i = k; i < m; i++) norm += Q[i * np + k] * Q[i * np + k];
    if (norm == 0) continue;
    double alpha = Q[k * np + k] > 0 ? -sqrt(norm) : sqrt(norm);
    for (int i = k; i < m; i++) { v[i] = Q[i * np + k] - (i == k ? alpha : 0); vv += v[i] * v[i]; }
    if (vv == 0) continue;
    for (int j = k; j <= np; j++) {   /* column np stands for y */
      double s = 0;
      for (int i = k; i < m; i++) s += v[i] * (j < np ? Q[i * np + j] : y[i]);
      s *= 2 / vv;
      for (int i = k; i < m; i++) {
        if (j < np) Q[i * np + j] -= s * v[i]; else y[i] -= s * v[i];
      }
    }
  }
  for (int k = np - 1; k >= 0; k--) {   /* R z = Q^T b */
    double s = y[k];
    for (int j = k + 1; j < np; j++) s -= Q[k * np + j] * z[cols[j]];
    z[cols[k]] = s / Q[k * np + k];
  }
  free(Q);
  free(y);
  free(v);
}

static double residual(const double *M, int m, int n, const double *b, const double *x, double *g)
{
  double rr = 0;
  if (g) for (int j = 0; j < n; j++) g[j] = 0;
  for (int i = 0; i < m; i++) {
    double r = b[i];
    for (int j = 0; j < n; j++) r -= M[i * n + j] * x[j];
    rr += r * r;
    if (g) for (int j = 0; j < n; j++) g[j] += M[i * n + j] * r;   /* g = M^T (b - M x) */
  }
  return sqrt(rr);
}

double nl_byexample_nnls(const double *M, int m, int n, const double *b, double *x)
{
  int passive[MAXB] = {0}, cols[MAXB], iter = 0;
  double g[MAXB], z[MAXB], colmax = 0;
  for (int j = 0; j < n; j++) {
    double c = 0;
    for (int i = 0; i < m; i++) c += fabs(M[i * n + j]);
    colmax = fmax(colmax, c);
    x[j] = 0;
  }
  double tol = 10 * DBL_EPSILON * colmax * (m > n ? m : n);   /* scipy's tolerance */
  for (;;) {
    residual(M, m, n, b, x, g);
    int t = -1;
    for (int j = 0; j < n; j++)
      if (!passive[j] && g[j] > tol && (t < 0 || g[j] > g[t])) t = j;
    if (t < 0) break;   /* Kuhn-Tucker conditions hold */
    passive[t] = 1;
    for (;;) {   /* solve on the passive set; step back while it leaves x >= 0 */
      if (++iter > 3 * n) return -1;
      int np = 0;
      for (int j = 0; j < n; j++) { z[j] = 0; if (passive[j]) cols[np++] = j; }
      lsq(M, m, n, cols, np, b, z);
      double alpha = 2;
      for (int j = 0; j < n; j++)
        if (passive[j] && z[j] <= 0) alpha = fmin(alpha, x[j] / (x[j] - z[j]));
      if (alpha > 1) { memcpy(x, z, (size_t)n * sizeof *x); break; }
      for (int j = 0; j < n; j++) {
        x[j] += alpha * (z[j] - x[j]);
        if (passive[j] && x[j] <= tol) { passive[j] = 0; x[j] = 0; }
      }
    }
  }
  return residual(M, m, n, b, x, NULL);
}

/* The weights of estimator `kind` from the image's raw and tapered band powers. */
static void solve(const nl_byexample_transfer *T, int kind, const double p[2][MAXB], double *wts)
{
  int nb = T->nbands, taper = kind == NL_BYEXAMPLE_EQ12_TAPER || kind == NL_BYEXAMPLE_CORRECTED;
  double M[MAXB * MAXB] = {0};
  if (kind == NL_BYEXAMPLE_EQ12 || kind == NL_BYEXAMPLE_EQ12_TAPER) {   /* eq. 12 */
    for (int k = 0; k < nb; k++) wts[k] = sqrt(p[taper][k] / T->sigma2);
    return;
  }
  for (int i = 0; i < nb; i++)   /* p_j = sum_i A[i][j] w_i^2: M = A^T */
    for (int j = 0; j < nb; j++) M[j * nb + i] = T->A[taper][i * nb + j];
  nl_byexample_nnls(M, nb, nb, p[taper], wts);   /* at the iteration limit x is still >= 0: used */
  for (int k = 0; k < nb; k++) wts[k] = sqrt(wts[k]);
}

void nl_byexample_estimate(const nl_byexample_transfer *T, int kind, const double *img, double *wts)
{
  double p[2][MAXB];
  powers(img, T->w, T->h, T->nbands, T->frac, p[0], p[1]);
  solve(T, kind, p, wts);
}

void nl_byexample_trial(const nl_byexample_transfer *T, nl_wavelet_tile *t, unsigned long seed, int nfine,
                        double *truth, double *est, double *img, double *err, double *fine, double *power)
{
  int nb = T->nbands;
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(seed, "byexample.true_weights", 0));   /* apart from the tile's stream */
  const double lo = NL_BYEXAMPLE_TRUE_WEIGHT_MIN, hi = NL_BYEXAMPLE_TRUE_WEIGHT_MAX;
  for (int k = 0; k < nb; k++) truth[k] = lo + (hi - lo) * gsl_rng_uniform(rng);
  gsl_rng_free(rng);
  nl_wavelet_tile_seed(t, seed);
  nl_wavelet_bands b;
  nl_wavelet_bands_init(&b, nb, truth, t->n, seed, NULL);
  nl_wavelet_bands_grid(t, &b, T->w, T->h, 0, 1, img);
  double p[2][MAXB];
  powers(img, T->w, T->h, nb, T->frac, p[0], p[1]);
  for (int e = 0; e < NL_BYEXAMPLE_ESTIMATORS; e++) {
    double *w = est + e * nb, se = 0, st = 0, sef = 0, stf = 0, pe = 0;
    solve(T, e, p, w);
    for (int k = 0; k < nb; k++) {
      double d2 = (w[k] - truth[k]) * (w[k] - truth[k]), t2 = truth[k] * truth[k];
      se += d2; st += t2; pe += w[k] * w[k];
      if (k < nfine) { sef += d2; stf += t2; }
    }
    err[e] = sqrt(se / st);
    fine[e] = stf > 0 ? sqrt(sef / stf) : 0;
    power[e] = pe / st;
  }
}

/* Trial k of nl_byexample_trials into its own slots (truth, est, E); a
 * per-thread tile (each trial reseeds it) and image. */
typedef struct {
  const nl_byexample_transfer *T;
  const unsigned long *seeds;
  int n, nfine;
  double *E, (*truth)[MAXB], (*est)[NL_BYEXAMPLE_ESTIMATORS * MAXB];
  nl_wavelet_tile *t[NL_PARALLEL_MAX];
  double *img[NL_PARALLEL_MAX];
} trials_job;

static void trial_item(void *ctx, size_t k, int th)
{
  enum { NE = NL_BYEXAMPLE_ESTIMATORS };
  trials_job *j = ctx;
  if (!j->t[th]) {
    j->t[th] = nl_wavelet_tile_alloc(2, j->T->tile);
    j->img[th] = nl_xmalloc((size_t)j->T->w * j->T->h * sizeof *j->img[th]);
  }
  double e[NE], f[NE], pw[NE];
  nl_byexample_trial(j->T, j->t[th], j->seeds[k], j->nfine, j->truth[k], j->est[k], j->img[th], e, f, pw);
  for (int q = 0; q < NE; q++) {
    j->E[(0 * NE + q) * j->n + (int)k] = e[q];
    j->E[(1 * NE + q) * j->n + (int)k] = f[q];
    j->E[(2 * NE + q) * j->n + (int)k] = pw[q];
  }
}

void nl_byexample_trials(const nl_byexample_transfer *T, const unsigned long *seeds, int n,
                         int nfine, double *E, double *rms, double *bias, int threads)
{
  enum { NE = NL_BYEXAMPLE_ESTIMATORS };
  int nb = T->nbands;
  double sq[NE * MAXB] = {0}, sum[NE * MAXB] = {0};
  trials_job *j = nl_xcalloc(1, sizeof *j);
  j->T = T; j->seeds = seeds; j->n = n; j->nfine = nfine; j->E = E;
  j->truth = nl_xmalloc((size_t)(n > 0 ? n : 1) * sizeof *j->truth);
  j->est = nl_xmalloc((size_t)(n > 0 ? n : 1) * sizeof *j->est);
  nl_parallel_for((size_t)(n > 0 ? n : 0), threads, trial_item, j);
  for (int k = 0; k < n; k++)   /* sums in trial order */
    for (int q = 0; q < NE; q++)
      for (int b = 0; b < nb; b++) {
        double d = j->est[k][q * nb + b] - j->truth[k][b];
        sq[q * nb + b] += d * d;
        sum[q * nb + b] += d;
      }
  for (int i = 0; i < NE * nb; i++) {
    if (rms) rms[i] = sqrt(sq[i] / n);
    if (bias) bias[i] = sum[i] / n;
  }
  for (int t = 0; t < NL_PARALLEL_MAX; t++) {
    if (j->t[t]) nl_wavelet_tile_free(j->t[t]);
    free(j->img[t]);
  }
  free(j->truth);
  free(j->est);
  free(j);
}

int nl_byexample_fit_all(const double *img, int w, int h, int tile, double frac, int nseeds, unsigned long tseed,
                         int nsyn, unsigned long rseed, double resid[NL_BYEXAMPLE_ESTIMATORS][2])
{
  nl_byexample_transfer T;
  double wts[MAXB];
  if (nl_byexample_transfer_measure(&T, tile, w, h, nl_byexample_band_count(w, h), frac, nseeds, tseed, 1,
                                    NULL))   /* callers thread over images */
    return -1;
  for (int q = 0; q < NL_BYEXAMPLE_ESTIMATORS; q++) {
    nl_byexample_estimate(&T, q, img, wts);
    nl_byexample_fit_residual(&T, wts, img, nsyn, rseed, resid[q]);
  }
  return T.nbands;
}

void nl_byexample_fit_residual(const nl_byexample_transfer *T, const double *wts, const double *img,
                               int nsyn, unsigned long seed, double resid[2])
{
  int w = T->w, h = T->h, nb = T->nbands;
  double target[2][MAXB], syn[2][MAXB] = {{0}}, p[2][MAXB];
  double *noise = nl_xmalloc((size_t)w * h * sizeof *noise);
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(2, T->tile);
  powers(img, w, h, nb, T->frac, target[0], target[1]);
  for (int s = 0; s < nsyn; s++) {
    unsigned long ss = nl_seed_stream(seed, "byexample.resynth", (unsigned long)s);
    nl_wavelet_tile_seed(t, ss);
    nl_wavelet_bands b;
    nl_wavelet_bands_init(&b, nb, wts, T->tile, ss, NULL);
    nl_wavelet_bands_grid(t, &b, w, h, 0, 1, noise);
    powers(noise, w, h, nb, T->frac, p[0], p[1]);
    for (int k = 0; k < 2; k++)
      for (int j = 0; j < nb; j++) syn[k][j] += p[k][j] / nsyn;
  }
  for (int k = 0; k < 2; k++) {
    double ss = 0;
    int used = 0;
    for (int j = 0; j < nb; j++) {
      if (target[k][j] <= 0) continue;
      double r = (syn[k][j] - target[k][j]) / target[k][j];
      ss += r * r;
      used++;
    }
    resid[k] = used ? sqrt(ss / used) : 0;
  }
  nl_wavelet_tile_free(t);
  free(noise);
}

double nl_byexample_paired_p(const double *a, const double *b, int n)
{
  double m = 0, ss = 0;
  for (int i = 0; i < n; i++) m += (a[i] - b[i]) / n;
  for (int i = 0; i < n; i++) ss += (a[i] - b[i] - m) * (a[i] - b[i] - m);
  if (n < 2) return 1;
  double se = sqrt(ss / (n - 1) / n);
  if (se == 0) return m == 0 ? 1 : 0;
  return 2 * gsl_cdf_tdist_Q(fabs(m) / se, n - 1);
}
