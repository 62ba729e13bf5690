#include "spectrum/nl_spectrum.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_fft_complex.h>
#include <limits.h>
#include <gsl/gsl_fft_real.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

double nl_spectrum_freq(int u, int n) { return (double)(2 * u < n ? u : u - n) / n; }

/* ---- 2D real-input FFT (power-of-two sides) ----------------------------
 * GSL's complex transform of every column of a row-major image walks an
 * (8 w)-byte stride and transforms w columns of which w/2 - 1 are the
 * conjugates of others. Here: rows two at a time as one complex sequence
 * (z = a + i b; A and B separate by Hermitian symmetry), then only the
 * w/2 + 1 columns of the half spectrum, gathered a block of columns at a
 * time into a contiguous buffer. Both passes are one Stockham radix-4
 * kernel (DIF, autosorting, no bit reversal) over a batch of interleaved
 * sequences, so its innermost loop runs over contiguous memory.
 * Twiddles are cos/sin of each angle (not products), once per plan. */

enum { FFT2_BATCH = 8 };   /* columns (or row pairs) per batched transform */

typedef struct {
  int n;
  double *tw;   /* per radix-4 stage of length len (n, n/4, ...): len/4 x {w1, w2, w3} */
} fft1_plan;

struct nl_spectrum_fft2_plan {
  int w, h, fast;        /* fast: both sides powers of two (else GSL's mixed radix) */
  fft1_plan row, col;
  double *buf, *work;    /* 2 * max(w, h) * FFT2_BATCH complex */
  double *zeros;         /* w zeros: the partner of a last odd row */
};

static int is_pow2(int n) { return n >= 1 && (n & (n - 1)) == 0; }

static void fft1_plan_init(fft1_plan *p, int n)
{
  p->n = n;
  size_t total = 0;
  for (int len = n; len >= 4; len /= 4) total += (size_t)(len / 4) * 6;
  p->tw = nl_xmalloc((total ? total : 1) * sizeof *p->tw);
  double *t = p->tw;
  for (int len = n; len >= 4; len /= 4)
    for (int q = 0; q < len / 4; q++) {
      for (int k = 1; k <= 3; k++) {   /* w_k = exp(-2 pi i k q / len) */
        double a = -NL_TWO_PI * (double)(k * q) / (double)len;
        t[2 * (k - 1)] = cos(a);
        t[2 * (k - 1) + 1] = sin(a);
      }
      t += 6;
    }
}

/* Forward DFT of the sequences x[k*s + j] (complex, j < s: s interleaved
 * sequences of length n), Stockham radix 4. eo: the result lands in y if
 * 1, in x if 0; the other array is work space. tw: this stage's twiddles. */
static void stockham(int n, size_t s, int eo, double *x, double *y, const double *tw)
{
  if (n == 1) {
    if (eo) memcpy(y, x, 2 * s * sizeof *x);
    return;
  }
  if (n == 2) {
    double *z = eo ? y : x;
    for (size_t j = 0; j < s; j++) {
      double ar = x[2 * j], ai = x[2 * j + 1], br = x[2 * (j + s)], bi = x[2 * (j + s) + 1];
      z[2 * j] = ar + br; z[2 * j + 1] = ai + bi;
      z[2 * (j + s)] = ar - br; z[2 * (j + s) + 1] = ai - bi;
    }
    return;
  }
  int m = n / 4;
  for (int q = 0; q < m; q++) {
    const double *w = tw + 6 * q;
    double w1r = w[0], w1i = w[1], w2r = w[2], w2i = w[3], w3r = w[4], w3i = w[5];
    const double *xa = x + 2 * s * (size_t)q, *xb = x + 2 * s * (size_t)(q + m);
    const double *xc = x + 2 * s * (size_t)(q + 2 * m), *xd = x + 2 * s * (size_t)(q + 3 * m);
    double *y0 = y + 2 * s * (size_t)(4 * q), *y1 = y0 + 2 * s, *y2 = y1 + 2 * s, *y3 = y2 + 2 * s;
    for (size_t j = 0; j < 2 * s; j += 2) {
      double apcr = xa[j] + xc[j], apci = xa[j + 1] + xc[j + 1];
      double amcr = xa[j] - xc[j], amci = xa[j + 1] - xc[j + 1];
      double bpdr = xb[j] + xd[j], bpdi = xb[j + 1] + xd[j + 1];
      double bmdr = xb[j] - xd[j], bmdi = xb[j + 1] - xd[j + 1];
      y0[j] = apcr + bpdr; y0[j + 1] = apci + bpdi;
      double t1r = amcr + bmdi, t1i = amci - bmdr;   /* a - c - i (b - d) */
      double t2r = apcr - bpdr, t2i = apci - bpdi;
      double t3r = amcr - bmdi, t3i = amci + bmdr;   /* a - c + i (b - d) */
      y1[j] = w1r * t1r - w1i * t1i; y1[j + 1] = w1r * t1i + w1i * t1r;
      y2[j] = w2r * t2r - w2i * t2i; y2[j + 1] = w2r * t2i + w2i * t2r;
      y3[j] = w3r * t3r - w3i * t3i; y3[j + 1] = w3r * t3i + w3i * t3r;
    }
  }
  stockham(m, 4 * s, !eo, y, x, tw + 6 * m);
}

/* Batched forward DFT in place: x holds s interleaved sequences; y is work. */
static void fft1_batch(const fft1_plan *p, size_t s, double *x, double *y) { stockham(p->n, s, 0, x, y, p->tw); }

nl_spectrum_fft2_plan *nl_spectrum_fft2_plan_alloc(int w, int h, nl_error *err)
{
  if (nl_spectrum_check_size(w, h, err)) return NULL;
  nl_spectrum_fft2_plan *p = nl_xcalloc(1, sizeof *p);
  p->w = w; p->h = h;
  p->fast = is_pow2(w) && is_pow2(h) && w >= 2;
  if (p->fast) {
    fft1_plan_init(&p->row, w);
    fft1_plan_init(&p->col, h);
    size_t len = (size_t)(w > h ? w : h) * FFT2_BATCH;
    p->buf = nl_xmalloc(2 * len * sizeof *p->buf);
    p->work = nl_xmalloc(2 * len * sizeof *p->work);
    p->zeros = nl_xcalloc((size_t)w, sizeof *p->zeros);
  }
  return p;
}

void nl_spectrum_fft2_plan_free(nl_spectrum_fft2_plan *p)
{
  if (!p) return;
  free(p->row.tw); free(p->col.tw); free(p->buf); free(p->work); free(p->zeros);
  free(p);
}

/* Rows r0 .. r0 + 2 nb - 1 (pairs; a missing odd row is zero) to the half
 * spectrum rows of H: pair b packed as z = row(2b) + i row(2b+1), element k
 * of pair b at buf[k nb + b]. */
static void rows_pass(nl_spectrum_fft2_plan *p, const double *img, int r0, int nb, double *H)
{
  int w = p->w, h = p->h, m = w / 2 + 1;
  double *z = p->buf;
  const double *rows[2 * FFT2_BATCH];
  for (int b = 0; b < 2 * nb; b++)   /* a missing odd row reads zeros */
    rows[b] = r0 + b < h ? img + (size_t)(r0 + b) * w : p->zeros;
  for (int k = 0; k < w; k++) {
    double *zk = z + 2 * (size_t)nb * k;
    for (int b = 0; b < nb; b++) { zk[2 * b] = rows[2 * b][k]; zk[2 * b + 1] = rows[2 * b + 1][k]; }
  }
  fft1_batch(&p->row, (size_t)nb, z, p->work);
  for (int b = 0; b < nb; b++) {
    double *ha = H + 2 * (size_t)(r0 + 2 * b) * m;
    double *hb = r0 + 2 * b + 1 < h ? ha + 2 * m : p->work;   /* a missing row: scratch */
    const double *zb = z + 2 * b;
    size_t st = 2 * (size_t)nb;
    for (int u = 0; u < m; u++) {
      const double *zu = zb + st * (size_t)u, *zv = zb + st * (size_t)(u ? w - u : 0);
      /* A = (Z_u + conj Z_-u) / 2, B = (Z_u - conj Z_-u) / (2 i) */
      ha[2 * u] = 0.5 * (zu[0] + zv[0]);
      ha[2 * u + 1] = 0.5 * (zu[1] - zv[1]);
      hb[2 * u] = 0.5 * (zu[1] + zv[1]);
      hb[2 * u + 1] = -0.5 * (zu[0] - zv[0]);
    }
  }
}

/* GSL's mixed-radix complex transform of every line of a w x h complex
 * array; columns through a transposed copy (the same arithmetic as a
 * strided transform, so the same bits, at a contiguous stride). */
static void fft2_gsl(double *F, int w, int h, gsl_fft_direction dir)
{
  gsl_fft_complex_wavetable *wt = gsl_fft_complex_wavetable_alloc((size_t)w);
  gsl_fft_complex_workspace *ws = gsl_fft_complex_workspace_alloc((size_t)w);
  for (int k = 0; k < h; k++) gsl_fft_complex_transform(F + 2 * (size_t)w * k, 1, (size_t)w, wt, ws, dir);
  gsl_fft_complex_workspace_free(ws);
  gsl_fft_complex_wavetable_free(wt);
  wt = gsl_fft_complex_wavetable_alloc((size_t)h);
  ws = gsl_fft_complex_workspace_alloc((size_t)h);
  double *col = nl_xmalloc(2 * (size_t)h * sizeof *col);
  for (int u = 0; u < w; u++) {
    for (int v = 0; v < h; v++) { col[2 * v] = F[2 * ((size_t)v * w + u)]; col[2 * v + 1] = F[2 * ((size_t)v * w + u) + 1]; }
    gsl_fft_complex_transform(col, 1, (size_t)h, wt, ws, dir);
    for (int v = 0; v < h; v++) { F[2 * ((size_t)v * w + u)] = col[2 * v]; F[2 * ((size_t)v * w + u) + 1] = col[2 * v + 1]; }
  }
  free(col);
  gsl_fft_complex_workspace_free(ws);
  gsl_fft_complex_wavetable_free(wt);
}

void nl_spectrum_rfft2(nl_spectrum_fft2_plan *p, const double *img, double *H)
{
  int w = p->w, h = p->h, m = w / 2 + 1;
  if (!p->fast) {
    double *F = nl_xmalloc(2 * (size_t)w * h * sizeof *F);
    for (size_t k = 0; k < (size_t)w * h; k++) { F[2 * k] = img[k]; F[2 * k + 1] = 0; }
    fft2_gsl(F, w, h, gsl_fft_forward);
    for (int v = 0; v < h; v++) memcpy(H + 2 * (size_t)v * m, F + 2 * (size_t)v * w, 2 * (size_t)m * sizeof *H);
    free(F);
    return;
  }
  for (int r0 = 0; r0 < h; r0 += 2 * FFT2_BATCH) {
    int nb = (h - r0 + 1) / 2;
    rows_pass(p, img, r0, nb < FFT2_BATCH ? nb : FFT2_BATCH, H);
  }
  /* columns: a block of nb columns of H is nb contiguous complex per row */
  for (int u0 = 0; u0 < m; u0 += FFT2_BATCH) {
    int nb = m - u0 < FFT2_BATCH ? m - u0 : FFT2_BATCH;
    size_t len = 2 * (size_t)nb;   /* copied by loops: memcpy's rep movs is slow at this length */
    for (int v = 0; v < h; v++) {
      const double *src = H + 2 * ((size_t)v * m + u0);
      double *dst = p->buf + len * v;
      for (size_t j = 0; j < len; j++) dst[j] = src[j];
    }
    fft1_batch(&p->col, (size_t)nb, p->buf, p->work);
    for (int v = 0; v < h; v++) {
      const double *src = p->buf + len * v;
      double *dst = H + 2 * ((size_t)v * m + u0);
      for (size_t j = 0; j < len; j++) dst[j] = src[j];
    }
  }
}

/* The sum of n's prime factors (with multiplicity) and the largest. */
static double prime_factor_sum(int n, int *largest)
{
  double sum = 0;
  *largest = 1;
  for (int f = 2; (long)f * f <= n; f++)
    while (n % f == 0) {
      sum += f;
      *largest = f;
      n /= f;
    }
  if (n > 1) {
    sum += n;
    *largest = n;
  }
  return sum;
}

double nl_spectrum_fft2_cost(int w, int h)
{
  int lw, lh;
  return (double)w * h * (prime_factor_sum(w, &lw) + prime_factor_sum(h, &lh));
}

static int size_passes(int w, int h)
{
  int lw, lh;
  prime_factor_sum(w, &lw);
  prime_factor_sum(h, &lh);
  return nl_spectrum_fft2_cost(w, h) <= NL_SPECTRUM_MAX_COST ||
         (lw <= NL_SPECTRUM_MAX_FACTOR && lh <= NL_SPECTRUM_MAX_FACTOR);
}

/* The largest m <= n with which the other side `other` passes: its prime
 * factors within NL_SPECTRUM_MAX_FACTOR (then passing needs the other side
 * so too), or cheap enough. */
static int crop_to(int n, int other, int is_width)
{
  for (int m = n; m > 1; m--) {
    int largest;
    prime_factor_sum(m, &largest);
    if (largest <= NL_SPECTRUM_MAX_FACTOR || size_passes(is_width ? m : other, is_width ? other : m))
      return m;
  }
  return 1;
}

nl_status nl_spectrum_check_size(int w, int h, nl_error *err)
{
  if (size_passes(w, h)) return NL_OK;
  int lw, lh;
  prime_factor_sum(w, &lw);
  prime_factor_sum(h, &lh);
  /* The side with the larger factor is cropped first, the other only if
   * that is not enough. */
  int side_is_w = lw >= lh, cw = w, ch = h;
  if (side_is_w) cw = crop_to(w, h, 1);
  else ch = crop_to(h, w, 0);
  if (!size_passes(cw, ch)) {
    if (side_is_w) ch = crop_to(h, cw, 0);
    else cw = crop_to(w, ch, 1);
  }
  return nl_fail(err, NL_EINVAL, "%d x %d pixels: %s %d has the prime factor %d (beyond %d), and a "
                 "Fourier transform of it costs %.2g operations (limit %.0g); crop it to %d x %d",
                 w, h, side_is_w ? "width" : "height", side_is_w ? w : h, side_is_w ? lw : lh,
                 NL_SPECTRUM_MAX_FACTOR, nl_spectrum_fft2_cost(w, h), NL_SPECTRUM_MAX_COST, cw, ch);
}

nl_status nl_spectrum_check_length(size_t n, nl_error *err)
{
  if (n > INT_MAX) return nl_fail(err, NL_EINVAL, "%zu samples: more than a transform takes", n);
  int largest;
  double cost = (double)n * prime_factor_sum((int)n, &largest);
  if (largest <= NL_SPECTRUM_MAX_FACTOR || cost <= NL_SPECTRUM_MAX_COST) return NL_OK;
  int m = (int)n;
  for (; m > 1; m--) {
    int l;
    double c = (double)m * prime_factor_sum(m, &l);
    if (l <= NL_SPECTRUM_MAX_FACTOR || c <= NL_SPECTRUM_MAX_COST) break;
  }
  return nl_fail(err, NL_EINVAL, "%zu samples: %zu has the prime factor %d (beyond %d), and a "
                 "Fourier transform of it costs %.2g operations (limit %.0g); use %d",
                 n, n, largest, NL_SPECTRUM_MAX_FACTOR, cost, NL_SPECTRUM_MAX_COST, m);
}

nl_status nl_spectrum_fft2(const double *img, int w, int h, double *F, nl_error *err)
{
  nl_spectrum_fft2_plan *p = nl_spectrum_fft2_plan_alloc(w, h, err);
  if (!p) return NL_EINVAL;
  if (!p->fast) {   /* GSL's transform of the complex image, as before */
    for (size_t k = 0; k < (size_t)w * h; k++) { F[2 * k] = img[k]; F[2 * k + 1] = 0; }
    fft2_gsl(F, w, h, gsl_fft_forward);
    nl_spectrum_fft2_plan_free(p);
    return NL_OK;
  }
  int m = w / 2 + 1;
  double *H = nl_xmalloc(2 * (size_t)m * h * sizeof *H);
  nl_spectrum_rfft2(p, img, H);
  for (int v = 0; v < h; v++) {   /* F(u, v) = conj F(w - u, h - v) for a real image */
    const double *hv = H + 2 * (size_t)v * m, *hc = H + 2 * (size_t)((h - v) % h) * m;
    double *fv = F + 2 * (size_t)v * w;
    memcpy(fv, hv, 2 * (size_t)m * sizeof *F);
    for (int u = m; u < w; u++) { fv[2 * u] = hc[2 * (w - u)]; fv[2 * u + 1] = -hc[2 * (w - u) + 1]; }
  }
  free(H);
  nl_spectrum_fft2_plan_free(p);
  return NL_OK;
}

nl_status nl_spectrum_fft2_inverse(const double *F, int w, int h, double *img, nl_error *err)
{
  if (nl_spectrum_check_size(w, h, err)) return NL_EINVAL;
  size_t n = (size_t)w * h;
  double *G = nl_xmalloc(2 * n * sizeof *G);
  memcpy(G, F, 2 * n * sizeof *G);
  fft2_gsl(G, w, h, gsl_fft_backward);
  for (size_t k = 0; k < n; k++) img[k] = G[2 * k] / (double)n;
  free(G);
  return NL_OK;
}

nl_status nl_spectrum_power2(const double *img, int w, int h, double *P, nl_error *err)
{
  size_t n = (size_t)w * h;
  double s = 1.0 / ((double)n * (double)n);
  nl_spectrum_fft2_plan *p = nl_spectrum_fft2_plan_alloc(w, h, err);
  if (!p) return NL_EINVAL;
  int m = w / 2 + 1;
  double *H = nl_xmalloc(2 * (size_t)m * h * sizeof *H);
  nl_spectrum_rfft2(p, img, H);
  nl_spectrum_fft2_plan_free(p);
  for (int v = 0; v < h; v++)
    for (int u = 0; u < m; u++) {
      const double *z = H + 2 * ((size_t)v * m + u);
      P[(size_t)v * w + u] = (z[0] * z[0] + z[1] * z[1]) * s;
    }
  for (int v = 0; v < h; v++)   /* |F(u, v)| = |F(w - u, h - v)| for a real image */
    for (int u = m; u < w; u++) P[(size_t)v * w + u] = P[(size_t)((h - v) % h) * w + (w - u)];
  free(H);
  return NL_OK;
}

nl_status nl_spectrum_radial(const double *img, int w, int h, int nbins, double *f, double *p,
                             nl_error *err)
{
  size_t n = (size_t)w * h;
  double *P = nl_xmalloc(n * sizeof *P);
  if (nl_spectrum_power2(img, w, h, P, err)) {
    free(P);
    return NL_EINVAL;
  }
  size_t *count = nl_xcalloc((size_t)nbins, sizeof *count);
  for (int b = 0; b < nbins; b++) { p[b] = 0; f[b] = (b + 0.5) * 0.5 / nbins; }
  for (int v = 0; v < h; v++)
    for (int u = 0; u < w; u++) {
      double fu = nl_spectrum_freq(u, w), fv = nl_spectrum_freq(v, h);
      int b = (int)(sqrt(fu * fu + fv * fv) / 0.5 * nbins);
      if (b >= nbins) continue;
      p[b] += P[(size_t)v * w + u];
      count[b]++;
    }
  for (int b = 0; b < nbins; b++) if (count[b]) p[b] /= (double)count[b];
  free(P); free(count);
  return NL_OK;
}

/* Tukey window of n samples, taper fraction frac: sin^2 over the outer frac/2 of each side. */
static double taper(int x, int n, double frac)
{
  double u = (x + 0.5) / n, e = frac / 2;   /* position in (0, 1), edge width */
  if (u > e && u < 1 - e) return 1;
  double s = sin(NL_PI * fmin(u, 1 - u) / (2 * e));
  return s * s;
}

void nl_spectrum_taper2(const double *img, int w, int h, double frac, double *out)
{
  size_t n = (size_t)w * h;
  double *hx = nl_xmalloc((size_t)w * sizeof *hx), *hy = nl_xmalloc((size_t)h * sizeof *hy);
  double mean = 0, sx = 0, sy = 0;
  for (size_t k = 0; k < n; k++) mean += img[k];
  mean /= (double)n;
  for (int x = 0; x < w; x++) { hx[x] = taper(x, w, frac); sx += hx[x] * hx[x]; }
  for (int y = 0; y < h; y++) { hy[y] = taper(y, h, frac); sy += hy[y] * hy[y]; }
  double norm = 1.0 / sqrt(sx / w * sy / h);   /* the window's power, measured (not 9/64) */
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      size_t k = (size_t)y * w + x;
      out[k] = (img[k] - mean) * hx[x] * hy[y] * norm;
    }
  free(hx);
  free(hy);
}

void nl_spectrum_hann2(const double *img, int w, int h, double *out) { nl_spectrum_taper2(img, w, h, 1.0, out); }

/* ---- 1D --------------------------------------------------------------- */

nl_status nl_spectrum_psd1(const double *x, size_t n, double rate, double *f, double *P, nl_error *err)
{
  if (n < 2 || !(rate > 0.0)) return nl_fail(err, NL_EINVAL, "psd1: need n >= 2 and rate > 0");
  if (nl_spectrum_check_length(n, err)) return NL_EINVAL;
  double *d = nl_xmalloc(n * sizeof *d);
  memcpy(d, x, n * sizeof *d);
  gsl_fft_real_wavetable *wt = gsl_fft_real_wavetable_alloc(n);
  gsl_fft_real_workspace *ws = gsl_fft_real_workspace_alloc(n);
  int gs = gsl_fft_real_transform(d, 1, n, wt, ws);
  gsl_fft_real_workspace_free(ws);
  gsl_fft_real_wavetable_free(wt);
  if (gs) { free(d); return nl_fail(err, NL_ENUM, "psd1: %s", gsl_strerror(gs)); }
  /* Half-complex layout: d[0] = X_0, (d[2k-1], d[2k]) = X_k, d[n-1] = X_{n/2}
   * for even n. |X_k|^2 / n^2 per two-sided bin (Parseval, eq. 4.4, over
   * n^2 so that the sum is the mean square); folded to one side. */
  double nn = (double)n * (double)n;
  size_t m = n / 2 + 1;
  for (size_t k = 0; k < m; k++) {
    double re, im = 0.0;
    if (k == 0) re = d[0];
    else if (2 * k == n) re = d[n - 1];
    else { re = d[2 * k - 1]; im = d[2 * k]; }
    double two_sided = (re * re + im * im) / nn;
    P[k] = (k == 0 || 2 * k == n) ? two_sided : 2.0 * two_sided;
    f[k] = (double)k * rate / (double)n;
  }
  free(d);
  return NL_OK;
}

nl_status nl_spectrum_psd1_window(const double *x, size_t n, double rate, int window, double *f, double *P,
                                  nl_error *err)
{
  if (window == NL_SPECTRUM_RECT) return nl_spectrum_psd1(x, n, rate, f, P, err);
  if (window != NL_SPECTRUM_HANN) return nl_fail(err, NL_EINVAL, "psd1: unknown window %d", window);
  if (n < 2) return nl_fail(err, NL_EINVAL, "psd1: need n >= 2 and rate > 0");
  double *w = nl_xmalloc(n * sizeof *w), pi2 = 2.0 * acos(-1.0);
  for (size_t j = 0; j < n; j++) w[j] = x[j] * 0.5 * (1.0 - cos(pi2 * (double)j / (double)n));
  nl_status rc = nl_spectrum_psd1(w, n, rate, f, P, err);
  free(w);
  if (!rc)   /* the periodic Hann window's mean square is exactly 3/8 */
    for (size_t k = 0; k < n / 2 + 1; k++) P[k] /= 0.375;
  return rc;
}
