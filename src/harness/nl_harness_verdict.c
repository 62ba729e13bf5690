/* nl_harness_verdict.c - the decision behind a row of REPORT.md's verdict
 * table (nl_harness.h, "verdicts"). The thresholds are the experiment's,
 * stated in the rule; this file only measures the distance the rule names
 * and words it. The reason says where ours lies, not the thresholds: the
 * rule beside it in verdicts.tsv (and REPORT.md's rule column) states them
 * once. */
#include "harness/nl_harness.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int has_prefix(const char *s, const char *prefix)
{
  return !strncmp(s, prefix, strlen(prefix));
}

nl_status nl_harness_verdict_kind_check(const char *kind, nl_error *err)
{
  unsigned long k, m;
  int used = 0;
  if (kind && (!strcmp(kind, "independent") || !strcmp(kind, "by construction") ||
               !strcmp(kind, "qualitative")))
    return NL_OK;
  if (kind && has_prefix(kind, "fitted ") && sscanf(kind, "fitted %lu/%lu%n", &k, &m, &used) == 2 &&
      !kind[used] && k >= 1 && m >= 1)
    return NL_OK;
  if (kind && has_prefix(kind, "selected ") && sscanf(kind, "selected 1/%lu%n", &m, &used) == 1 &&
      !kind[used] && m >= 2)
    return NL_OK;
  return nl_fail(err, NL_EINVAL,
                 "verdict kind '%s': wanted independent, fitted K/M, selected 1/N, by construction "
                 "or qualitative", kind ? kind : "(null)");
}

const char *nl_harness_verdict_word(nl_harness_outcome outcome, const char *kind)
{
  if (!strcmp(kind, "by construction")) return "by construction";
  if (!strcmp(kind, "qualitative")) return "see figure";
  /* A row fitted to, or selected by closeness to, the paper's numbers is no
   * independent evidence: its word names the fit or the selection whatever
   * the outcome, so that no fitted row is read (or counted) as a verdict. */
  int fit = has_prefix(kind, "fitted"), sel = has_prefix(kind, "selected");
  if (fit || sel) {
    if (outcome == NL_VERDICT_REPRODUCED) return fit ? "consistent after fit" : "consistent after selection";
    if (outcome == NL_VERDICT_PARTLY)
      return fit ? "partly consistent after fit" : "partly consistent after selection";
    return fit ? "not consistent after fit" : "not consistent after selection";
  }
  return outcome == NL_VERDICT_REPRODUCED ? "reproduced"
         : outcome == NL_VERDICT_PARTLY   ? "partly"
                                          : "not reproduced";
}

nl_status nl_harness_verdict_decide(const char *rule, double paper, double ours, double sd,
                                    nl_harness_outcome *verdict, char *reason, size_t len,
                                    nl_error *err)
{
  char kind[16];
  double a, b;
  int used = 0;
  if (sscanf(rule, "%15s %lf %lf %n", kind, &a, &b, &used) != 3 || rule[used])
    kind[0] = 0;
  if (!strcmp(kind, "equiv"))
    return nl_fail(err, NL_EINVAL, "verdict rule '%s': an equivalence needs its degrees of freedom: "
                   "nl_harness_verdict_decide_equiv", rule);
  if (!strcmp(kind, "p") || !strcmp(kind, "fit")) {
    /* p-value rules: "p A B" an effect (small p), "fit A B" a law (large p) */
    int effect = !strcmp(kind, "p");
    if (!(a >= 0 && b <= 1 && (effect ? b >= a : a >= b)))
      return nl_fail(err, NL_EINVAL, "verdict rule '%s': wanted 'p A B' with 0 <= A <= B <= 1 or "
                     "'fit A B' with 1 >= A >= B >= 0", rule);
    if (!(ours >= 0 && ours <= 1))
      return nl_fail(err, NL_EINVAL, "verdict rule '%s': p-value %g not in [0, 1]", rule, ours);
    if (effect)
      *verdict = ours <= a ? NL_VERDICT_REPRODUCED : ours <= b ? NL_VERDICT_PARTLY : NL_VERDICT_NOT;
    else
      *verdict = ours >= a ? NL_VERDICT_REPRODUCED : ours >= b ? NL_VERDICT_PARTLY : NL_VERDICT_NOT;
    snprintf(reason, len, "p = %.2g", ours);
    return NL_OK;
  }
  if (!kind[0] || !(a >= 0) || !(b >= a) ||
      (strcmp(kind, "rel") && strcmp(kind, "abs") && strcmp(kind, "factor") && strcmp(kind, "sd")))
    return nl_fail(err, NL_EINVAL, "verdict rule '%s': wanted 'rel|abs|factor|sd A B' with 0 <= A <= B, "
                   "'p A B' or 'fit A B'", rule);
  if (!isfinite(paper) || !isfinite(ours))
    return nl_fail(err, NL_EINVAL, "verdict rule '%s': paper %g, ours %g: not finite", rule, paper, ours);
  double d, diff = ours - paper;   /* d: the distance the rule measures */
  if (!strcmp(kind, "rel")) {
    if (paper == 0) return nl_fail(err, NL_EINVAL, "verdict rule '%s': the paper's value is 0", rule);
    d = fabs(diff) / fabs(paper);
    snprintf(reason, len, "%.3g%% %s the paper", 100 * d, diff >= 0 ? "above" : "below");
  } else if (!strcmp(kind, "abs")) {
    d = fabs(diff);
    snprintf(reason, len, "%.3g %s the paper", d, diff >= 0 ? "above" : "below");
  } else if (!strcmp(kind, "factor")) {
    if (!(paper > 0) || !(ours > 0))
      return nl_fail(err, NL_EINVAL, "verdict rule '%s': paper %g and ours %g must be > 0", rule, paper, ours);
    d = ours > paper ? ours / paper : paper / ours;
    snprintf(reason, len, "x%.3g %s the paper", d, ours >= paper ? "above" : "below");
  } else {
    if (!(sd >= 0)) return nl_fail(err, NL_EINVAL, "verdict rule '%s': needs the spread of ours", rule);
    d = sd > 0 ? fabs(diff) / sd : (diff == 0 ? 0 : INFINITY);
    if (isinf(d)) snprintf(reason, len, "%.4g from the paper with sd 0", diff);
    else snprintf(reason, len, "%.3g sd %s the paper", d, diff >= 0 ? "above" : "below");
  }
  *verdict = d <= a ? NL_VERDICT_REPRODUCED : d <= b ? NL_VERDICT_PARTLY : NL_VERDICT_NOT;
  return NL_OK;
}

/* Two one-sided tests (Schuirmann 1987): ours - paper = d with standard
 * error se on df degrees of freedom is shown to lie inside (-M, M) when
 * both H0: d <= -M and H0: d >= M are rejected; the p-value is the larger
 * of the two one-sided p's. A failure to reject a difference never counts
 * as equality here: a wide se gives a large p whatever d is. */
nl_status nl_harness_verdict_decide_equiv(const char *rule, double paper, double ours, double se,
                                          double df, nl_harness_outcome *verdict, char *reason,
                                          size_t len, nl_error *err)
{
  char scale[8];
  double m, a, b;
  int used = 0;
  if (sscanf(rule, "equiv %7s %lf %lf %lf %n", scale, &m, &a, &b, &used) != 4 || rule[used] ||
      (strcmp(scale, "rel") && strcmp(scale, "abs")) || !(m > 0) || !(a >= 0) || !(b >= a) || !(b <= 1))
    return nl_fail(err, NL_EINVAL, "verdict rule '%s': wanted 'equiv rel|abs M A B' with M > 0 and "
                   "0 <= A <= B <= 1", rule);
  if (!isfinite(paper) || !isfinite(ours) || !(se >= 0) || !isfinite(se))
    return nl_fail(err, NL_EINVAL, "verdict rule '%s': paper %g, ours %g, se %g: not finite", rule, paper,
                   ours, se);
  int rel = !strcmp(scale, "rel");
  if (rel && paper == 0) return nl_fail(err, NL_EINVAL, "verdict rule '%s': the paper's value is 0", rule);
  double margin = rel ? m * fabs(paper) : m, d = ours - paper, p;
  if (se == 0) p = fabs(d) < margin ? 0 : 1;
  else if (df >= 1) p = fmax(gsl_cdf_tdist_Q((d + margin) / se, df), gsl_cdf_tdist_P((d - margin) / se, df));
  else p = fmax(gsl_cdf_ugaussian_Q((d + margin) / se), gsl_cdf_ugaussian_P((d - margin) / se));
  *verdict = p <= a ? NL_VERDICT_REPRODUCED : p <= b ? NL_VERDICT_PARTLY : NL_VERDICT_NOT;
  if (rel)
    snprintf(reason, len, "TOST p = %.2g within +-%.3g%%: %.3g%% %s the paper, se %.2g%%", p, 100 * m,
             100 * fabs(d) / fabs(paper), d >= 0 ? "above" : "below", 100 * se / fabs(paper));
  else
    snprintf(reason, len, "TOST p = %.2g within +-%.3g: %.3g %s the paper, se %.2g", p, m, fabs(d),
             d >= 0 ? "above" : "below", se);
  return NL_OK;
}
