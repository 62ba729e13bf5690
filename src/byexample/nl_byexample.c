#include "byexample/nl_byexample.h"
#include "byexample/nl_byexample_leak.h"
#include "spectrum/nl_spectrum.h"
#include "stats/nl_stats.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_interp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdio.h>

/* ---- noise by example (sec. 4) ------------------------------------------ */

int nl_byexample_band_count(int w, int h)
{
  /* Lowest non-zero frequency 1/max(w, h) cycles per pixel lies in band
   * floor(log2 max(w, h)) of eq. 13 (512 -> 9). */
  int m = w > h ? w : h, k = 0;
  while ((2 << k) <= m) k++;
  return k < NL_WAVELET_MAX_BANDS ? k : NL_WAVELET_MAX_BANDS;
}

/* Eq. 13 band k = i - 1 for a frequency with max(|f_x|, |f_y|) = m cycles per
 * pixel (m > 0): i = floor(log2(1 / 2m)) + 1. frexp keeps exact powers of two
 * on the right side of each boundary. */
static int band_of(double m)
{
  int e;
  frexp(1.0 / (2.0 * m), &e);   /* 1/(2m) = f 2^e, f in [1/2, 1) */
  return e - 1;
}

nl_status nl_byexample_band_power(const double *img, int w, int h, int nbands, double *power,
                                  nl_error *err)
{
  double *P = nl_xmalloc((size_t)w * h * sizeof *P);
  if (nl_spectrum_power2(img, w, h, P, err)) {
    free(P);
    return NL_EINVAL;
  }
  memset(power, 0, (size_t)nbands * sizeof *power);
  for (int v = 0; v < h; v++) {
    double fy = fabs(nl_spectrum_freq(v, h));
    for (int u = 0; u < w; u++) {
      double m = fmax(fabs(nl_spectrum_freq(u, w)), fy);
      if (m == 0) continue;   /* DC: in no band */
      int k = band_of(m);
      if (k < nbands) power[k] += P[(size_t)v * w + u];
    }
  }
  free(P);
  return NL_OK;
}

nl_status nl_byexample_weights(const double *img, int w, int h, int nbands, double sigma2, double *wts,
                               nl_error *err)
{
  if (nl_byexample_band_power(img, w, h, nbands, wts, err)) return NL_EINVAL;
  for (int k = 0; k < nbands; k++) wts[k] = sqrt(wts[k] / sigma2);
  return NL_OK;
}

nl_status nl_byexample_band_leakage(const nl_wavelet_tile *t, int size, int nbands, unsigned long seed,
                                    double *share, double *var, nl_error *err)
{
  if (nl_spectrum_check_size(size, size, err)) return NL_EINVAL;
  double *img = nl_xmalloc((size_t)size * size * sizeof *img), w[NL_WAVELET_MAX_BANDS];
  for (int k = 0; k < nbands; k++) {
    nl_wavelet_bands b;
    for (int j = 0; j < nbands; j++) w[j] = j == k;
    nl_wavelet_bands_init(&b, nbands, w, t->n, seed, NULL);
    nl_wavelet_bands_grid(t, &b, size, size, 0, 1, img);
    double *row = share + (size_t)k * nbands;
    if (nl_byexample_band_power(img, size, size, nbands, row, err)) {   /* checked above */
      free(img);
      return NL_EINVAL;
    }
    var[k] = 0;
    for (int j = 0; j < nbands; j++) var[k] += row[j];
    for (int j = 0; j < nbands; j++) row[j] /= var[k];
  }
  free(img);
  return NL_OK;
}

double nl_byexample_sigma2(int n)
{
  /* Cached: synthesis and analysis ask for the same tile period. Per thread,
   * so that syntheses run in parallel (nl_parallel_for) never read a half-
   * written cache (ThreadSanitizer found the shared one racing). */
  static _Thread_local int cached_n;
  static _Thread_local double cached;
  if (n == cached_n) return cached;
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(2, n);
  if (!t) return 0;
  double s = 0;
  for (unsigned long k = 0; k < 4; k++) {   /* fixed draws: a constant of the method */
    nl_wavelet_tile_seed(t, nl_seed_stream(0, "example.sigma_calibration", k));
    s += nl_wavelet_tile_variance(t, 4);
  }
  nl_wavelet_tile_free(t);
  cached_n = n;
  cached = s / 4;
  return cached;
}

/* ---- colour (sec. 5.1) --------------------------------------------------- */

static int colour_channels(const nl_image *im) { return im->channels >= 3 ? 3 : 1; }

/* Orients the principal axes: entries summing >= 0 (ties: largest entry
 * positive), then det = +1 by flipping the weakest axis. */
static void orient_axes(double M[3][3])
{
  for (int r = 0; r < 3; r++) {
    double s = M[r][0] + M[r][1] + M[r][2];
    if (fabs(s) < 1e-9) {
      int j = 0;
      for (int c = 1; c < 3; c++) if (fabs(M[r][c]) > fabs(M[r][j])) j = c;
      s = M[r][j];
    }
    if (s < 0) for (int c = 0; c < 3; c++) M[r][c] = -M[r][c];
  }
  double det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1])
             - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0])
             + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  if (det < 0) for (int c = 0; c < 3; c++) M[2][c] = -M[2][c];
}

nl_status nl_byexample_pca(const nl_image *im, double mean[3], double matrix[3][3], nl_error *err)
{
  int nch = colour_channels(im), C = im->channels;
  size_t n = (size_t)im->width * im->height;
  if (n == 0) return nl_fail(err, NL_EINVAL, "empty image");
  double cov[9] = {0};
  memset(matrix, 0, 9 * sizeof(double));
  for (int c = 0; c < 3; c++) {
    mean[c] = 0;
    if (c >= nch) continue;
    for (size_t i = 0; i < n; i++) mean[c] += im->data[i * C + c];
    mean[c] /= (double)n;
  }
  if (nch == 1) { matrix[0][0] = 1; return NL_OK; }
  for (size_t i = 0; i < n; i++) {
    const float *px = im->data + i * C;
    double d[3] = {px[0] - mean[0], px[1] - mean[1], px[2] - mean[2]};
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) cov[3 * a + b] += d[a] * d[b];
  }
  gsl_matrix_view A = gsl_matrix_view_array(cov, 3, 3);
  gsl_vector *eval = gsl_vector_alloc(3);
  gsl_matrix *evec = gsl_matrix_alloc(3, 3);
  gsl_eigen_symmv_workspace *ws = gsl_eigen_symmv_alloc(3);
  int rc = gsl_eigen_symmv(&A.matrix, eval, evec, ws);
  gsl_eigen_symmv_sort(eval, evec, GSL_EIGEN_SORT_VAL_DESC);
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) matrix[r][c] = gsl_matrix_get(evec, c, r);   /* columns -> rows */
  gsl_eigen_symmv_free(ws);
  gsl_matrix_free(evec);
  gsl_vector_free(eval);
  if (rc) return nl_fail(err, NL_ENUM, "PCA: eigen decomposition failed");
  orient_axes(matrix);
  return NL_OK;
}

void nl_byexample_decorrelate(const nl_image *im, int nch, const double mean[3],
                              const double matrix[3][3], double **plane)
{
  size_t n = (size_t)im->width * im->height;
  for (size_t i = 0; i < n; i++) {
    const float *px = im->data + i * im->channels;
    for (int r = 0; r < nch; r++) {
      double s = 0;
      for (int c = 0; c < nch; c++) s += matrix[r][c] * (px[c] - mean[c]);
      plane[r][i] = s;
    }
  }
}

void nl_byexample_recorrelate(double *const *plane, int nch, const double mean[3],
                              const double matrix[3][3], nl_image *out)
{
  size_t n = (size_t)out->width * out->height;
  for (size_t i = 0; i < n; i++) {
    float *px = out->data + i * out->channels;
    for (int c = 0; c < nch; c++) {
      double s = mean[c];
      for (int r = 0; r < nch; r++) s += matrix[r][c] * plane[r][i];   /* M^T */
      px[c] = (float)s;
    }
  }
}

/* ---- histograms (sec. 5.2) ----------------------------------------------- */

void nl_byexample_quantiles(const double *v, size_t n, double *q)
{
  double *s = nl_xmalloc(n * sizeof *s);
  memcpy(s, v, n * sizeof *s);
  nl_stats_sort(s, n);
  for (int j = 0; j < NL_BYEXAMPLE_HIST; j++) {
    double pos = (double)j / (NL_BYEXAMPLE_HIST - 1) * (double)(n - 1);
    size_t i = (size_t)pos;
    double f = pos - (double)i;
    q[j] = i + 1 < n ? s[i] + f * (s[i + 1] - s[i]) : s[n - 1];
  }
  free(s);
}

void nl_byexample_hist(const double *v, size_t n, nl_byexample_hist_kind kind, double *q)
{
  if (kind == NL_HIST_PAPER) { nl_byexample_quantiles(v, n, q); return; }
  double p[NL_BYEXAMPLE_HIST_MAX], *s = nl_xmalloc(n * sizeof *s);
  int m = nl_byexample_hist_knots(kind, NULL, p);
  memcpy(s, v, n * sizeof *s);
  nl_stats_sort(s, n);
  /* Order statistic r sits at p = (r + 1/2) / n, the same plotting position
   * as nl_byexample_gaussianize, so a Gaussian channel's knots lie on the
   * line its gaussianized values do; beyond the first and last order
   * statistics the min and max. */
  for (int j = 0; j < m; j++) {
    double pos = fmin(fmax(p[j] * (double)n - 0.5, 0.0), (double)(n - 1));
    size_t i = (size_t)pos;
    double f = pos - (double)i;
    q[j] = i + 1 < n ? s[i] + f * (s[i + 1] - s[i]) : s[n - 1];
  }
  free(s);
}

void nl_byexample_gaussianize(double *v, size_t n)
{
  size_t *order = nl_xmalloc((n ? n : 1) * sizeof *order);
  nl_stats_argsort(v, n, order);   /* ties by index */
  for (size_t k = 0; k < n; k++) v[order[k]] = gsl_cdf_ugaussian_Pinv(((double)k + 0.5) / (double)n);
  free(order);
}

/* Fritsch-Carlson slopes: PCHIP's harmonic mean inside (Fritsch & Butland),
 * the shape-preserving three-point formula at the ends, then FC's limiter
 * alpha^2 + beta^2 <= 9 on every interval. */
static void fc_slopes(const double *x, const double *y, int n, double *d)
{
  double del[64] = {0}, hh[64] = {0};
  for (int k = 0; k + 1 < n; k++) { hh[k] = x[k + 1] - x[k]; del[k] = (y[k + 1] - y[k]) / hh[k]; }
  for (int k = 1; k + 1 < n; k++) {
    if (del[k - 1] * del[k] <= 0) { d[k] = 0; continue; }
    double w1 = 2 * hh[k] + hh[k - 1], w2 = hh[k] + 2 * hh[k - 1];
    d[k] = (w1 + w2) / (w1 / del[k - 1] + w2 / del[k]);
  }
  for (int e = 0; e < 2; e++) {   /* ends */
    int k = e ? n - 1 : 0, a = e ? n - 2 : 0, b = e ? n - 3 : 1;
    double h0 = hh[a], h1 = hh[b], d0 = del[a], d1 = del[b];
    double s = n > 2 ? ((2 * h0 + h1) * d0 - h0 * d1) / (h0 + h1) : d0;
    if (s * d0 <= 0) s = 0;
    else if (d0 * d1 < 0 && fabs(s) > 3 * fabs(d0)) s = 3 * d0;
    d[k] = s;
  }
  for (int k = 0; k + 1 < n; k++) {
    if (del[k] == 0) { d[k] = d[k + 1] = 0; continue; }
    double al = d[k] / del[k], be = d[k + 1] / del[k], r2 = al * al + be * be;
    if (r2 > 9) { double t = 3 / sqrt(r2); d[k] = t * al * del[k]; d[k + 1] = t * be * del[k]; }
  }
}

static double hermite(const double *x, const double *y, const double *d, int n, double t)
{
  int k = 0;
  while (k + 2 < n && t > x[k + 1]) k++;
  double h = x[k + 1] - x[k], s = (t - x[k]) / h, s2 = s * s, s3 = s2 * s;
  /* Written around y[k] so that a flat interval stays exactly flat. */
  return y[k] + (y[k + 1] - y[k]) * (3 * s2 - 2 * s3) + h * (d[k] * (s3 - 2 * s2 + s) + d[k + 1] * (s3 - s2));
}

void nl_byexample_spline(const double *x, const double *y, int n, nl_byexample_spline_kind kind,
                         const double *xs, double *ys, size_t m)
{
  if (kind == NL_SPLINE_STEFFEN) {
    gsl_interp *ip = gsl_interp_alloc(gsl_interp_steffen, (size_t)n);
    gsl_interp_accel *acc = gsl_interp_accel_alloc();
    gsl_interp_init(ip, x, y, (size_t)n);
    for (size_t i = 0; i < m; i++)
      ys[i] = gsl_interp_eval(ip, x, y, fmin(fmax(xs[i], x[0]), x[n - 1]), acc);
    gsl_interp_accel_free(acc);
    gsl_interp_free(ip);
    return;
  }
  double d[64];
  fc_slopes(x, y, n, d);
  for (size_t i = 0; i < m; i++) ys[i] = hermite(x, y, d, n, fmin(fmax(xs[i], x[0]), x[n - 1]));
}

void nl_byexample_match(double *v, size_t n, double sigma, const double *q, nl_byexample_spline_kind kind)
{
  double p[NL_BYEXAMPLE_HIST];
  for (int j = 0; j < NL_BYEXAMPLE_HIST; j++) p[j] = (double)j / (NL_BYEXAMPLE_HIST - 1);
  /* The expected CDF of the noise (a Gaussian of variance sigma^2, eq. 14)
   * takes noise to a probability, the exemplar's inverse cumulative
   * histogram takes it to an intensity. */
  for (size_t i = 0; i < n; i++) v[i] = gsl_cdf_ugaussian_P(v[i] / sigma);
  if (q[NL_BYEXAMPLE_HIST - 1] == q[0]) {   /* constant channel */
    for (size_t i = 0; i < n; i++) v[i] = q[0];
    return;
  }
  nl_byexample_spline(p, q, NL_BYEXAMPLE_HIST, kind, v, v, n);
}

void nl_byexample_match_kind(double *v, size_t n, double sigma, nl_byexample_hist_kind hk, const double *q,
                             nl_byexample_spline_kind kind)
{
  if (hk == NL_HIST_PAPER) { nl_byexample_match(v, n, sigma, q, kind); return; }
  double z[NL_BYEXAMPLE_HIST_MAX];
  int m = nl_byexample_hist_knots(hk, z, NULL);
  if (q[m - 1] == q[0]) {   /* constant channel */
    for (size_t i = 0; i < n; i++) v[i] = q[0];
    return;
  }
  /* The noise in sd units is z itself: the cubic through (z_j, q_j) is the
   * exemplar's quantile function in Gaussian coordinates, clamped to the
   * outer knots (+-4 sd, 6e-5 of a Gaussian lies beyond). */
  for (size_t i = 0; i < n; i++) v[i] /= sigma;
  nl_byexample_spline(z, q, m, kind, v, v, n);
}

/* ---- analysis and synthesis (sec. 5.3) ----------------------------------- */

/* Per eq. 13 band, the correlation of the decorrelated channels a, b (the
 * PCA makes them uncorrelated over all bands, not per band): the band's
 * cross power by polarisation, (P(a + b) - P(a) - P(b)) / 2, over
 * sqrt(P(a) P(b)). Channels missing (flat) or bands without power get 0;
 * each band's 3 x 3 matrix is shrunk towards the identity until it is
 * positive definite (its Cholesky factor mixes the noise in synthesis). */
static nl_status band_correlation(double *const *plane, int w, int h, nl_byexample_params *p,
                                  nl_error *err)
{
  static const int pair[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  size_t n = (size_t)w * h;
  double *s = nl_xmalloc(n * sizeof *s), sum[NL_WAVELET_MAX_BANDS];
  for (int q = 0; q < 3; q++) {
    const double *a = plane[pair[q][0]], *b = plane[pair[q][1]];
    if (!a || !b) continue;
    for (size_t i = 0; i < n; i++) s[i] = a[i] + b[i];
    if (nl_byexample_band_power(s, w, h, p->nbands, sum, err)) {
      free(s);
      return NL_EINVAL;
    }
    for (int k = 0; k < p->nbands; k++) {
      double pa = p->target[pair[q][0]][k], pb = p->target[pair[q][1]][k];
      p->corr[q][k] = pa > 0 && pb > 0 ? fmax(-0.99, fmin(0.99, (sum[k] - pa - pb) / (2 * sqrt(pa * pb)))) : 0;
    }
  }
  free(s);
  for (int k = 0; k < p->nbands; k++) {
    double L[3][3];
    while (nl_byexample_band_cholesky(p, k, L)) for (int q = 0; q < 3; q++) p->corr[q][k] *= 0.9;
  }
  return NL_OK;
}

int nl_byexample_band_cholesky(const nl_byexample_params *p, int k, double L[3][3])
{
  double r01 = p->corr[0][k], r02 = p->corr[1][k], r12 = p->corr[2][k];
  memset(L, 0, 9 * sizeof(double));
  L[0][0] = 1;
  L[1][0] = r01;
  double d1 = 1 - r01 * r01;
  if (!(d1 > 1e-6)) return 1;
  L[1][1] = sqrt(d1);
  L[2][0] = r02;
  L[2][1] = (r12 - r02 * r01) / L[1][1];
  double d2 = 1 - L[2][0] * L[2][0] - L[2][1] * L[2][1];
  if (!(d2 > 1e-6)) return 1;
  L[2][2] = sqrt(d2);
  return 0;
}

nl_status nl_byexample_analyse(const nl_image *im, const nl_byexample_options *opt,
                               nl_byexample_params *p, nl_error *err)
{
  nl_byexample_options o = {1, 1, 0, 0, NL_HIST_PAPER, 0};
  if (opt) o = *opt;
  if (o.tile == 0) o.tile = NL_BYEXAMPLE_TILE;
  if (im->width < NL_BYEXAMPLE_MIN_SIZE || im->height < NL_BYEXAMPLE_MIN_SIZE)
    return nl_fail(err, NL_EINVAL, "image is %d x %d pixels, smaller than %d", im->width,
                   im->height, NL_BYEXAMPLE_MIN_SIZE);
  if (o.tile < 8 || o.tile % 2) return nl_fail(err, NL_EINVAL, "tile period %d not even and >= 8", o.tile);
  /* The analysis transforms the image several times: a side with a large
   * prime factor would make each transform O(n^2) (minutes, not seconds). */
  if (nl_spectrum_check_size(im->width, im->height, err)) return NL_EINVAL;
  memset(p, 0, sizeof *p);
  p->channels = colour_channels(im);
  p->nbands = nl_byexample_band_count(im->width, im->height);
  p->tile = o.tile;
  p->histogram = o.histogram;
  p->hist_kind = o.hist_kind;
  p->calibrate = o.histogram && o.calibrate > 0 ? o.calibrate : 0;
  p->nhist = nl_byexample_hist_knots(o.hist_kind, NULL, NULL);
  if (!p->nhist) return nl_fail(err, NL_EINVAL, "unknown histogram representation %d", (int)o.hist_kind);
  p->sigma2 = o.sigma2 > 0 ? o.sigma2 : nl_byexample_sigma2(o.tile);
  nl_status st = nl_byexample_pca(im, p->mean, p->matrix, err);
  if (st) return st;
  if (!o.decorrelate) {
    memset(p->matrix, 0, sizeof p->matrix);
    for (int c = 0; c < 3; c++) p->matrix[c][c] = 1;
  }
  size_t n = (size_t)im->width * im->height;
  double *plane[3], *keep[3] = {NULL, NULL, NULL};
  for (int c = 0; c < p->channels; c++) plane[c] = nl_xmalloc(n * sizeof(double));
  nl_byexample_decorrelate(im, p->channels, p->mean, p->matrix, plane);
  for (int c = 0; c < p->channels; c++) {
    /* The flat test needs the true extremes (the gauss reading's outer
     * knots are order statistics next to them). */
    double ext[NL_BYEXAMPLE_HIST];
    nl_byexample_quantiles(plane[c], n, ext);
    nl_byexample_hist(plane[c], n, p->hist_kind, p->hist[c]);
    int flat = ext[0] == ext[NL_BYEXAMPLE_HIST - 1];
    /* The size passed nl_spectrum_check_size above: these transforms cannot
     * be refused, but their status is still the one returned. */
    if (p->calibrate && !flat && !st)
      st = nl_byexample_band_power(plane[c], im->width, im->height, p->nbands, p->target[c], err);
    if (p->calibrate && !flat) { keep[c] = nl_xmalloc(n * sizeof(double)); memcpy(keep[c], plane[c], n * sizeof(double)); }
    if (p->histogram && !flat) nl_byexample_gaussianize(plane[c], n);
    if (!flat && !st) st = nl_byexample_weights(plane[c], im->width, im->height, p->nbands, p->sigma2, p->w[c], err);
    free(plane[c]);
  }
  if (!st && p->calibrate && p->channels == 3) st = band_correlation(keep, im->width, im->height, p, err);
  for (int c = 0; c < 3; c++) free(keep[c]);
  if (st) return st;
  /* Finite pixels can still overflow (values near FLT_MAX squared in the
   * PCA): a result synthesis would reject is an error here. */
  for (int c = 0; c < p->channels; c++) {
    int bad = !isfinite(p->mean[c]);
    for (int k = 0; k < p->channels; k++) bad |= !isfinite(p->matrix[c][k]);
    for (int k = 0; k < p->nhist; k++) bad |= !isfinite(p->hist[c][k]);
    for (int k = 0; k < p->nbands; k++) bad |= !isfinite(p->w[c][k]) || !isfinite(p->target[c][k]);
    if (bad)
      return nl_fail(err, NL_ENUM, "the fitted parameters of channel %d are not finite (pixel values too large?)", c + 1);
  }
  return NL_OK;
}

void nl_byexample_channel_noise(const nl_byexample_params *p, int c, const nl_wavelet_tile *t,
                                double gain, int w, int h, unsigned long seed,
                                const nl_byexample_synth_options *opt, double *out)
{
  double wts[NL_WAVELET_MAX_BANDS];
  for (int k = 0; k < p->nbands; k++) wts[k] = gain * p->w[c][k];
  nl_wavelet_bands b;
  nl_wavelet_bands_init(&b, p->nbands, wts, t->n, nl_seed_stream(seed, "example.channel", (unsigned long)c), NULL);
  double scale = opt && opt->scale > 0 ? opt->scale : 1.0;
  nl_wavelet_bands_grid(t, &b, w, h, opt ? opt->z : 0, scale, out);
}

/* Rank-based histogram matching (Heeger & Bergen 1995): the realised values
 * are taken to Gaussian scores by rank, then through the representation. */
static void match_ranked(const nl_byexample_params *p, int c, double *v, size_t n, nl_byexample_spline_kind kind)
{
  if (p->hist[c][p->nhist - 1] == p->hist[c][0]) {
    for (size_t i = 0; i < n; i++) v[i] = p->hist[c][0];
    return;
  }
  nl_byexample_gaussianize(v, n);
  nl_byexample_match_kind(v, n, 1.0, p->hist_kind, p->hist[c], kind);
}

/* Removes from img the frequencies of eq. 13 bands >= nb (below the
 * exemplar's lowest frequency) and the DC. */
static nl_status high_pass(double *img, int w, int h, int nb, nl_error *err)
{
  size_t n = (size_t)w * h;
  double *F = nl_xmalloc(2 * n * sizeof *F);
  if (nl_spectrum_fft2(img, w, h, F, err)) {
    free(F);
    return NL_EINVAL;
  }
  for (int v = 0; v < h; v++) {
    double fy = fabs(nl_spectrum_freq(v, h));
    for (int u = 0; u < w; u++) {
      double m = fmax(fabs(nl_spectrum_freq(u, w)), fy);
      if (m == 0 || band_of(m) >= nb) F[2 * ((size_t)v * w + u)] = F[2 * ((size_t)v * w + u) + 1] = 0;
    }
  }
  nl_status st = nl_spectrum_fft2_inverse(F, w, h, img, err);
  free(F);
  return st;
}

/* Synthesis-time calibration (nl_byexample.h). Every channel's noise bands
 * B_k are drawn once, stripped of frequencies below the exemplar's lowest
 * (when the output is larger) and mixed per band by the Cholesky factor of
 * the band's channel correlation. Per channel, A[k][j] = eq. 13 power of B_k
 * in band j (the leakage, measured on this realisation); then `calibrate`
 * times: sum with gains g, predict the band powers S = A^T g^2, match the
 * histogram by rank, measure P, and solve NNLS A^T g^2 = target * S / P
 * (what the sum needs for the matched image to hit the target); the last
 * sum, matched, is the output. */
static nl_status calibrate_channels(const nl_byexample_params *p, const nl_wavelet_tile *t, double gain,
                                    int w, int h, unsigned long seed,
                                    const nl_byexample_synth_options *opt, double **out, nl_error *err)
{
  nl_status st = NL_OK;
  size_t n = (size_t)w * h;
  int nb = p->nbands, C = p->channels, nbs = nl_byexample_band_count(w, h), nbo = nbs < nb ? nbs : nb;
  double *B[3], g2[NL_WAVELET_MAX_BANDS], P[NL_WAVELET_MAX_BANDS], S[NL_WAVELET_MAX_BANDS], b[NL_WAVELET_MAX_BANDS];
  double A[NL_WAVELET_MAX_BANDS * NL_WAVELET_MAX_BANDS], M[NL_WAVELET_MAX_BANDS * NL_WAVELET_MAX_BANDS];
  nl_byexample_params one = *p;
  for (int c = 0; c < C; c++) {
    B[c] = nl_xmalloc((size_t)nb * n * sizeof *B[c]);
    for (int k = 0; k < nb; k++) {
      for (int j = 0; j < nb; j++) one.w[c][j] = j == k;
      nl_byexample_channel_noise(&one, c, t, gain, w, h, seed, opt, B[c] + (size_t)k * n);
      /* only the 3 coarsest noise bands reach below the exemplar's lowest frequency */
      if (!st && nbs > nb && k >= nb - 3) st = high_pass(B[c] + (size_t)k * n, w, h, nb, err);
    }
  }
  for (int k = 0; k < nb && C == 3; k++) {
    double L[3][3];
    if (nl_byexample_band_cholesky(p, k, L)) continue;   /* analysis made it definite */
    for (int c = 2; c > 0; c--) {   /* in place: row c uses sources j <= c */
      double *d = B[c] + (size_t)k * n;
      for (size_t i = 0; i < n; i++) {
        double v = 0;
        for (int j = 0; j <= c; j++) v += L[c][j] * B[j][(size_t)k * n + i];
        d[i] = v;
      }
    }
  }
  for (int c = 0; c < C && !st; c++) {
    for (int k = 0; k < nb && !st; k++) {
      g2[k] = p->w[c][k] * p->w[c][k];
      st = nl_byexample_band_power(B[c] + (size_t)k * n, w, h, nbo, A + (size_t)k * nbo, err);
    }
    for (int j = 0; j < nbo; j++)
      for (int k = 0; k < nb; k++) M[j * nb + k] = A[k * nbo + j];
    for (int it = 0; it <= p->calibrate && !st; it++) {
      memset(out[c], 0, n * sizeof *out[c]);
      for (int k = 0; k < nb; k++)
        if (g2[k] > 0) {
          double gk = sqrt(g2[k]);
          for (size_t i = 0; i < n; i++) out[c][i] += gk * B[c][(size_t)k * n + i];
        }
      match_ranked(p, c, out[c], n, opt ? opt->spline : 0);
      if (it == p->calibrate) break;
      if ((st = nl_byexample_band_power(out[c], w, h, nbo, P, err))) break;
      for (int j = 0; j < nbo; j++) {
        S[j] = 0;
        for (int k = 0; k < nb; k++) S[j] += g2[k] * A[k * nbo + j];
        b[j] = P[j] > 0 ? p->target[c][j] * S[j] / P[j] : 0;
      }
      double x[NL_WAVELET_MAX_BANDS];
      if (nl_byexample_nnls(M, nbo, nb, b, x) >= 0) memcpy(g2, x, (size_t)nb * sizeof *x);
    }
  }
  for (int c = 0; c < C; c++) free(B[c]);
  return st;
}

nl_status nl_byexample_synth_check(const nl_byexample_synth_options *opt, nl_error *err)
{
  if (!opt) return NL_OK;
  if (!isfinite(opt->scale)) return nl_fail(err, NL_EINVAL, "--scale: %g is not a finite number", opt->scale);
  if (!(opt->scale >= NL_BYEXAMPLE_SCALE_MIN && opt->scale <= NL_BYEXAMPLE_SCALE_MAX))
    return nl_fail(err, NL_EINVAL, "--scale: %g is outside [%g, %g]", opt->scale, NL_BYEXAMPLE_SCALE_MIN,
                   NL_BYEXAMPLE_SCALE_MAX);
  if (!isfinite(opt->z)) return nl_fail(err, NL_EINVAL, "--z: %g is not a finite number", opt->z);
  if (fabs(opt->z) > NL_BYEXAMPLE_Z_MAX)
    return nl_fail(err, NL_EINVAL, "--z: %g is outside [%g, %g]", opt->z, -NL_BYEXAMPLE_Z_MAX, NL_BYEXAMPLE_Z_MAX);
  return NL_OK;
}

nl_status nl_byexample_synthesize(const nl_byexample_params *p, int w, int h, unsigned long seed,
                                  const nl_byexample_synth_options *opt, nl_image **out,
                                  nl_error *err)
{
  if (w < 1 || w > NL_BYEXAMPLE_MAX_SIDE)
    return nl_fail(err, NL_EINVAL, "--size: %d is outside [1, %d]", w, NL_BYEXAMPLE_MAX_SIDE);
  if (h < 1 || h > NL_BYEXAMPLE_MAX_SIDE)
    return nl_fail(err, NL_EINVAL, "--height: %d is outside [1, %d]", h, NL_BYEXAMPLE_MAX_SIDE);
  if (nl_byexample_synth_check(opt, err)) return NL_EINVAL;
  if ((double)w * h > 1e9)   /* each side may be in range while their product is not */
    return nl_fail(err, NL_EINVAL, "output size %d x %d is %.3g pixels, more than the limit of 1e9",
                   w, h, (double)w * h);
  /* channel planes (double) and the image (float), checked before allocating */
  int solid = opt && opt->solid;
  /* Calibration holds every band of every channel at the output size. The
   * method never depends on the machine: when that does not fit, the
   * synthesis is refused, saying what calibration needs. */
  int cal = p->calibrate > 0 && p->histogram && !solid && !(opt && opt->scale > 0 && opt->scale != 1);
  double need = (double)w * h * p->channels * (sizeof(double) + sizeof(float));
  double cal_need = cal ? (double)w * h * p->nbands * p->channels * sizeof(double) : 0;
  if (!nl_mem_fits(need + cal_need)) {
    char b1[32], b2[32], b3[32];
    if (cal && nl_mem_fits(need))
      return nl_fail(err, NL_ENOMEM, "output %d x %d with %d channels and %d bands needs %s with "
                     "the calibration its parameters ask for (%s without); %s is available", w, h, p->channels, p->nbands,
                     nl_format_bytes(b1, need + cal_need), nl_format_bytes(b2, need),
                     nl_format_bytes(b3, nl_mem_available()));
    return nl_fail(err, NL_ENOMEM, "output %d x %d with %d channels needs %s%s; %s is available",
                   w, h, p->channels, nl_format_bytes(b1, need + cal_need),
                   cal ? " with calibration" : "", nl_format_bytes(b2, nl_mem_available()));
  }
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(solid ? 3 : 2, solid ? NL_BYEXAMPLE_TILE3 : p->tile);
  if (!t) return nl_fail(err, NL_EINVAL, "tile period %d not even and >= 8", p->tile);
  nl_wavelet_tile_seed(t, seed);
  /* Scale this tile's noise to the sigma_N^2 the weights were computed with:
   * the variance then is sigma_N^2 sum w^2 whatever the tile (and 3D noise,
   * whose band variance differs from 2D's, gets the same 2D weights). */
  double gain = sqrt(p->sigma2 / nl_wavelet_tile_variance(t, solid ? 2 : 4));
  size_t n = (size_t)w * h;
  double *plane[3];
  /* Calibration measures band powers by FFT of the output: O(n^2) for a
   * side with a large prime factor, as in the analysis. */
  if (cal && nl_spectrum_check_size(w, h, err)) {
    nl_wavelet_tile_free(t);
    return NL_EINVAL;
  }
  for (int c = 0; c < p->channels; c++) plane[c] = nl_xmalloc(n * sizeof(double));
  if (cal && calibrate_channels(p, t, gain, w, h, seed, opt, plane, err)) {   /* size checked above */
    nl_wavelet_tile_free(t);
    for (int c = 0; c < p->channels; c++) free(plane[c]);
    return NL_EINVAL;
  }
  for (int c = 0; c < p->channels && !cal; c++) {
    nl_byexample_channel_noise(p, c, t, gain, w, h, seed, opt, plane[c]);
    if (p->histogram) {
      double ss = 0;
      for (int k = 0; k < p->nbands; k++) ss += p->w[c][k] * p->w[c][k];
      double sigma_m = sqrt(p->sigma2 * ss);
      if (sigma_m > 0) nl_byexample_match_kind(plane[c], n, sigma_m, p->hist_kind, p->hist[c], opt ? opt->spline : 0);
      else for (size_t i = 0; i < n; i++) plane[c][i] = p->hist[c][p->nhist / 2];
    }
  }
  nl_wavelet_tile_free(t);
  *out = nl_image_alloc(w, h, p->channels);
  nl_byexample_recorrelate(plane, p->channels, p->mean, p->matrix, *out);
  for (int c = 0; c < p->channels; c++) free(plane[c]);
  return NL_OK;
}

void nl_byexample_attenuate(nl_byexample_params *p, int nfine, double factor)
{
  for (int c = 0; c < p->channels; c++)
    for (int k = 0; k < nfine && k < p->nbands; k++) {
      p->w[c][k] *= factor;
      p->target[c][k] *= factor * factor;   /* calibration aims at the edited power */
    }
}

nl_image *nl_byexample_spectrum_image(const double *img, int w, int h, double decades, nl_error *err)
{
  size_t n = (size_t)w * h;
  double *P = nl_xmalloc(n * sizeof *P), *L = nl_xmalloc(n * sizeof *L), top = -INFINITY;
  if (nl_spectrum_power2(img, w, h, P, err)) {
    free(P);
    free(L);
    return NULL;
  }
  for (int v = 0; v < h; v++)
    for (int u = 0; u < w; u++) {
      double l = log10(P[(size_t)v * w + u] + 1e-300);
      L[(size_t)((v + h / 2) % h) * w + (size_t)((u + w / 2) % w)] = l;   /* DC to the centre */
      if (u || v) top = fmax(top, l);
    }
  nl_image *im = nl_image_from_values(L, w, h, top - decades, top);
  free(P);
  free(L);
  return im;
}

void nl_byexample_channel(const nl_image *im, int c, double *out)
{
  size_t n = (size_t)im->width * im->height;
  for (size_t i = 0; i < n; i++) out[i] = im->data[i * im->channels + c];
}

void nl_byexample_luminance(const nl_image *im, double *out)
{
  nl_image *g = nl_image_convert(im, 1);
  nl_byexample_channel(g, 0, out);
  nl_image_free(g);
}

double nl_byexample_correlation_error(const nl_image *a, const nl_image *b)
{
  double ca[3][3], cb[3][3], e = 0;
  nl_byexample_correlation(a, ca);
  nl_byexample_correlation(b, cb);
  for (int i = 0; i < 3; i++)
    for (int j = i + 1; j < 3; j++) e = fmax(e, fabs(ca[i][j] - cb[i][j]));
  return e;
}

void nl_byexample_rotation_error(const double M[3][3], double *det, double *orth)
{
  *det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0])
       + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  *orth = 0;
  for (int u = 0; u < 3; u++)
    for (int v = 0; v < 3; v++)
      *orth = fmax(*orth, fabs(M[u][0] * M[v][0] + M[u][1] * M[v][1] + M[u][2] * M[v][2] - (u == v)));
}

void nl_byexample_correlation(const nl_image *im, double corr[3][3])
{
  double mean[3], M[3][3], cov[3][3] = {{0}};
  int nch = colour_channels(im);
  size_t n = (size_t)im->width * im->height;
  nl_byexample_pca(im, mean, M, NULL);
  for (size_t i = 0; i < n; i++)
    for (int a = 0; a < nch; a++)
      for (int b = 0; b < nch; b++)
        cov[a][b] += (im->data[i * im->channels + a] - mean[a]) * (im->data[i * im->channels + b] - mean[b]);
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      double d = a < nch && b < nch ? sqrt(cov[a][a] * cov[b][b]) : 0;
      corr[a][b] = a == b ? 1 : d > 0 ? cov[a][b] / d : 0;
    }
}

/* ---- measures of a synthesis against its exemplar ------------------------- */

double nl_byexample_tail_mass(const double *x, size_t n, const double *ref, size_t nref, double k)
{
  double m = 0, ss = 0;
  for (size_t i = 0; i < nref; i++) m += ref[i];
  m /= (double)nref;
  for (size_t i = 0; i < nref; i++) ss += (ref[i] - m) * (ref[i] - m);
  double lim = k * sqrt(ss / (double)nref);
  size_t c = 0;
  for (size_t i = 0; i < n; i++) c += fabs(x[i] - m) > lim;
  return (double)c / (double)n;
}

double nl_byexample_saturation(const float *px, int channels)
{
  if (channels < 3) return 0;
  /* On the displayed values (clamped to [0, 1]): what the eye sees as speckle. */
  double lo = 1, hi = 0;
  for (int c = 0; c < 3; c++) {
    double v = fmin(fmax(px[c], 0.0), 1.0);
    lo = fmin(lo, v);
    hi = fmax(hi, v);
  }
  return hi > 0 ? (hi - lo) / hi : 0;
}

double nl_byexample_speckle(const nl_image *ex, const nl_image *syn)
{
  size_t n = (size_t)ex->width * ex->height, m = (size_t)syn->width * syn->height, c = 0;
  double *s = nl_xmalloc(n * sizeof *s);
  for (size_t i = 0; i < n; i++) s[i] = nl_byexample_saturation(ex->data + i * ex->channels, ex->channels);
  nl_stats_sort(s, n);
  double p99 = s[(size_t)(0.99 * (double)(n - 1))];
  for (size_t i = 0; i < m; i++) c += nl_byexample_saturation(syn->data + i * syn->channels, syn->channels) > p99;
  free(s);
  return (double)c / (double)m;
}
