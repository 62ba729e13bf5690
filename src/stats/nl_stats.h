/* nl_stats.h - goodness-of-fit tests and empirical distributions.
 *
 * One-sample Kolmogorov-Smirnov (KS), against any continuous CDF:
 *   nl_stats_ks_result r;
 *   nl_stats_ks_test_uniform(x, n, 0.0, NL_TWO_PI, &r, &err);   // or nl_stats_ks_test(x, n, cdf, params, ...)
 *   printf("D=%g p=%g via %s\n", r.d, r.p, nl_stats_ks_method_name(r.method));
 * D = max(D+, D-) with D+ = max_i (i/n - F(x_(i))), D- = max_i (F(x_(i)) - (i-1)/n)
 * over the sorted sample (i = 1..n), computed with exactly the expressions of
 * scipy.stats.kstest, so D agrees with scipy to the last bit. The p-value is
 * P(D_n >= D), two-sided, for a continuous F: scipy.stats.kstwo.sf(D, n), which
 * is what kstest(method='auto'/'exact') reports. It follows Simard & L'Ecuyer
 * (2011, J. Stat. Softw. 39(11)) in choosing, by n and n D^2,
 *   - the Ruben-Gambino closed forms for D <= 1/n and D >= 1 - 1/n,
 *   - twice the one-sided exact Smirnov tail (Birnbaum-Tingey) where it is
 *     exact (D >= 0.5) or accurate to double precision (large n D^2),
 *   - Durbin's matrix method with Marsaglia-Tsang-Wang (2003) scaling
 *     for small n D^2 (p near 1),
 *   - Pomeranz's recursion (1974) for n <= 140 and moderate n D^2,
 *   - the Pelz-Good (1976) expansion for n > 140 in between;
 * r.method says which one ran. Relative accuracy against scipy: 1e-10 or better
 * for p > 1e-300 (tests/data/stats). nl_stats_kolmogorov_sf() is the n -> infinity
 * limit (scipy.stats.kstwobign.sf(D sqrt n)) for those who want it.
 *
 * Two-sample KS (nl_stats_ks2_test): D = max |F1 - F2| over the pooled sample, the
 * p-value exact (lattice-path counting: Hodges 1958, with Viehmann's 2021
 * recursion for 1-p) when both sizes are <= 10000, else the one-sample
 * distribution with n = round(n1 n2 / (n1 + n2)): scipy.stats.ks_2samp(
 * method='auto').
 *
 * Incremental KS for optimisers (nl_stats_ks_incr_*): a sorted copy of the sample
 * that follows one changed value. A move relocates the value with two
 * binary searches and one memmove (O(log n + s), s = how far the value moves
 * in rank) and recomputes the maxima of the blocks of 32 ranks it touched plus
 * a scan of the n/32 block maxima: O(log n + s + 32 + n/32). For n = 512 it
 * does 2.3 million moves/s on a mix of small steps and random jumps, 2.7x the
 * rate of a full O(n) rescan (bench/bench_stats). The result is
 * bit-identical to nl_stats_ks_statistic() on the same sample, because every term
 * is computed by the same expression from the same (rank, F value) pair.
 *
 * Kuiper's V = D+ + D- (nl_stats_kuiper_test) does not depend on where a circle is
 * cut, so it suits angles. The p-value is the four-regime formula of Paltani
 * (2004) / Stephens (1965) used by astropy.stats.kuiper_false_positive_
 * probability: exact expressions for V < 3/n and for V > 1/2 (Stephens 1965),
 * and Stephens' (1970) asymptotic series in lambda = V sqrt(n) in between,
 *   P(V > v) ~ sum_j 2(4j^2 lambda^2 - 1) e^{-2 j^2 lambda^2}
 *              - 8v/3 sum_j j^2 (4 j^2 lambda^2 - 3) e^{-2 j^2 lambda^2}.
 * Accuracy of the series: it errs on the conservative side (never below the
 * true tail); Paltani reports up to 1.5x too high near p = 1e-7 for n = 40-50.
 * Our Monte Carlo check at n = 512 (make_stats_vectors.py) agrees within the
 * simulation's 3-sigma band for p from 0.001 to 0.9.
 *
 * Pearson chi-square on k equal-width bins of [a, b) (nl_stats_chisq_test_uniform):
 * chi2 = sum (O - E)^2 / E, df = k - 1, p = gsl_cdf_chisq_Q(chi2, df)
 * (scipy.stats.chisquare). low_expected is set when E < 5, Cochran's rule for
 * the chi-square approximation to hold (512 values in 500 bins give E = 1.02).
 * Values outside [a, b) are an error: they would be dropped silently otherwise.
 *
 * ECDF and histogram helpers: nl_stats_ecdf_* keep a sorted copy and evaluate the
 * right-continuous step function F_n(t) = #{x_i <= t} / n
 * (scipy.stats.ecdf); nl_stats_histogram_uniform fills a gsl_histogram.
 *
 * Also here: the mean, sd and min of a sample in two named roundings
 * (nl_stats_mean_sd, nl_summary.c) and the sorts under all of the above
 * (nl_stats_sort, nl_stats_argsort, nl_sort.c).
 *
 * Conventions: inputs are const and never reordered (a sorted copy is made);
 * n >= 1 for the one-sample tests; NaN or infinite data give NL_EINVAL; a CDF
 * callback must return values in [0, 1] (others are an error).
 */
#ifndef NL_STATS_H
#define NL_STATS_H

#include "base/nl_base.h"

#include <gsl/gsl_histogram.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A continuous cumulative distribution function. */
typedef double (*nl_stats_cdf_fn)(double x, void *params);

/* F(x) of the uniform distribution on [a, b) with params = double[2]{a, b},
 * clipped to [0, 1]: (x - a) / (b - a), scipy.stats.uniform(a, b - a).cdf. */
double nl_stats_cdf_uniform(double x, void *params);

/* Named distributions with scipy's shape/loc/scale convention, F(x) = F0((x - loc) / scale)
 * with F0 the standard form of scipy.stats.NAME with its shape parameters:
 *   uniform      z on [0, 1]       (uniform on [loc, loc + scale])
 *   norm         Phi(z)            (scipy.special.ndtr's erf/erfc split)
 *   expon        1 - e^-z, z >= 0  (as -expm1(-z))
 *   gamma a      P(a, z)           (regularised lower incomplete gamma, gsl_cdf_gamma_P)
 *   beta a b     I_z(a, b)         (gsl_cdf_beta_P)
 *   lognorm s    Phi(ln z / s)     (scipy's lognorm(s, scale = e^mu))
 *   t df         Student's t       (gsl_cdf_tdist_P)
 *   chi2 df      chi-square        (gsl_cdf_chisq_P)
 *   weibull_min c  1 - exp(-z^c), z >= 0
 *   cauchy       1/2 + atan(z) / pi
 *   logistic     1 / (1 + e^-z)
 *   laplace      e^z / 2 below 0, 1 - e^-z / 2 above
 *   pareto b     1 - z^-b, z >= 1
 *   rayleigh     1 - exp(-z^2 / 2), z >= 0
 * and a tabulated CDF (points x_i strictly increasing, F_i non-decreasing in
 * [0, 1]) interpolated linearly and constant beyond its ends (numpy.interp).
 *   nl_stats_dist dist;
 *   double a = 2.5;
 *   nl_stats_dist_init_shape(&dist, NL_DIST_GAMMA, &a, 1, 0.0, 1.0, &err);
 *   nl_stats_ks_test(x, n, nl_stats_dist_cdf, &dist, &r, &err); // kstest(x, 'gamma', (2.5,))
 * A table's arrays are not copied: they must outlive the dist. */
typedef enum {
  NL_DIST_UNIFORM, NL_DIST_NORM, NL_DIST_EXPON, NL_DIST_GAMMA, NL_DIST_BETA, NL_DIST_LOGNORM,
  NL_DIST_T, NL_DIST_CHI2, NL_DIST_WEIBULL_MIN, NL_DIST_CAUCHY, NL_DIST_LOGISTIC, NL_DIST_LAPLACE,
  NL_DIST_PARETO, NL_DIST_RAYLEIGH, NL_DIST_TABLE
} nl_stats_dist_kind;
typedef struct {
  nl_stats_dist_kind kind;
  double loc, scale;
  double shape[2];
  size_t m;
  const double *x, *F;
} nl_stats_dist;
/* scipy's name ("gamma", "weibull_min", ...) -> kind; NL_EINVAL otherwise. */
nl_status nl_stats_dist_parse(const char *name, nl_stats_dist_kind *kind, nl_error *err);
const char *nl_stats_dist_name(nl_stats_dist_kind kind);
/* How many shape parameters the kind takes (0, 1 or 2), and their scipy names ("a,b"). */
int nl_stats_dist_nshape(nl_stats_dist_kind kind);
const char *nl_stats_dist_shape_names(nl_stats_dist_kind kind);
/* scale > 0 and loc finite, else NL_EINVAL; a kind with shapes is refused. */
nl_status nl_stats_dist_init(nl_stats_dist *d, nl_stats_dist_kind kind, double loc, double scale,
                             nl_error *err);
/* As nl_stats_dist_init with the kind's nshape shapes, each positive and finite. */
nl_status nl_stats_dist_init_shape(nl_stats_dist *d, nl_stats_dist_kind kind, const double *shape,
                                   size_t nshape, double loc, double scale, nl_error *err);
nl_status nl_stats_dist_table(nl_stats_dist *d, const double *x, const double *F, size_t m,
                              nl_error *err);
/* An nl_stats_cdf_fn; params is an nl_stats_dist *. */
double nl_stats_dist_cdf(double x, void *params);

typedef enum {
  NL_KS_RUBEN_GAMBINO,   /* closed forms, D <= 1/n or D >= 1 - 1/n */
  NL_KS_SMIRNOV,         /* 2 x one-sided exact Smirnov tail */
  NL_KS_DURBIN_MTW,      /* Durbin matrix, Marsaglia-Tsang-Wang */
  NL_KS_POMERANZ,
  NL_KS_PELZ_GOOD,
  NL_KS_KOLMOGOROV,      /* n -> infinity limit */
  NL_KS_TWO_SAMPLE_EXACT,
  NL_KS_TWO_SAMPLE_ASYMP /* one-sample law at the effective n */
} nl_stats_ks_method;

/* "ruben-gambino", "smirnov", "durbin-mtw", "pomeranz", "pelz-good",
 * "kolmogorov", "exact", "asymp". */
const char *nl_stats_ks_method_name(nl_stats_ks_method m);

typedef struct {
  double d;          /* statistic, max(d_plus, d_minus) */
  double d_plus, d_minus;
  double p;          /* two-sided P(D >= d) under the null */
  size_t n;          /* sample size (two-sample: n1) */
  size_t n2;         /* two-sample: second size; else 0 */
  nl_stats_ks_method method;
} nl_stats_ks_result;

/* Distribution of the two-sided statistic D_n for a continuous F.
 * nl_stats_ks_sf = P(D_n >= d) (scipy.stats.kstwo.sf), nl_stats_ks_cdf = P(D_n <= d)
 * (kstwo.cdf); each computed directly, not as 1 - the other, so both tails
 * keep full relative accuracy. method may be NULL. n >= 1. */
double nl_stats_ks_sf(size_t n, double d, nl_stats_ks_method *method);
double nl_stats_ks_cdf(size_t n, double d, nl_stats_ks_method *method);
/* One-sided P(D+_n >= d), exact (Birnbaum & Tingey 1951): scipy.special.smirnov. */
double nl_stats_smirnov_sf(size_t n, double d);
/* Kolmogorov's limit P(K > lambda) = 2 sum (-1)^(j-1) exp(-2 j^2 lambda^2):
 * scipy.special.kolmogorov = scipy.stats.kstwobign.sf. */
double nl_stats_kolmogorov_sf(double lambda);

/* P(D_{n1,n2} >= d) for the two-sample statistic: exact for n1, n2 <= 10000
 * (d is rounded to the lattice h / lcm(n1, n2) first), else asymptotic;
 * scipy.stats.ks_2samp(method='auto'). */
double nl_stats_ks2_sf(size_t n1, size_t n2, double d, nl_stats_ks_method *method);

/* One-sided P(D+_{n1,n2} >= d) (the same law for D-): exact for n1, n2 <= 10000
 * while the path counts fit a double, else Hodges' corrected limit;
 * scipy.stats.ks_2samp(alternative='greater', method='auto'). */
double nl_stats_ks2_sf_one_sided(size_t n1, size_t n2, double d, nl_stats_ks_method *method);

/* scipy.stats.ks_2samp's method=: want NL_KS_TWO_SAMPLE_EXACT is the exact law
 * at any sizes whose lcm is below 2^31 - 1 (slow for large ones, as scipy's),
 * NL_KS_TWO_SAMPLE_ASYMP the asymptotic law of nl_stats_ks2_sf (two-sided) or
 * nl_stats_ks2_sf_one_sided (one_sided != 0), any other value 'auto' (those
 * two functions). *method (may be NULL) says which ran: ASYMP after an
 * exact try that overflowed, where scipy warns and falls back too (then,
 * as in scipy, the asymptotic law is of d put on the lattice h / lcm). */
double nl_stats_ks2_sf_method(size_t n1, size_t n2, double d, int one_sided,
                              nl_stats_ks_method want, nl_stats_ks_method *method);

/* scipy.stats.kstest's alternatives, F_n the sample's ECDF and F the null's
 * CDF (two samples: F_1 and F_2): "greater" tests F_n > F somewhere with
 * D+ = max(F_n - F) (max(F_1 - F_2)), "less" F_n < F with D- = max(F - F_n)
 * (max(F_2 - F_1)); two-sided is D = max(D+, D-). */
typedef enum { NL_KS_TWO_SIDED, NL_KS_LESS, NL_KS_GREATER } nl_stats_ks_alternative;
/* "two-sided", "less", "greater"; NL_EINVAL otherwise. */
nl_status nl_stats_ks_alternative_parse(const char *name, nl_stats_ks_alternative *alt,
                                        nl_error *err);
/* Turns a two-sided result of nl_stats_ks_test* (n2 == 0) or nl_stats_ks2_test
 * into the one-sided test's: d = d_plus (greater) or d_minus (less), p from
 * the exact one-sided law (smirnov_sf; two-sample: nl_stats_ks2_sf_one_sided). */
void nl_stats_ks_one_sided(nl_stats_ks_result *r, nl_stats_ks_alternative alt);

/* D+, D-, D of CDF values u[0..n-1] sorted ascending (no p-value). */
void nl_stats_ks_statistic(const double *u, size_t n, double *d_plus, double *d_minus);

nl_status nl_stats_ks_test(const double *x, size_t n, nl_stats_cdf_fn cdf, void *params,
                           nl_stats_ks_result *res, nl_error *err);
/* Against the uniform distribution on [a, b), a < b. */
nl_status nl_stats_ks_test_uniform(const double *x, size_t n, double a, double b,
                                   nl_stats_ks_result *res, nl_error *err);
/* Two-sample test; res->d_plus = max(F1 - F2), res->d_minus = max(F2 - F1). */
nl_status nl_stats_ks2_test(const double *x, size_t n1, const double *y, size_t n2,
                            nl_stats_ks_result *res, nl_error *err);

/* Incremental one-sample statistic. Fields are read-only for callers. */
typedef struct {
  size_t n;
  double *x;          /* sample, sorted ascending */
  double *u;          /* F(x[i]), same order */
  nl_stats_cdf_fn cdf;
  void *params;
  size_t nblocks;
  double *bplus;      /* per block of NL_KS_INCR_BLOCK ranks: max of D+ terms */
  double *bminus;     /* ... and of D- terms */
  double *rank;       /* i / n for i = 0..n: the terms' rank fractions, divided once */
  /* undo record of the last replace (nl_stats_ks_incr_undo) */
  int can_undo;
  size_t from, to;    /* the value moved from rank `from` to rank `to` */
  double ux, uu, ud_plus, ud_minus, ud;
  double *ubplus, *ubminus;   /* the touched blocks' previous maxima, same indices */
  double d_plus, d_minus, d;
} nl_stats_ks_incr;
#define NL_KS_INCR_BLOCK 32

/* Copies and sorts x. Returns NULL (with err) on n = 0, NaN/inf data or
 * CDF values outside [0, 1]. */
nl_stats_ks_incr *nl_stats_ks_incr_alloc(const double *x, size_t n, nl_stats_cdf_fn cdf, void *params,
                                         nl_error *err);
void nl_stats_ks_incr_free(nl_stats_ks_incr *s);
/* Replaces one occurrence of old_value by new_value and updates d_plus,
 * d_minus, d. NL_EINVAL (state unchanged) if old_value is not in the sample or
 * new_value is not finite. To undo a move, replace new_value by old_value. */
nl_status nl_stats_ks_incr_replace(nl_stats_ks_incr *s, double old_value, double new_value,
                                   nl_error *err);
/* Takes back the last successful replace: the state becomes exactly what
 * replacing new_value by old_value would give, without searching or
 * recomputing (the saved values are put back). NL_EINVAL if there is
 * nothing to take back (no replace since the last undo, or it failed). */
nl_status nl_stats_ks_incr_undo(nl_stats_ks_incr *s, nl_error *err);
/* p-value of the current statistic, nl_stats_ks_sf(n, d). */
double nl_stats_ks_incr_p(const nl_stats_ks_incr *s);

typedef struct {
  double v;          /* Kuiper's V = D+ + D- */
  double d_plus, d_minus;
  double p;          /* P(V_n >= v) */
  size_t n;
} nl_stats_kuiper_result;

/* P(V_n >= v) (see the top of this header for the method and its accuracy). */
double nl_stats_kuiper_sf(size_t n, double v);
nl_status nl_stats_kuiper_test(const double *x, size_t n, nl_stats_cdf_fn cdf, void *params,
                               nl_stats_kuiper_result *res, nl_error *err);
nl_status nl_stats_kuiper_test_uniform(const double *x, size_t n, double a, double b,
                                       nl_stats_kuiper_result *res, nl_error *err);

typedef struct {
  double chi2;
  size_t df;           /* k - 1 */
  double p;            /* gsl_cdf_chisq_Q(chi2, df) */
  double min_expected; /* smallest expected count */
  int low_expected;    /* 1 if min_expected < 5: the p-value is unreliable */
  size_t n, k;
} nl_stats_chisq_result;

/* Pearson's test of observed counts against expected counts (k >= 2, all
 * expected > 0): scipy.stats.chisquare(observed, expected). */
nl_status nl_stats_chisq_test(const double *observed, const double *expected, size_t k,
                              nl_stats_chisq_result *res, nl_error *err);
/* Bins x into k equal bins of [a, b) and tests against equal expected counts. */
nl_status nl_stats_chisq_test_uniform(const double *x, size_t n, size_t k, double a, double b,
                                      nl_stats_chisq_result *res, nl_error *err);

/* ---- two samples from their summaries -----------------------------------
 *
 * For a mean and an sd over n independent runs on each side (the regression
 * check's means over seeds):
 *   double p;
 *   nl_stats_welch_p(0.51, 0.02, 10, 0.50, 0.03, 10, &p, &err);  // equal means?
 *   nl_stats_ftest_p(0.02, 10, 0.03, 10, &p, &err);              // equal variances?
 * Welch's t-test (unequal variances): t = |m2 - m1| / sqrt(s1^2/n1 + s2^2/n2),
 * Welch-Satterthwaite df, p = 2 P(T_df > t): scipy.stats.ttest_ind_from_stats(
 * m1, s1, n1, m2, s2, n2, equal_var=False).pvalue, sd with ddof = 1.
 * F-test: F = s2^2 / s1^2 on (n2 - 1, n1 - 1) df, p = min(1, 2 min(P(F' <= F),
 * P(F' >= F))), the two-sided test scipy has no single call for
 * (2 min(f.cdf, f.sf)). One sd 0 and the other not: p = 0. Both sds 0, n < 2,
 * a negative or non-finite sd or mean: NL_EINVAL (nothing to test: compare the
 * values). Accuracy: 1e-12 relative against scipy 1.10's 10 vectors
 * (src/stats/test_meantest.c); against the incomplete beta in long double at
 * 3000 inputs (test_tests_reference.c) F within 2.6e-13 and Welch within
 * 1.6e-11 for p >= 1e-8, but below that GSL's Student tail (a
 * Cornish-Fisher expansion for t^2 < 10 df) drifts: 1e-10 at p = 3e-9, up
 * to 9e-7 relative near p = 1e-30 - far beyond any decision's threshold. */
nl_status nl_stats_welch_p(double m1, double s1, size_t n1, double m2, double s2, size_t n2,
                           double *p, nl_error *err);
nl_status nl_stats_ftest_p(double s1, size_t n1, double s2, size_t n2, double *p, nl_error *err);

/* ---- mean, sd and min of a sample (nl_summary.c) -------------------------
 *
 * Quantities measured over seeds are summarised by their mean and sample
 * sd (divisor n - 1; 0 for n < 2). Two roundings of the same formulas are
 * named, because the committed reference tables were made with both and
 * each keeps its last digits:
 *   NL_STATS_RUNNING  GSL's running mean, m += (x_i - m) / (i + 1), and its
 *                     sd (gsl_stats_mean, gsl_stats_sd);
 *   NL_STATS_SUMMED   the sum in order divided by n, then the sum in order
 *                     of (x_i - m)^2 (two passes).
 *   double m, sd;
 *   nl_stats_mean_sd(x, n, NL_STATS_SUMMED, &m, &sd);
 * n = 0: the mean is NaN (SUMMED) or 0 (RUNNING, as GSL), the sd 0. */
typedef enum { NL_STATS_RUNNING = 0, NL_STATS_SUMMED = 1 } nl_stats_rounding;

double nl_stats_mean(const double *x, size_t n, nl_stats_rounding rounding);
double nl_stats_sd(const double *x, size_t n, nl_stats_rounding rounding);
void nl_stats_mean_sd(const double *x, size_t n, nl_stats_rounding rounding, double *mean,
                      double *sd);
/* The same for a sample from outside (the Python binding): n = 0, which has
 * no mean (statistics.mean raises, numpy warns and gives NaN), and an
 * unknown rounding are NL_EINVAL ("sample: no values"), mean and sd then
 * untouched. */
nl_status nl_stats_mean_sd_checked(const double *x, size_t n, nl_stats_rounding rounding,
                                   double *mean, double *sd, nl_error *err);
/* The smallest x (fmin: a NaN is passed over unless all are NaN); n >= 1. */
double nl_stats_min(const double *x, size_t n);

/* Empirical CDF: a sorted copy of the sample. */
typedef struct {
  size_t n;
  double *x;   /* sorted ascending */
} nl_stats_ecdf;
nl_stats_ecdf *nl_stats_ecdf_alloc(const double *x, size_t n, nl_error *err);
void nl_stats_ecdf_free(nl_stats_ecdf *e);
/* F_n(t) = #{x_i <= t} / n, by binary search: O(log n). */
double nl_stats_ecdf_eval(const nl_stats_ecdf *e, double t);

/* A gsl_histogram with k equal bins on [a, b) holding x; values outside
 * [a, b) are counted in *outside (may be NULL) and not binned. */
gsl_histogram *nl_stats_histogram_uniform(const double *x, size_t n, size_t k, double a,
                                          double b, size_t *outside, nl_error *err);

/* The bin of v among k equal bins of [a, b] by the rule nl_stats_histogram_uniform
 * and nl_stats_chisq_test_uniform use (numpy.histogram's): the index computed
 * arithmetically, then corrected against the bin edges a + i (b - a)/k so
 * that a value on an edge goes to the bin the edge opens; the last bin is
 * closed, values above b clamp to it. Exported, as GSL exports
 * gsl_histogram_find, for code that keeps bin counts itself (the chi-square
 * term of the Cheng optimiser updates one count per move) and must bin
 * exactly as the test it is checked against. k >= 1, a < b. */
size_t nl_stats_chisq_bin(double v, size_t k, double a, double b);

/* Sorts doubles ascending: introsort specialised for double below 4096
 * values (3-4x faster than qsort with a comparison callback at n = 512), an
 * LSD radix sort on the doubles' bits from 4096 (9x faster than introsort
 * on a 256^2 image's pixels). -0 and +0 are equal values (either may come first). NaN
 * not allowed. */
void nl_stats_sort(double *x, size_t n);
/* order[k] = the index of the k-th smallest x (numpy's argsort with
 * kind='stable'): equal values, -0 and +0 included, in index order (the
 * radix sort at every n). NaN not allowed. */
void nl_stats_argsort(const double *x, size_t n, size_t *order);

#ifdef __cplusplus
}
#endif

#endif
