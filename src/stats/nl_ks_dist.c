/* nl_ks_dist.c - the null distribution of the Kolmogorov-Smirnov statistics.
 *
 * A port of scipy 1.10's scipy/stats/_ksstats.py (kstwo), which follows
 * Simard & L'Ecuyer, "Computing the Two-Sided Kolmogorov-Smirnov Distribution",
 * J. Stat. Softw. 39(11), 2011, and of the two-sample lattice-path counts of
 * scipy.stats.ks_2samp (Hodges 1958; Viehmann, arXiv:2102.08037). The region
 * boundaries are scipy's so that the same method, hence the same value to
 * rounding, is chosen for the same (n, d).
 */
#include "stats/nl_stats.h"

#include <gsl/gsl_blas.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>


#define E128 128
static const double EP128 = 0x1p128, EM128 = 0x1p-128;

static double clip01(double p) { return p < 0.0 ? 0.0 : p > 1.0 ? 1.0 : p; }

/* Returns the tail asked for (cdf or sf), clipped to [0, 1]. */
static double pick(int want_cdf, double cdfprob, double sfprob)
{
  return clip01(want_cdf ? cdfprob : sfprob);
}

const char *nl_stats_ks_method_name(nl_stats_ks_method m)
{
  static const char *names[] = {"ruben-gambino", "smirnov", "durbin-mtw", "pomeranz",
                                "pelz-good", "kolmogorov", "exact", "asymp"};
  return (unsigned)m < sizeof names / sizeof names[0] ? names[m] : "?";
}

/* Birnbaum & Tingey (1951): P(D+_n >= d) = d sum_{j=0}^{floor(n(1-d))}
 * C(n,j) (1-d-j/n)^(n-j) (d+j/n)^(j-1). All terms are positive, so summing
 * them in log space loses nothing to cancellation; the relative error is that
 * of lgamma(n+1), about 1e-16 * n log n. */
double nl_stats_smirnov_sf(size_t n, double d)
{
  if (!(d > 0.0)) return 1.0;
  if (d >= 1.0) return 0.0;
  double nn = (double)n, lgn = nl_lgamma(nn + 1.0), sum = 0.0;
  size_t jmax = (size_t)floor(nn * (1.0 - d));
  for (size_t j = 0; j <= jmax && j <= n; j++) {
    double a = (double)(n - j) / nn - d, b = d + (double)j / nn;
    if (a <= 0.0) { if (j == n) sum += pow(b, (double)j - 1.0); continue; }
    double lt = lgn - nl_lgamma((double)j + 1.0) - nl_lgamma(nn - (double)j + 1.0)
                + (nn - (double)j) * log(a) + ((double)j - 1.0) * log(b);
    sum += exp(lt);
  }
  return clip01(d * sum);
}

/* P(K > lambda) for Kolmogorov's limit law: the theta-function form
 * (Jacobi) converges fast for small lambda, the alternating series for
 * large lambda; both to double precision in a few terms. */
double nl_stats_kolmogorov_sf(double lambda)
{
  if (lambda <= 0.0) return 1.0;
  if (lambda < 1.0) {
    double s = 0.0, w = -NL_PI * NL_PI / (8.0 * lambda * lambda);
    for (int k = 1; k < 20; k++) s += exp((2 * k - 1) * (2 * k - 1) * w);
    return clip01(1.0 - sqrt(NL_TWO_PI) / lambda * s);
  }
  double s = 0.0;
  for (int j = 1; j < 100; j++) {
    double t = exp(-2.0 * j * j * lambda * lambda);
    s += (j % 2 ? t : -t);
    if (t < 1e-300) break;
  }
  return clip01(2.0 * s);
}

/* C = A B for m x m matrices (GSL's CBLAS, i.e. OpenBLAS here). */
static void matmul(size_t m, const double *a, const double *b, double *c)
{
  gsl_matrix_const_view A = gsl_matrix_const_view_array(a, m, m);
  gsl_matrix_const_view B = gsl_matrix_const_view_array(b, m, m);
  gsl_matrix_view C = gsl_matrix_view_array(c, m, m);
  gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, 1.0, &A.matrix, &B.matrix, 0.0, &C.matrix);
}

/* Durbin's (1968) matrix formula P(D_n < d) = n!/n^n (H^n)_{kk}, with the
 * Marsaglia-Tsang-Wang (2003) scaling that keeps H^n in range by tracking a
 * binary exponent. H is (2k-1) x (2k-1), k = ceil(n d). */
static double ks_cdf_durbin(size_t n, double d)
{
  double nd = (double)n * d;
  if (nd <= 0.5) return 0.0;
  size_t k = (size_t)ceil(nd), m = 2 * k - 1;
  double h = (double)k - nd;
  double *H = nl_xcalloc(3 * m * m + 2 * m, sizeof(double));
  double *P = H + m * m, *T = P + m * m, *v = T + m * m, *w = v + m;
  double fac = 1.0;
  for (size_t j = 1; j <= m; j++) {
    w[j - 1] = fac;
    fac /= (double)j;
    v[j - 1] = (1.0 - pow(h, (double)j)) * fac;
  }
  double tt = pow(fmax(2.0 * h - 1.0, 0.0), (double)m) - 2.0 * pow(h, (double)m);
  v[m - 1] = (1.0 + tt) * fac;
  for (size_t i = 1; i < m; i++)
    for (size_t r = i - 1; r < m; r++) H[r * m + i] = w[r - (i - 1)];
  for (size_t r = 0; r < m; r++) H[r * m] = v[r];
  for (size_t c = 0; c < m; c++) H[(m - 1) * m + c] = v[m - 1 - c];
  for (size_t i = 0; i < m; i++) P[i * m + i] = 1.0;
  long expnt = 0, hexpnt = 0;
  for (size_t nn = n; nn > 0; nn /= 2) {
    if (nn % 2) {
      matmul(m, P, H, T);
      memcpy(P, T, m * m * sizeof(double));
      expnt += hexpnt;
    }
    matmul(m, H, H, T);
    memcpy(H, T, m * m * sizeof(double));
    hexpnt *= 2;
    if (fabs(H[(k - 1) * m + k - 1]) > EP128) {
      for (size_t i = 0; i < m * m; i++) H[i] /= EP128;
      hexpnt += E128;
    }
  }
  double p = P[(k - 1) * m + k - 1];
  for (size_t i = 1; i <= n; i++) {
    p = (double)i * p / (double)n;
    if (fabs(p) < EM128) { p *= EP128; expnt -= E128; }
  }
  free(H);
  return clip01(ldexp(p, (int)expnt));
}

/* Row i's window [j1, j2] in Pomeranz's recursion (scipy's
 * _pomeranz_compute_j1j2, same integer arithmetic). */
static void pomeranz_window(long i, long n, long ll, long ceilf, long roundf,
                            long *j1, long *j2)
{
  long a, b;
  if (i == 0) {
    a = -ll - ceilf - 1; b = ll + ceilf - 1;
  } else {
    long half = (i + 1) / 2;
    if ((i + 1) % 2 == 0) {
      if (half == n + 1) { a = n - ll - ceilf - 1; b = n + ll + ceilf - 1; }
      else { a = half - 1 - ll - roundf - 1; b = half + ll - 1 + ceilf - 1; }
    } else {
      a = half - 1 - ll - 1; b = half + ll + roundf - 1;
    }
  }
  *j1 = a + 2 > 0 ? a + 2 : 0;
  *j2 = b < n ? b : n;
}

/* One step: out[t] = (seg * pw)[off + t], a slice of the full convolution of
 * seg (seglen) and pw (plen), t < outlen. */
static void conv_slice(const double *seg, long seglen, const double *pw, long plen,
                       long off, long outlen, double *out)
{
  for (long t = 0; t < outlen; t++) {
    long tt = off + t, s0 = tt - plen + 1 > 0 ? tt - plen + 1 : 0;
    long s1 = tt < seglen - 1 ? tt : seglen - 1;
    double s = 0.0;
    for (long s_ = s0; s_ <= s1; s_++) s += seg[s_] * pw[tt - s_];
    out[t] = s;
  }
}

/* Pomeranz (1974) recursion for P(D_n <= d), as in scipy's _kolmogn_Pomeranz:
 * 2n+1 convolution steps with the powers (g/n)^m/m!, (2g/n)^m/m!,
 * ((1-2g)/n)^m/m!, rescaled by 2^128 whenever a row gets small. */
static double ks_cdf_pomeranz(size_t nz, double x)
{
  long n = (long)nz;
  double t = (double)n * x;
  long ll = (long)floor(t);
  double f = t - (double)ll, g = fmin(f, 1.0 - f);
  long ceilf = f > 0, roundf = f > 0.5, np_ = 2 * (ll + 1);
  double *buf = nl_xcalloc(5 * (size_t)np_, sizeof(double));
  double *gp = buf, *tgp = gp + np_, *omp = tgp + np_, *V0 = omp + np_, *V1 = V0 + np_;
  gp[0] = tgp[0] = omp[0] = 1.0;
  double gn = g / (double)n, tgn = 2 * g / (double)n, omn = (1 - 2 * g) / (double)n;
  for (long m = 1; m < np_; m++) {
    gp[m] = gp[m - 1] * gn / (double)m;
    tgp[m] = tgp[m - 1] * tgn / (double)m;
    omp[m] = omp[m - 1] * omn / (double)m;
  }
  V1[0] = 1.0;
  long V0s = 0, V1s = 0, j1, j2, expnt = 0;
  pomeranz_window(0, n, ll, ceilf, roundf, &j1, &j2);
  for (long i = 1; i < 2 * n + 2; i++) {
    long k1 = j1, ts = V0s;
    double *tv = V0; V0 = V1; V1 = tv;
    V0s = V1s; V1s = ts;
    memset(V1, 0, (size_t)np_ * sizeof(double));
    pomeranz_window(i, n, ll, ceilf, roundf, &j1, &j2);
    const double *pw = (i == 1 || i == 2 * n + 1) ? gp : (i % 2 ? tgp : omp);
    long ln2 = j2 - k1 + 1;
    if (ln2 <= 0) continue;
    long base = k1 - V0s, seglen = ln2 < np_ - base ? ln2 : np_ - base;
    long plen = ln2 < np_ ? ln2 : np_;
    conv_slice(V0 + base, seglen, pw, plen, j1 - k1, j2 - j1 + 1, V1);
    double mx = 0.0;
    for (long j = 0; j < np_; j++) mx = fmax(mx, V1[j]);
    if (mx > 0.0 && mx < EM128) {
      for (long j = 0; j < np_; j++) V1[j] *= EP128;
      expnt -= E128;
    }
    V1s = V0s + j1 - k1;
  }
  double ans = V1[n - V1s];
  free(buf);
  for (long m = 1; m <= n; m++) {
    if (fabs(ans) > EP128) { ans *= EM128; expnt += E128; }
    ans *= (double)m;
  }
  return clip01(ldexp(ans, (int)expnt));
}

/* Pelz & Good (1976): P(D_n <= x) ~ K0(z) + K1(z)/sqrt(n) + K2(z)/n +
 * K3(z)/n^1.5, z = x sqrt(n), each K written with Jacobi theta functions so
 * that it converges for small z. want_cdf selects the tail. */
static double ks_pelz_good(size_t n, double x, int want_cdf)
{
  const double pi2 = NL_PI * NL_PI, pi4 = pi2 * pi2, pi6 = pi4 * pi2;
  const double sqrt2pi = sqrt(NL_TWO_PI);
  double z = sqrt((double)n) * x, z2 = z * z, z3 = z2 * z, z4 = z2 * z2, z6 = z4 * z2;
  double qlog = -pi2 / 8.0 / z2;
  if (qlog < -708) return want_cdf ? 0.0 : 1.0;
  double q = exp(qlog);
  double k1a = -z2, k1b = pi2 / 4;
  double k2a = 6 * z6 + 2 * z4, k2b = (2 * z4 - 5 * z2) * pi2 / 4, k2c = pi4 * (1 - 2 * z2) / 16;
  double k3d = pi6 * (5 - 30 * z2) / 64, k3c = pi4 * (-60 * z2 + 212 * z4) / 16;
  double k3b = pi2 * (135 * z4 - 96 * z6) / 4, k3a = -30 * z6 - 90 * z4 * z4;
  double K[4] = {0, 0, 0, 0};
  long maxk = (long)ceil(16 * z / NL_PI);
  for (long k = maxk; k > 0; k--) {
    double m = 2.0 * k - 1, m2 = m * m, m4 = m2 * m2, m6 = m4 * m2;
    double qp = pow(q, 8.0 * k);
    double c[4] = {1.0, k1a + k1b * m2, k2a + k2b * m2 + k2c * m4,
                   k3a + k3b * m2 + k3c * m4 + k3d * m6};
    for (int i = 0; i < 4; i++) K[i] = K[i] * qp + c[i];
  }
  double den[4] = {z, 6 * z4, 72 * z4 * z3, 6480 * z6 * z4};
  for (int i = 0; i < 4; i++) K[i] = K[i] * q * sqrt2pi / den[i];
  q = exp(-pi2 / 2 / z2);
  double e2 = 0.0, e3 = 0.0, s3z = sqrt(3.0) * z;
  for (long k = maxk; k > 0; k--) {
    double k2 = (double)k * (double)k, qk = pow(q, k2), kpi = NL_PI * (double)k;
    e2 += k2 * qk;
    e3 += (s3z + kpi) * (s3z - kpi) * k2 * qk;
  }
  K[2] += e2 * pi2 * sqrt2pi / (-36 * z3);
  K[3] += e3 * pi2 * sqrt2pi / (216 * z6);
  double sum = 0.0, rn = sqrt((double)n);
  for (int i = 0; i < 4; i++) {
    double ki = K[i] / pow(rn, (double)i);
    if (!want_cdf) ki = -ki + (i == 0 ? 1.0 : 0.0);
    sum += ki;
  }
  return sum;
}

/* log(n!/n^n) by Stirling's series (scipy's _log_nfactorial_div_n_pow_n). */
static double log_nfact_div_npow(double n)
{
  static const double c[] = {-2.955065359477124183e-2, 6.4102564102564102564e-3,
                             -1.9175269175269175269e-3, 8.4175084175084175084e-4,
                             -5.952380952380952381e-4, 7.9365079365079365079e-4,
                             -2.7777777777777777778e-3, 8.3333333333333333333e-2};
  double rn = 1.0 / n, y = rn / n, p = 0.0;
  for (int i = 0; i < 8; i++) p = p * y + c[i];
  return log(n) / 2 - n + log(NL_TWO_PI) / 2 + rn * p;
}

/* The middle range 1 < n d < n - 1 of scipy's _kolmogn. */
static double kolmogn_mid(size_t n, double x, int want_cdf, nl_stats_ks_method *m)
{
  double nn = (double)n, nx2 = nn * x * x, p;
  *m = NL_KS_SMIRNOV;
  if (n > 140 && !want_cdf && nx2 >= 370.0) return 0.0;   /* below 1e-321 */
  if (x >= 0.5 || (n <= 140 && nx2 > 4) || (n > 140 && !want_cdf && nx2 >= 2.2)) {
    /* exact for x >= 0.5; elsewhere the two one-sided tails no longer overlap
     * to double precision (Simard & L'Ecuyer sec. 3) */
    p = 2 * nl_stats_smirnov_sf(n, x);
    return pick(want_cdf, 1.0 - p, p);
  }
  if (n <= 140 || (n <= 100000 && nn * pow(x, 1.5) <= 1.4 && nx2 < 18.0)) {
    if (n > 140 || nx2 <= 0.754693) { *m = NL_KS_DURBIN_MTW; p = ks_cdf_durbin(n, x); }
    else { *m = NL_KS_POMERANZ; p = ks_cdf_pomeranz(n, x); }
    return pick(want_cdf, p, 1.0 - p);
  }
  if (nx2 >= 18.0) return pick(want_cdf, 1.0, 0.0);
  *m = NL_KS_PELZ_GOOD;
  return clip01(ks_pelz_good(n, x, want_cdf));
}

/* scipy's _kolmogn: P(D_n <= x) or P(D_n >= x), choosing the method by n,
 * n x and n x^2 (Simard & L'Ecuyer 2011, fig. 1). */
static double kolmogn(size_t n, double x, int want_cdf, nl_stats_ks_method *method)
{
  nl_stats_ks_method m = NL_KS_RUBEN_GAMBINO;
  double nn = (double)n, t = nn * x, r;
  if (x >= 1.0) r = pick(want_cdf, 1.0, 0.0);
  else if (x <= 0.0 || t <= 0.5) r = pick(want_cdf, 0.0, 1.0);
  else if (t <= 1.0) {        /* Ruben & Gambino (1982): n!/n^n (2t-1)^n */
    double p = 1.0;
    if (n <= 140) for (size_t i = 1; i <= n; i++) p *= (double)i * (1.0 / nn) * (2 * t - 1);
    else p = exp(log_nfact_div_npow(nn) + nn * log(2 * t - 1));
    r = pick(want_cdf, p, 1.0 - p);
  } else if (t >= nn - 1) {   /* Ruben & Gambino: 2 (1-x)^n */
    double p = 2 * pow(1.0 - x, nn);
    r = pick(want_cdf, 1 - p, p);
  } else {
    r = kolmogn_mid(n, x, want_cdf, &m);
  }
  if (method) *method = m;
  return r;
}

double nl_stats_ks_sf(size_t n, double d, nl_stats_ks_method *method)
{
  return kolmogn(n, d, 0, method);
}

double nl_stats_ks_cdf(size_t n, double d, nl_stats_ks_method *method)
{
  return kolmogn(n, d, 1, method);
}

/* P(D_{n,n} >= h/n) = 2 sum_k (-1)^(k-1) C(2n, n-kh)/C(2n, n), summed
 * Horner-fashion from the smallest term to avoid cancellation (scipy's
 * _compute_prob_outside_square). */
static double ks2_prob_outside_square(long n, long h)
{
  double P = 0.0;
  for (long k = n / h; k >= 0; k--) {
    double p1 = 1.0;
    for (long j = 0; j < h; j++)
      p1 = (double)(n - k * h - j) * p1 / (double)(n + k * h + j + 1);
    P = p1 * (1.0 - P);
  }
  return 2 * P;
}

static long floor_div(long a, long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
static long ceil_div(long a, long b) { return -floor_div(-a, b); }

/* Proportion of lattice paths from (0,0) to (m,n) leaving the band
 * |x/m - y/n| < h/lcm(m,n), by the column recursion for 1 - p (Viehmann
 * 2021; scipy's _compute_outer_prob_inside_method). O(m * band width). */
static double ks2_outer_prob_inside(long m, long n, long g, long h)
{
  if (m < n) { long t = m; m = n; n = t; }
  long mg = m / g, ng = n / g;
  long minj = 0, maxj = ceil_div(h, mg) < n + 1 ? ceil_div(h, mg) : n + 1;
  long curlen = maxj - minj, lenA = 2 * maxj + 2 < n + 1 ? 2 * maxj + 2 : n + 1;
  double *A = nl_xmalloc((size_t)lenA * sizeof(double)), res;
  for (long j = 0; j < lenA; j++) A[j] = j < maxj ? 0.0 : 1.0;
  for (long i = 1; i <= m; i++) {
    long lastminj = minj, lastlen = curlen;
    minj = floor_div(ng * i - h, mg) + 1;
    minj = minj < 0 ? 0 : minj > n ? n : minj;
    maxj = ceil_div(ng * i + h, mg) < n + 1 ? ceil_div(ng * i + h, mg) : n + 1;
    if (maxj <= minj) { free(A); return 1.0; }
    double val = minj == 0 ? 0.0 : 1.0;
    for (long jj = 0; jj < maxj - minj; jj++) {
      long j = jj + minj;
      val = (A[jj + minj - lastminj] * (double)i + val * (double)j) / (double)(i + j);
      A[jj] = val;
    }
    curlen = maxj - minj;
    for (long j = curlen; j < curlen + (lastlen - curlen) && j < lenA; j++) A[j] = 1.0;
  }
  res = A[maxj - minj - 1];
  free(A);
  return res;
}

static long gcd_long(long a, long b) { while (b) { long t = a % b; a = b; b = t; } return a; }

/* The exact two-sided law on the lattice h / lcm(n1, n2): 0 where a count
 * overflows or the result is not a probability (scipy then falls back). */
static int ks2_exact_two_sided(size_t n1, size_t n2, double d, double *p)
{
  long g = gcd_long((long)n1, (long)n2), lcm = (long)n1 / g * (long)n2;
  long h = (long)nearbyint(d * (double)lcm);
  *p = h <= 0 ? 1.0
     : n1 == n2 ? ks2_prob_outside_square((long)n1, h)
     : ks2_outer_prob_inside((long)n1, (long)n2, g, h);
  return isfinite(*p) && *p >= 0.0 && *p <= 1.0;
}

/* Smirnov's limit through the one-sample law at n1 n2 / (n1 + n2),
 * rounded half to even like numpy. */
static double ks2_asymp_two_sided(size_t n1, size_t n2, double d)
{
  double a = (double)n1, b = (double)n2, en = nearbyint(a * b / (a + b));
  return nl_stats_ks_sf(en < 1.0 ? 1 : (size_t)en, d, NULL);
}

double nl_stats_ks2_sf(size_t n1, size_t n2, double d, nl_stats_ks_method *method)
{
  double p;
  if (n1 <= 10000 && n2 <= 10000 && ks2_exact_two_sided(n1, n2, d, &p)) {
    if (method) *method = NL_KS_TWO_SAMPLE_EXACT;
    return p;
  }
  if (method) *method = NL_KS_TWO_SAMPLE_ASYMP;
  return ks2_asymp_two_sided(n1, n2, d);
}

/* scipy.special.binom for integer n >= k >= 0: the product for small k (with
 * its rescaling), else 1 / ((n + 1) B(n - k + 1, k + 1)). The one-sided
 * exact p below is a difference of such numbers, so they are computed as
 * scipy computes them. */
static double binom_scipy(double n, double k)
{
  if (k > n / 2 && n > 0) k = n - k;
  if (k >= 0 && k < 20) {
    double num = 1.0, den = 1.0;
    for (int i = 1; i <= (int)k; i++) {
      num *= (double)i + n - k;
      den *= (double)i;
      if (fabs(num) > 1e50) {
        num /= den;
        den = 1.0;
      }
    }
    return num / den;
  }
  double lb = nl_lgamma(n - k + 1.0) + nl_lgamma(k + 1.0) - nl_lgamma(n + 2.0);
  return 1.0 / (n + 1.0) / exp(lb);
}

/* Lattice paths from (0,0) to (m,n) that reach m y <= n x - h g somewhere
 * (Hodges 1958, Drion/Gnedenko/Korolyuk; scipy's _count_paths_outside_method):
 * B_j, the paths to the j-th crossing point that did not cross before, times
 * the extensions to (m, n). Infinite when a count overflows. */
static double ks2_count_paths_outside(long m, long n, long g, long h)
{
  if (m < n) { long t = m; m = n; n = t; }
  long mg = m / g, ng = n / g;
  long lxj = n + floor_div(mg - h, mg);
  if (lxj <= 0) return binom_scipy((double)(m + n), (double)n);
  long *xj = nl_xmalloc((size_t)lxj * sizeof *xj);
  double *B = nl_xmalloc((size_t)lxj * sizeof *B), paths = 0.0;
  for (long j = 0; j < lxj; j++) xj[j] = floor_div(h + mg * j + ng - 1, ng);
  B[0] = 1.0;
  for (long j = 1; j < lxj; j++) {
    double bj = binom_scipy((double)(xj[j] + j), (double)j);
    for (long i = 0; i < j; i++)
      bj -= binom_scipy((double)(xj[j] - xj[i] + j - i), (double)(j - i)) * B[i];
    B[j] = bj;
  }
  for (long j = 0; j < lxj; j++)
    paths += B[j] * binom_scipy((double)(m - xj[j] + n - j), (double)(n - j));
  free(xj);
  free(B);
  return paths;
}

static int ks2_exact_one_sided(size_t n1, size_t n2, double d, double *p)
{
  long g = gcd_long((long)n1, (long)n2), lcm = (long)n1 / g * (long)n2;
  long h = (long)nearbyint(d * (double)lcm);
  if (h <= 0) *p = 1.0;
  else if (n1 == n2) {   /* C(2n, n - h) / C(2n, n) as a product */
    *p = 1.0;
    for (long j = 0; j < h; j++) *p *= ((double)n1 - (double)j) / ((double)n1 + (double)j + 1.0);
  } else {
    double paths = ks2_count_paths_outside((long)n1, (long)n2, g, h);
    double all = binom_scipy((double)(n1 + n2), (double)n1);
    *p = isfinite(all) && isfinite(paths) && paths <= all ? paths / all : NAN;
  }
  return isfinite(*p) && *p >= 0.0 && *p <= 1.0;
}

/* Hodges' (1958) corrected limit, scipy's asymptotic one-sided p. */
static double ks2_asymp_one_sided(size_t n1, size_t n2, double d)
{
  double m = (double)(n1 > n2 ? n1 : n2), n = (double)(n1 > n2 ? n2 : n1), en = m * n / (m + n);
  double z = sqrt(en) * d;
  return clip01(exp(-2 * z * z - 2 * z * (m + 2 * n) / sqrt(m * n * (m + n)) / 3.0));
}

double nl_stats_ks2_sf_one_sided(size_t n1, size_t n2, double d, nl_stats_ks_method *method)
{
  double p;
  if (n1 <= 10000 && n2 <= 10000 && ks2_exact_one_sided(n1, n2, d, &p)) {
    if (method) *method = NL_KS_TWO_SAMPLE_EXACT;
    return p;
  }
  if (method) *method = NL_KS_TWO_SAMPLE_ASYMP;
  return ks2_asymp_one_sided(n1, n2, d);
}

double nl_stats_ks2_sf_method(size_t n1, size_t n2, double d, int one_sided,
                              nl_stats_ks_method want, nl_stats_ks_method *method)
{
  if (want != NL_KS_TWO_SAMPLE_EXACT && want != NL_KS_TWO_SAMPLE_ASYMP)
    return one_sided ? nl_stats_ks2_sf_one_sided(n1, n2, d, method)
                     : nl_stats_ks2_sf(n1, n2, d, method);
  double p;
  /* scipy's bound for trying: lcm(n1, n2) below 2^31 - 1 */
  long g = gcd_long((long)n1, (long)n2);
  int fits = (double)((long)n1 / g) < 2147483647.0 / (double)((long)n2 / g);
  if (want == NL_KS_TWO_SAMPLE_EXACT && fits) {
    /* scipy puts d on the lattice before trying, and keeps it there when
     * it falls back, so the asymptotic p below is of the lattice value */
    double lcm = (double)((long)n1 / g * (long)n2);
    d = nearbyint(d * lcm) / lcm;
  }
  if (want == NL_KS_TWO_SAMPLE_EXACT && fits
      && (one_sided ? ks2_exact_one_sided(n1, n2, d, &p) : ks2_exact_two_sided(n1, n2, d, &p))) {
    if (method) *method = NL_KS_TWO_SAMPLE_EXACT;
    return p;
  }
  if (method) *method = NL_KS_TWO_SAMPLE_ASYMP;
  return one_sided ? ks2_asymp_one_sided(n1, n2, d) : ks2_asymp_two_sided(n1, n2, d);
}
