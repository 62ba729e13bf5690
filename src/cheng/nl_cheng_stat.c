/* The statistic term E_stat of eq. 3.9 (KS eq. 3.7, chi-square eq. 3.4,
 * Kuiper), full and incremental, as a thin layer on nl_stats. */
#include "cheng/nl_cheng_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Both chi-square terms keep bin counts; they differ only in the value. */
static int is_chisq(nl_cheng_stat k) { return k == NL_CHENG_STAT_CHISQ || k == NL_CHENG_STAT_CHISQ_RAW; }

void nl_cheng__stat_init(nl_cheng_statstate *s, nl_cheng_stat kind, size_t bins)
{
  memset(s, 0, sizeof *s);
  s->kind = kind;
  s->k = bins;
  s->range[0] = 0.0;
  s->range[1] = NL_TWO_PI;
}

void nl_cheng__stat_clear(nl_cheng_statstate *s)
{
  nl_stats_ks_incr_free(s->ks);
  free(s->count);
  s->ks = NULL;
  s->count = NULL;
}

void nl_cheng__stat_reset(nl_cheng_statstate *s, const double *x, size_t n)
{
  nl_cheng__stat_clear(s);
  s->n = n;
  if (n == 0) return;
  if (is_chisq(s->kind)) {
    s->count = nl_xcalloc(s->k, sizeof *s->count);
    for (size_t i = 0; i < n; i++) s->count[nl_cheng__bin(x[i], s->k)]++;
    s->sumsq = 0;
    for (size_t b = 0; b < s->k; b++) s->sumsq += s->count[b] * s->count[b];
    return;
  }
  /* Angles are produced in [0, 2 pi) by construction; a failure here is a bug. */
  nl_error err;
  s->ks = nl_stats_ks_incr_alloc(x, n, nl_stats_cdf_uniform, s->range, &err);
  if (!s->ks) { fprintf(stderr, "nl_cheng: %s\n", err.msg); abort(); }
}

void nl_cheng__stat_replace(nl_cheng_statstate *s, double old_value, double new_value)
{
  if (s->n == 0) return;
  if (is_chisq(s->kind)) {
    size_t a = nl_cheng__bin(old_value, s->k), b = nl_cheng__bin(new_value, s->k);
    if (a == b) return;
    /* (c-1)^2 - c^2 = 1 - 2c and (c+1)^2 - c^2 = 1 + 2c: integers, exact. */
    s->sumsq += 2 - 2 * s->count[a] + 2 * s->count[b];
    s->count[a]--;
    s->count[b]++;
    return;
  }
  nl_error err;
  if (nl_stats_ks_incr_replace(s->ks, old_value, new_value, &err)) {
    fprintf(stderr, "nl_cheng: %s\n", err.msg);
    abort();
  }
}

/* Takes back the last replace (old_value -> new_value): KS and Kuiper put
 * the saved state back (nl_stats_ks_incr_undo), chi-square moves the count. */
void nl_cheng__stat_undo(nl_cheng_statstate *s, double old_value, double new_value)
{
  if (s->n == 0) return;
  if (is_chisq(s->kind)) { nl_cheng__stat_replace(s, new_value, old_value); return; }
  nl_error err;
  if (nl_stats_ks_incr_undo(s->ks, &err)) {
    fprintf(stderr, "nl_cheng: %s\n", err.msg);
    abort();
  }
}

/* Cramer's V of a chi-square statistic: chi2 on KS's scale (see nl_cheng.h). */
static double cramer_v(double chi2, size_t n, size_t k)
{
  return sqrt(fmax(chi2, 0.0) / ((double)n * (double)(k - 1)));
}

double nl_cheng__stat_value(const nl_cheng_statstate *s)
{
  if (s->n == 0) return 0.0;
  if (is_chisq(s->kind)) {
    /* sum (O - E)^2 / E = sum O^2 / E - n with E = n / k. */
    double chi2 = (double)s->sumsq * (double)s->k / (double)s->n - (double)s->n;
    return s->kind == NL_CHENG_STAT_CHISQ_RAW ? chi2 : cramer_v(chi2, s->n, s->k);
  }
  return s->kind == NL_CHENG_STAT_KUIPER ? s->ks->d_plus + s->ks->d_minus : s->ks->d;
}

double nl_cheng__stat_full(nl_cheng_stat kind, size_t bins, const double *x, size_t n)
{
  if (n == 0) return 0.0;
  nl_error err;
  nl_status st;
  double v = 0;
  if (is_chisq(kind)) {
    nl_stats_chisq_result r;
    st = nl_stats_chisq_test_uniform(x, n, bins, 0.0, NL_TWO_PI, &r, &err);
    v = kind == NL_CHENG_STAT_CHISQ_RAW ? r.chi2 : cramer_v(r.chi2, n, bins);
  } else if (kind == NL_CHENG_STAT_KUIPER) {
    nl_stats_kuiper_result r;
    st = nl_stats_kuiper_test_uniform(x, n, 0.0, NL_TWO_PI, &r, &err);
    v = r.v;
  } else {
    nl_stats_ks_result r;
    st = nl_stats_ks_test_uniform(x, n, 0.0, NL_TWO_PI, &r, &err);
    v = r.d;
  }
  if (st) { fprintf(stderr, "nl_cheng: %s\n", err.msg); abort(); }
  return v;
}

/* Median of the one-sample KS statistic D_n under the null: the yardstick
 * for "as uniform as a random table". */
double nl_cheng_ks_median(size_t n)
{
  double lo = 0, hi = 1;   /* bisection on the exact CDF of D_n */
  for (int it = 0; it < 60; it++) {
    double mid = 0.5 * (lo + hi);
    if (nl_stats_ks_cdf(n, mid, NULL) < 0.5) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}
