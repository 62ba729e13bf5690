/* C2's equivalence test (equiv.h). */
#include "equiv.h"
#include "stats/nl_stats.h"

#include <math.h>

/* P(T > t) from the two-sided Welch p of |t|: half of it when t > 0. */
static double one_sided(double t, double p_two) { return t > 0 ? p_two / 2 : 1 - p_two / 2; }

nl_status c2_tost_p(double mean_a, double sd_a, size_t n_a, double mean_b, double sd_b, size_t n_b,
                    double margin, double *p, nl_error *err)
{
  if (!(margin > 0)) return nl_fail(err, NL_EINVAL, "TOST margin must be > 0, got %g", margin);
  double d = mean_a - mean_b;
  double p_lo, p_hi;
  /* H0 d <= -margin: the shifted difference d + margin, from mean_a + margin */
  if (nl_stats_welch_p(mean_a + margin, sd_a, n_a, mean_b, sd_b, n_b, &p_lo, err)) return NL_EINVAL;
  /* H0 d >= margin: margin - d, from mean_b + margin */
  if (nl_stats_welch_p(mean_a, sd_a, n_a, mean_b + margin, sd_b, n_b, &p_hi, err)) return NL_EINVAL;
  *p = fmax(one_sided(d + margin, p_lo), one_sided(margin - d, p_hi));
  return NL_OK;
}

nl_table *c2_equiv_alloc(void)
{
  const char *cols[] = { "pattern", "a",  "b",     "seeds",  "mean_a",  "mean_b", "no_diff",
                         "diff",    "diff_pct", "se", "n_eff", "margin", "p_welch", "p_tost" };
  return nl_table_alloc(sizeof cols / sizeof *cols, cols);
}

double c2_equiv_margin(double sd_a, double sd_b) { return sqrt(0.5 * (sd_a * sd_a + sd_b * sd_b)); }

size_t c2_equiv_add(nl_table *t, const char *pattern, const char *a, const char *b, double ma,
                    double sa, size_t na, double mb, double sb, size_t nb, double margin)
{
  double va = sa * sa / (double)na, vb = sb * sb / (double)nb;
  double se = sqrt(va + vb);
  double df = va + vb > 0 ? (va + vb) * (va + vb) /
                                (va * va / ((double)na - 1) + vb * vb / ((double)nb - 1))
                          : (double)(na + nb - 2);
  double pw, pt;
  nl_error err;
  if (nl_stats_welch_p(ma, sa, na, mb, sb, nb, &pw, &err)) pw = ma == mb ? 1 : 0;
  if (c2_tost_p(ma, sa, na, mb, sb, nb, margin, &pt, &err)) pt = fabs(ma - mb) < margin ? 0 : 1;
  nl_table_append(t, "sssddddddddddd", pattern, a, b, (double)na, ma, mb, 0.0, mb - ma,
                  100 * (mb - ma) / ma, se, df + 1, margin, pw, pt);
  return t->nrows - 1;
}
