/* nl_gof.c - goodness-of-fit tests (KS, Kuiper, chi-square), ECDF, histogram. */
#include "stats/nl_stats.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- one-sample KS and Kuiper ------------------------------------------- */

double nl_stats_cdf_uniform(double x, void *params)
{
  const double *ab = params;
  double u = (x - ab[0]) / (ab[1] - ab[0]);
  return u < 0.0 ? 0.0 : u > 1.0 ? 1.0 : u;
}

/* The two terms at rank i (0-based) with F value u: scipy's
 * arange(1, n+1)/n - cdf and cdf - arange(0, n)/n. Every path (full and
 * incremental) uses these, which is what makes them agree bit for bit. */
static inline double term_plus(size_t i, size_t n, double u) { return (double)(i + 1) / (double)n - u; }
static inline double term_minus(size_t i, size_t n, double u) { return u - (double)i / (double)n; }
/* fmax of two non-NaN doubles, inline: x86's maxsd, which is what glibc's
 * fmax executes for ordered operands (a > b ? a : b), so every result is the
 * same double; the terms here are never NaN (u is checked to lie in [0, 1]). */
static inline double max2(double a, double b) { return a > b ? a : b; }

static void ks_range_max(const double *u, size_t lo, size_t hi, size_t n,
                         double *dp, double *dm)
{
  double p = -INFINITY, m = -INFINITY;
  for (size_t i = lo; i < hi; i++) {
    p = max2(p, term_plus(i, n, u[i]));
    m = max2(m, term_minus(i, n, u[i]));
  }
  *dp = p;
  *dm = m;
}

void nl_stats_ks_statistic(const double *u, size_t n, double *d_plus, double *d_minus)
{
  ks_range_max(u, 0, n, n, d_plus, d_minus);
}

static nl_status check_finite(const double *x, size_t n, const char *what, nl_error *err)
{
  if (n == 0) return nl_fail(err, NL_EINVAL, "%s: no values", what);
  for (size_t i = 0; i < n; i++)
    if (!isfinite(x[i]))
      return nl_fail(err, NL_EINVAL, "%s: value %zu is %g (NaN or infinite)", what, i + 1, x[i]);
  return NL_OK;
}

/* Sorted copy of x and F at each value. *xs and *us are malloc'ed. */
static nl_status sorted_cdf(const double *x, size_t n, nl_stats_cdf_fn cdf, void *params,
                            double **xs, double **us, nl_error *err)
{
  nl_status s = check_finite(x, n, "sample", err);
  if (s) return s;
  double *a = nl_xmalloc(n * sizeof(double)), *u = nl_xmalloc(n * sizeof(double));
  memcpy(a, x, n * sizeof(double));
  nl_stats_sort(a, n);
  for (size_t i = 0; i < n; i++) {
    u[i] = cdf(a[i], params);
    if (!(u[i] >= 0.0 && u[i] <= 1.0)) {
      s = nl_fail(err, NL_EINVAL, "CDF returned %g at x = %g, outside [0, 1]", u[i], a[i]);
      free(a); free(u);
      return s;
    }
  }
  *xs = a;
  *us = u;
  return NL_OK;
}

/* The width b - a must be finite too: for [-1e308, 1e308] it overflows, and
 * the uniform CDF (x - a) / (b - a) is then 0 or NaN for every x. */
static nl_status check_interval(double a, double b, nl_error *err)
{
  if (!(isfinite(a) && isfinite(b) && a < b))
    return nl_fail(err, NL_EINVAL, "interval [%g, %g) is empty or not finite", a, b);
  if (!isfinite(b - a))
    return nl_fail(err, NL_EINVAL,
                   "interval [%g, %g) is wider than a double holds: rescale the data", a, b);
  return NL_OK;
}

/* D+ and D- of the sample x against cdf: what KS and Kuiper share. */
static nl_status cdf_statistic(const double *x, size_t n, nl_stats_cdf_fn cdf, void *params,
                               double *d_plus, double *d_minus, nl_error *err)
{
  double *xs, *u;
  nl_status s = sorted_cdf(x, n, cdf, params, &xs, &u, err);
  if (s) return s;
  nl_stats_ks_statistic(u, n, d_plus, d_minus);
  free(xs);
  free(u);
  return NL_OK;
}

nl_status nl_stats_ks_test(const double *x, size_t n, nl_stats_cdf_fn cdf, void *params,
                           nl_stats_ks_result *res, nl_error *err)
{
  double dp, dm;
  nl_status s = cdf_statistic(x, n, cdf, params, &dp, &dm, err);
  if (s) return s;
  memset(res, 0, sizeof *res);
  res->d_plus = dp;
  res->d_minus = dm;
  res->d = fmax(res->d_plus, res->d_minus);
  res->n = n;
  res->p = nl_stats_ks_sf(n, res->d, &res->method);
  return NL_OK;
}

nl_status nl_stats_ks_test_uniform(const double *x, size_t n, double a, double b,
                                   nl_stats_ks_result *res, nl_error *err)
{
  double ab[2] = {a, b};
  nl_status s = check_interval(a, b, err);
  return s ? s : nl_stats_ks_test(x, n, nl_stats_cdf_uniform, ab, res, err);
}

double nl_stats_kuiper_sf(size_t n, double v)
{
  double N = (double)n;
  if (n < 2 || v <= 1.0 / N) return 1.0;   /* V >= 1/n always; n = 1 gives V = 1 */
  if (v >= 1.0) return 0.0;
  double p;
  if (v < 2.0 / N) {
    /* Stephens (1965): 1 - n! (v - 1/n)^(n-1) */
    p = 1.0 - exp(nl_lgamma(N + 1.0) + (N - 1.0) * log(v - 1.0 / N));
  } else if (v < 3.0 / N) {
    double k = -(N * v - 1.0) / 2.0, r = sqrt(k * k - (N * v - 2.0) * (N * v - 2.0) / 2.0);
    double a = -k + r, b = -k - r;
    double lc = nl_lgamma(N) - (N - 2.0) * log(N);
    double t1 = exp(lc + (N - 1.0) * log(b)) * (1.0 - a);
    double t2 = exp(lc + (N - 1.0) * log(a)) * (1.0 - b);
    p = 1.0 - (t1 - t2) / (b - a);
  } else if ((v > 0.5 && n % 2 == 0) || (v > (N - 1.0) / (2.0 * N) && n % 2 == 1)) {
    /* Stephens (1965), exact upper tail */
    p = 0.0;
    for (double t = 0.0; t <= floor(N * (1.0 - v)); t += 1.0) {
      double y = v + t / N, c = 1.0 - v - t / N;
      double br = y * y * y * N - y * y * t * (3 - 2 / N) + y * t * (t - 1) * (3 - 2 / N) / N
                  - t * (t - 1) * (t - 2) / (N * N);
      double lt = nl_lgamma(N + 1) - nl_lgamma(t + 1) - nl_lgamma(N - t + 1) + (t - 3) * log(y);
      if (c > 0.0) lt += (N - t - 1) * log(c);
      else if (N - t - 1 > 0) continue;
      p += br * exp(lt);
    }
  } else {
    /* Stephens (1970) asymptotic series; terms past m z > 18.82 underflow */
    double z = v * sqrt(N), s1 = 0.0, s2 = 0.0;
    for (double m = 1.0; m < 18.82 / z; m += 1.0) {
      double q = m * m * z * z, e = exp(-2.0 * q);
      s1 += 2.0 * (4.0 * q - 1.0) * e;
      s2 += m * m * (4.0 * q - 3.0) * e;
    }
    p = s1 - 8.0 * v / 3.0 * s2;
  }
  return p < 0.0 ? 0.0 : p > 1.0 ? 1.0 : p;
}

nl_status nl_stats_kuiper_test(const double *x, size_t n, nl_stats_cdf_fn cdf, void *params,
                               nl_stats_kuiper_result *res, nl_error *err)
{
  nl_status s = cdf_statistic(x, n, cdf, params, &res->d_plus, &res->d_minus, err);
  if (s) return s;
  res->v = res->d_plus + res->d_minus;
  res->n = n;
  res->p = nl_stats_kuiper_sf(n, res->v);
  return NL_OK;
}

nl_status nl_stats_kuiper_test_uniform(const double *x, size_t n, double a, double b,
                                       nl_stats_kuiper_result *res, nl_error *err)
{
  double ab[2] = {a, b};
  nl_status s = check_interval(a, b, err);
  return s ? s : nl_stats_kuiper_test(x, n, nl_stats_cdf_uniform, ab, res, err);
}

/* ---- two-sample KS ------------------------------------------------------ */

nl_status nl_stats_ks2_test(const double *x, size_t n1, const double *y, size_t n2,
                            nl_stats_ks_result *res, nl_error *err)
{
  nl_status s = check_finite(x, n1, "first sample", err);
  if (!s) s = check_finite(y, n2, "second sample", err);
  if (s) return s;
  double *a = nl_xmalloc(n1 * sizeof(double)), *b = nl_xmalloc(n2 * sizeof(double));
  memcpy(a, x, n1 * sizeof(double));
  memcpy(b, y, n2 * sizeof(double));
  nl_stats_sort(a, n1);
  nl_stats_sort(b, n2);
  /* Walk the pooled sample; evaluate F1 - F2 only after all copies of a value
   * are consumed (scipy's searchsorted(side='right')). */
  double dp = 0.0, dm = 0.0;
  size_t i = 0, j = 0;
  while (i < n1 || j < n2) {
    double v = (j >= n2 || (i < n1 && a[i] <= b[j])) ? a[i] : b[j];
    while (i < n1 && a[i] == v) i++;
    while (j < n2 && b[j] == v) j++;
    double diff = (double)i / (double)n1 - (double)j / (double)n2;
    dp = fmax(dp, diff);
    dm = fmax(dm, -diff);
  }
  free(a);
  free(b);
  memset(res, 0, sizeof *res);
  res->d_plus = dp;
  res->d_minus = dm;
  res->d = fmax(dp, dm);
  res->n = n1;
  res->n2 = n2;
  res->p = nl_stats_ks2_sf(n1, n2, res->d, &res->method);
  if (res->method == NL_KS_TWO_SAMPLE_EXACT) {
    /* report the lattice value the exact p belongs to, as scipy does */
    long g = (long)n1, h = (long)n2;
    while (h) { long t = g % h; g = h; h = t; }
    double lcm = (double)((long)n1 / g * (long)n2);
    res->d = nearbyint(res->d * lcm) / lcm;
  }
  return NL_OK;
}

/* ---- incremental KS ------------------------------------------------------ */

/* The hot path of the optimisers (nl_cheng). Every term is the same double
 * as term_plus/term_minus's (rank[i] = (double)i / (double)n is that very
 * quotient), and a maximum is a selection, so any order of taking it gives
 * the same double as ks_range_max's left-to-right scan; the one value two
 * orders could tell apart, the sign of a zero maximum, cannot reach d or
 * D+ + D- (D+ + D- >= 1/n, so a zero D- sits beside a positive D+). */
#if defined(__SSE2__)
#include <emmintrin.h>
static inline double hmax(__m128d v) { return max2(_mm_cvtsd_f64(v), _mm_cvtsd_f64(_mm_unpackhi_pd(v, v))); }
#endif

static void incr_block(nl_stats_ks_incr *s, size_t b)
{
  size_t lo = b * NL_KS_INCR_BLOCK, hi = lo + NL_KS_INCR_BLOCK, i = lo;
  if (hi > s->n) hi = s->n;
  const double *u = s->u, *r = s->rank;
  double p = -INFINITY, m = -INFINITY;
#if defined(__SSE2__)
  if (hi - lo >= 8) {   /* four independent chains of maxpd */
    __m128d p0 = _mm_set1_pd(-INFINITY), p1 = p0, m0 = p0, m1 = p0;
    for (; i + 4 <= hi; i += 4) {
      __m128d u0 = _mm_loadu_pd(u + i), u1 = _mm_loadu_pd(u + i + 2);
      p0 = _mm_max_pd(p0, _mm_sub_pd(_mm_loadu_pd(r + i + 1), u0));
      p1 = _mm_max_pd(p1, _mm_sub_pd(_mm_loadu_pd(r + i + 3), u1));
      m0 = _mm_max_pd(m0, _mm_sub_pd(u0, _mm_loadu_pd(r + i)));
      m1 = _mm_max_pd(m1, _mm_sub_pd(u1, _mm_loadu_pd(r + i + 2)));
    }
    p = hmax(_mm_max_pd(p0, p1));
    m = hmax(_mm_max_pd(m0, m1));
  }
#endif
  for (; i < hi; i++) {
    p = max2(p, r[i + 1] - u[i]);
    m = max2(m, u[i] - r[i]);
  }
  s->bplus[b] = p;
  s->bminus[b] = m;
}

static void incr_total(nl_stats_ks_incr *s)
{
  double p = -INFINITY, m = -INFINITY;
  size_t b = 0;
#if defined(__SSE2__)
  __m128d vp = _mm_set1_pd(-INFINITY), vm = vp;
  for (; b + 2 <= s->nblocks; b += 2) {
    vp = _mm_max_pd(vp, _mm_loadu_pd(s->bplus + b));
    vm = _mm_max_pd(vm, _mm_loadu_pd(s->bminus + b));
  }
  p = hmax(vp);
  m = hmax(vm);
#endif
  for (; b < s->nblocks; b++) {
    p = max2(p, s->bplus[b]);
    m = max2(m, s->bminus[b]);
  }
  s->d_plus = p;
  s->d_minus = m;
  s->d = max2(p, m);
}

nl_stats_ks_incr *nl_stats_ks_incr_alloc(const double *x, size_t n, nl_stats_cdf_fn cdf, void *params,
                                         nl_error *err)
{
  double *xs, *u;
  if (sorted_cdf(x, n, cdf, params, &xs, &u, err)) return NULL;
  nl_stats_ks_incr *s = nl_xcalloc(1, sizeof *s);
  s->n = n;
  s->x = xs;
  s->u = u;
  s->cdf = cdf;
  s->params = params;
  s->nblocks = (n + NL_KS_INCR_BLOCK - 1) / NL_KS_INCR_BLOCK;
  s->bplus = nl_xmalloc(s->nblocks * sizeof(double));
  s->bminus = nl_xmalloc(s->nblocks * sizeof(double));
  s->rank = nl_xmalloc((n + 1) * sizeof(double));
  s->ubplus = nl_xmalloc(s->nblocks * sizeof(double));
  s->ubminus = nl_xmalloc(s->nblocks * sizeof(double));
  for (size_t i = 0; i <= n; i++) s->rank[i] = (double)i / (double)n;
  for (size_t b = 0; b < s->nblocks; b++) incr_block(s, b);
  incr_total(s);
  return s;
}

void nl_stats_ks_incr_free(nl_stats_ks_incr *s)
{
  if (!s) return;
  free(s->x);
  free(s->u);
  free(s->bplus);
  free(s->bminus);
  free(s->rank);
  free(s->ubplus);
  free(s->ubminus);
  free(s);
}

/* First index with x[i] >= v (lower_bound); the branch-free halving keeps
 * the CPU from mispredicting every other step. */
static size_t lower_bound(const double *x, size_t n, double v)
{
  size_t lo = 0;
  while (n > 1) {
    size_t half = n / 2;
    lo += half & (0 - (size_t)(x[lo + half - 1] < v));   /* a mask, not a branch */
    n -= half;
  }
  return lo + (n == 1 && x[lo] < v);
}

/* lower_bound(x, n, v) of the sorted sample, searched first in the window
 * the statistic allows: a value v with F(v) = u at rank p has
 * (p + 1) / n - u <= D+ and u - p / n <= D-, so n (u - D-) <= p <= n (u + D+) - 1
 * (widened by two ranks for rounding); in a sorted window the count of
 * values below v is lower_bound's answer. The answer is checked (the one rank
 * with x[p-1] < v <= x[p]) and searched over the whole sample otherwise, so
 * the window decides only the speed. */
static size_t rank_of(const nl_stats_ks_incr *s, double v)
{
  const double *x = s->x;
  size_t n = s->n;
  double u = s->cdf(v, s->params), lo_f = (double)n * (u - s->d_minus) - 2.0, hi_f = (double)n * (u + s->d_plus) + 2.0;
  if (!(lo_f <= hi_f)) return lower_bound(x, n, v);   /* NaN: no window */
  size_t lo = lo_f > 0 ? (lo_f < (double)n ? (size_t)lo_f : n) : 0;
  size_t hi = hi_f < (double)n ? (hi_f > 0 ? (size_t)hi_f : 0) : n;
  if (hi < lo) hi = lo;
  size_t p = lo;
  if (hi - lo <= 64) {   /* count the smaller values: independent loads, no chain of dependent ones */
    size_t i = lo;
#if defined(__SSE2__)
    /* two at a time: each compare's mask is -1 where x[i] < v (NaN: 0, as x[i] < v) */
    __m128i c = _mm_setzero_si128();
    const __m128d vv = _mm_set1_pd(v);
    for (; i + 2 <= hi; i += 2)
      c = _mm_sub_epi64(c, _mm_castpd_si128(_mm_cmplt_pd(_mm_loadu_pd(x + i), vv)));
    p += (size_t)_mm_cvtsi128_si64(c) + (size_t)_mm_cvtsi128_si64(_mm_unpackhi_epi64(c, c));
#endif
    for (; i < hi; i++) p += x[i] < v;
  } else
    p += lower_bound(x + lo, hi - lo, v);
  if ((p == 0 || x[p - 1] < v) && (p == n || x[p] >= v)) return p;
  return lower_bound(x, n, v);
}

/* A move of an optimiser usually shifts a value by a few ranks: walk that
 * far, then fall back to a binary search and memmove. */
#define INCR_WALK 16

nl_status nl_stats_ks_incr_replace(nl_stats_ks_incr *s, double old_value, double new_value,
                                   nl_error *err)
{
  size_t n = s->n, p = rank_of(s, old_value), q;
  s->can_undo = 0;
  if (p == n || s->x[p] != old_value)
    return nl_fail(err, NL_EINVAL, "value %.17g is not in the sample", old_value);
  double u = isfinite(new_value) ? s->cdf(new_value, s->params) : NAN;
  if (!(u >= 0.0 && u <= 1.0))
    return nl_fail(err, NL_EINVAL, "new value %g (F = %g) is not finite or F not in [0, 1]",
                   new_value, u);
  /* Remove rank p, insert at the rank that keeps the order (the ranks in
   * between shift by one place): q = p + #{x[p+1..] < new} going up, the
   * first rank below p with x >= new going down. */
  double *x = s->x, *uu = s->u;
  s->ux = x[p];
  s->uu = uu[p];
  q = p;
  if (new_value > old_value) {
    size_t end = p + INCR_WALK < n ? p + INCR_WALK : n;
    while (q + 1 < end && x[q + 1] < new_value) { x[q] = x[q + 1]; uu[q] = uu[q + 1]; q++; }
    if (q + 1 == end && end < n) {   /* walked the whole stretch: search the rest */
      size_t r = lower_bound(x + q + 1, n - q - 1, new_value) + q;
      memmove(x + q, x + q + 1, (r - q) * sizeof(double));
      memmove(uu + q, uu + q + 1, (r - q) * sizeof(double));
      q = r;
    }
  } else {
    size_t end = p > INCR_WALK ? p - INCR_WALK : 0;
    while (q > end && x[q - 1] >= new_value) { x[q] = x[q - 1]; uu[q] = uu[q - 1]; q--; }
    if (q == end && end > 0) {
      size_t r = lower_bound(x, q, new_value);
      memmove(x + r + 1, x + r, (q - r) * sizeof(double));
      memmove(uu + r + 1, uu + r, (q - r) * sizeof(double));
      q = r;
    }
  }
  x[q] = new_value;
  uu[q] = u;
  size_t lo = p < q ? p : q, hi = p < q ? q : p;
  s->from = p;
  s->to = q;
  s->ud_plus = s->d_plus;
  s->ud_minus = s->d_minus;
  s->ud = s->d;
  for (size_t b = lo / NL_KS_INCR_BLOCK; b <= hi / NL_KS_INCR_BLOCK; b++) {
    s->ubplus[b] = s->bplus[b];
    s->ubminus[b] = s->bminus[b];
    incr_block(s, b);
  }
  incr_total(s);
  s->can_undo = 1;
  return NL_OK;
}

nl_status nl_stats_ks_incr_undo(nl_stats_ks_incr *s, nl_error *err)
{
  if (!s->can_undo) return nl_fail(err, NL_EINVAL, "no replace to undo");
  /* The inverse shift puts every value back at its rank; a replace back
   * would give the same arrays (equal values are interchangeable, and the
   * old value's first rank among its equals is where it came from). */
  size_t p = s->from, q = s->to;
  double *x = s->x, *uu = s->u;
  if (p < q) {
    if (q - p < INCR_WALK) for (size_t i = q; i > p; i--) { x[i] = x[i - 1]; uu[i] = uu[i - 1]; }
    else { memmove(x + p + 1, x + p, (q - p) * sizeof(double)); memmove(uu + p + 1, uu + p, (q - p) * sizeof(double)); }
  } else {
    if (p - q < INCR_WALK) for (size_t i = q; i < p; i++) { x[i] = x[i + 1]; uu[i] = uu[i + 1]; }
    else { memmove(x + q, x + q + 1, (p - q) * sizeof(double)); memmove(uu + q, uu + q + 1, (p - q) * sizeof(double)); }
  }
  x[p] = s->ux;
  uu[p] = s->uu;
  size_t lo = p < q ? p : q, hi = p < q ? q : p;
  for (size_t b = lo / NL_KS_INCR_BLOCK; b <= hi / NL_KS_INCR_BLOCK; b++) {
    s->bplus[b] = s->ubplus[b];
    s->bminus[b] = s->ubminus[b];
  }
  s->d_plus = s->ud_plus;
  s->d_minus = s->ud_minus;
  s->d = s->ud;
  s->can_undo = 0;
  return NL_OK;
}

double nl_stats_ks_incr_p(const nl_stats_ks_incr *s)
{
  return nl_stats_ks_sf(s->n, s->d, NULL);
}

/* ---- chi-square ----------------------------------------------------------- */

nl_status nl_stats_chisq_test(const double *observed, const double *expected, size_t k,
                              nl_stats_chisq_result *res, nl_error *err)
{
  if (k < 2) return nl_fail(err, NL_EINVAL, "chi-square needs at least 2 bins, got %zu", k);
  double chi2 = 0.0, emin = INFINITY, n = 0.0;
  for (size_t i = 0; i < k; i++) {
    if (!(expected[i] > 0.0 && isfinite(expected[i]) && isfinite(observed[i])))
      return nl_fail(err, NL_EINVAL, "bin %zu: expected count %g is not positive and finite",
                     i + 1, expected[i]);
    double dlt = observed[i] - expected[i];
    chi2 += dlt * dlt / expected[i];
    emin = fmin(emin, expected[i]);
    n += observed[i];
  }
  res->chi2 = chi2;
  res->df = k - 1;
  res->p = gsl_cdf_chisq_Q(chi2, (double)(k - 1));
  res->min_expected = emin;
  res->low_expected = emin < 5.0;
  res->n = (size_t)n;
  res->k = k;
  return NL_OK;
}

/* Bin index of v in k equal bins of [a, b], numpy.histogram's rule: compute
 * the index arithmetically, then correct it against the bin edges
 * a + i (b - a)/k so that values on an edge go to the bin the edge opens; the
 * last bin is closed. */
static size_t bin_index(double v, size_t k, double a, double b)
{
  double step = (b - a) / (double)k;
  size_t i = (size_t)((v - a) * ((double)k / (b - a)));
  if (i >= k) i = k - 1;
  if (i > 0 && v < a + (double)i * step) i--;
  else if (i + 1 < k && v >= a + (double)(i + 1) * step) i++;
  return i;
}

gsl_histogram *nl_stats_histogram_uniform(const double *x, size_t n, size_t k, double a,
                                          double b, size_t *outside, nl_error *err)
{
  if (k < 1 || check_interval(a, b, err)) {
    if (k < 1) nl_fail(err, NL_EINVAL, "histogram needs at least 1 bin");
    return NULL;
  }
  /* bin_index scales by k / (b - a): infinite for 2 bins of [0, 1e-308],
   * and 0 * inf is NaN, which has no bin. */
  if (!isfinite((double)k / (b - a))) {
    nl_fail(err, NL_EINVAL, "interval [%g, %g) is too narrow for %zu equal bins", a, b, k);
    return NULL;
  }
  gsl_histogram *h = gsl_histogram_alloc(k);
  gsl_histogram_set_ranges_uniform(h, a, b);
  size_t out = 0;
  for (size_t i = 0; i < n; i++) {
    if (!(x[i] >= a && x[i] <= b)) { out++; continue; }
    h->bin[bin_index(x[i], k, a, b)] += 1.0;
  }
  if (outside) *outside = out;
  return h;
}

nl_status nl_stats_chisq_test_uniform(const double *x, size_t n, size_t k, double a, double b,
                                      nl_stats_chisq_result *res, nl_error *err)
{
  nl_status s = check_finite(x, n, "sample", err);
  if (s) return s;
  if (k < 2) return nl_fail(err, NL_EINVAL, "chi-square needs at least 2 bins, got %zu", k);
  size_t out;
  gsl_histogram *h = nl_stats_histogram_uniform(x, n, k, a, b, &out, err);
  if (!h) return NL_EINVAL;
  if (out) {
    gsl_histogram_free(h);
    return nl_fail(err, NL_EINVAL, "%zu of %zu values lie outside [%g, %g]", out, n, a, b);
  }
  double *e = nl_xmalloc(k * sizeof(double));
  for (size_t i = 0; i < k; i++) e[i] = (double)n / (double)k;
  s = nl_stats_chisq_test(h->bin, e, k, res, err);
  free(e);
  gsl_histogram_free(h);
  return s;
}

/* ---- ECDF ------------------------------------------------------------------ */

nl_stats_ecdf *nl_stats_ecdf_alloc(const double *x, size_t n, nl_error *err)
{
  if (check_finite(x, n, "sample", err)) return NULL;
  nl_stats_ecdf *e = nl_xmalloc(sizeof *e);
  e->n = n;
  e->x = nl_xmalloc(n * sizeof(double));
  memcpy(e->x, x, n * sizeof(double));
  nl_stats_sort(e->x, n);
  return e;
}

void nl_stats_ecdf_free(nl_stats_ecdf *e)
{
  if (!e) return;
  free(e->x);
  free(e);
}

double nl_stats_ecdf_eval(const nl_stats_ecdf *e, double t)
{
  size_t lo = 0, hi = e->n;   /* first index with x > t */
  while (lo < hi) {
    size_t mid = lo + (hi - lo) / 2;
    if (e->x[mid] <= t) lo = mid + 1; else hi = mid;
  }
  return (double)lo / (double)e->n;
}

size_t nl_stats_chisq_bin(double v, size_t k, double a, double b)
{
  return bin_index(v, k, a, b);
}

/* ---- one-sided alternatives ---------------------------------------------- */

nl_status nl_stats_ks_alternative_parse(const char *name, nl_stats_ks_alternative *alt,
                                        nl_error *err)
{
  if (!strcmp(name, "two-sided")) *alt = NL_KS_TWO_SIDED;
  else if (!strcmp(name, "less")) *alt = NL_KS_LESS;
  else if (!strcmp(name, "greater")) *alt = NL_KS_GREATER;
  else
    return nl_fail(err, NL_EINVAL, "unknown alternative '%s' (two-sided, less or greater)", name);
  return NL_OK;
}

void nl_stats_ks_one_sided(nl_stats_ks_result *r, nl_stats_ks_alternative alt)
{
  if (alt == NL_KS_TWO_SIDED) return;
  double d = alt == NL_KS_GREATER ? r->d_plus : r->d_minus;
  if (r->n2 == 0) {
    /* the exact one-sided law for any n: scipy's ksone.sf = special.smirnov */
    r->d = d;
    r->p = nl_stats_smirnov_sf(r->n, d);
    r->method = NL_KS_SMIRNOV;
    return;
  }
  r->p = nl_stats_ks2_sf_one_sided(r->n, r->n2, d, &r->method);
  r->d = d;
  if (r->method == NL_KS_TWO_SAMPLE_EXACT) {
    /* the lattice value the exact p belongs to, as for the two-sided test */
    long g = (long)r->n, h = (long)r->n2;
    while (h) { long t = g % h; g = h; h = t; }
    double lcm = (double)((long)r->n / g * (long)r->n2);
    r->d = nearbyint(d * lcm) / lcm;
  }
}
