/* C2's own-statistic table (c2.h): each objective's statistic under it and
 * under the other objectives, so that "the KS objective has the lower E_KS"
 * sits beside "the Kuiper objective has the lower V" - its control. */
#include "c2.h"
#include "harness/nl_harness.h"

nl_table *c2_own_alloc(void)
{
  const char *cols[] = { "pattern", "statistic", "objective", "seeds", "value", "value_sd" };
  return nl_table_alloc(sizeof cols / sizeof *cols, cols);
}

size_t c2_own_add(nl_table *own, const nl_table *sum, size_t row, const char *pattern,
                  const char *objective, const char *statistic)
{
  char sd[64];
  snprintf(sd, sizeof sd, "%s_sd", statistic);
  nl_table_append(own, "sssddd", pattern, statistic, objective, nl_table_value(sum, row, "seeds"),
                  nl_table_value(sum, row, statistic), nl_table_value(sum, row, sd));
  return own->nrows - 1;
}

void c2_own_verdicts(nl_harness *r, nl_table *own, const nl_table *sum, const char *p, size_t ks,
                     size_t chi, size_t ku)
{
  /* Two claims compare an objective with another on its own statistic; the
   * Kuiper objective on V against the same other objective is the control
   * (any objective wins on the statistic it minimises). */
  size_t o_ks = c2_own_add(own, sum, ks, p, "ks", "E_ks");
  size_t o_ks_chi = c2_own_add(own, sum, chi, p, "chisq", "E_ks");
  size_t o_chi = c2_own_add(own, sum, chi, p, "chisq", "chi2");
  size_t o_chi_ks = c2_own_add(own, sum, ks, p, "ks", "chi2");
  size_t o_ku = c2_own_add(own, sum, ku, p, "kuiper", "V_kuiper");
  size_t o_ku_chi = c2_own_add(own, sum, chi, p, "chisq", "V_kuiper");
  size_t o_ku_ks = c2_own_add(own, sum, ks, p, "ks", "V_kuiper");
  char q[2][64];
  snprintf(q[0], sizeof q[0], "E_KS, KS vs chi-square objective, %s", p);
  snprintf(q[1], sizeof q[1], "chi2, chi-square vs KS objective, %s", p);
  nl_harness_verdict_less(r, "own.tsv", own, o_ks, o_ks_chi, q[0], "KS CDF closer to ideal",
                          "value", "value_sd", "seeds", 0.05, "independent");
  nl_harness_verdict_control_less(r, "the Kuiper objective against the chi-square one on V",
                                  "own.tsv", own, o_ku, o_ku_chi);
  nl_harness_verdict_less(r, "own.tsv", own, o_chi, o_chi_ks, q[1],
                          "chi2 lower under its objective", "value", "value_sd", "seeds", 0.05,
                          "independent");
  nl_harness_verdict_control_less(r, "the Kuiper objective against the KS one on V", "own.tsv", own,
                                  o_ku, o_ku_ks);
}
