/* C4's trend (Cheng 2009 sec. 4.3.2: "the pattern can be well-preserved
 * with larger weight in control term"): over the dense sweep of w1 / w2,
 * Spearman's rho of r with the pattern on log(w2 / w1), beside the same
 * test of the same tables against the pattern shuffled, which no weight can
 * make them follow. */
#include "c4.h"
#include "study/nl_study_cheng.h"

#include <math.h>
#include <stdlib.h>

#define NPERM 9999

nl_table *c4_trend(const nl_study_cheng *s, const nl_cheng_config *base, const nl_cheng_pattern *pat,
                   const nl_table *sweep, nl_noise_grad2 *const *tables, const double *rhos,
                   int nsweep)
{
  int k = nl_harness_seeds(s->r);
  unsigned long seed = nl_harness_seed(s->r);
  nl_cheng_pattern *sh = nl_study_cheng_pattern_shuffled(pat, nl_seed_stream(seed, "c4.shuffle", 0));
  double *x = nl_xmalloc((size_t)nsweep * sizeof *x), *y = nl_xmalloc((size_t)nsweep * sizeof *y);
  double *ys = nl_xmalloc((size_t)nsweep * sizeof *ys);
  for (int j = 0; j < nsweep; j++) {
    x[j] = -log10(rhos[j]); /* log10(w2 / w1) */
    y[j] = nl_table_value(sweep, (size_t)j, "r_pattern");
    ys[j] = 0;
    for (int i = 0; i < k; i++)
      ys[j] += nl_study_cheng_pattern_r(tables[(size_t)j * k + i], base, sh) / k;
  }
  const char *cols[] = { "tables", "points", "rho", "p_perm", "n_perm" };
  nl_table *t = nl_table_alloc(5, cols);
  double rho, p = nl_study_spearman_perm_p(x, y, (size_t)nsweep, NPERM,
                                           nl_seed_stream(seed, "c4.trend", 0), &rho);
  nl_table_append(t, "sdddd", "optimised, pattern", (double)nsweep, rho, p, (double)NPERM);
  p = nl_study_spearman_perm_p(x, ys, (size_t)nsweep, NPERM, nl_seed_stream(seed, "c4.trend", 1),
                               &rho);
  nl_table_append(t, "sdddd", "optimised, pattern shuffled", (double)nsweep, rho, p, (double)NPERM);
  nl_harness_write_table(s->r, t, "trend.tsv");
  nl_harness_report_table(s->r, t,
                          "Trend of r with the pattern on log(w2 / w1) over the sweep: Spearman's "
                          "rho and its one-sided permutation p; the same tables against the pattern "
                          "shuffled as the control",
                          4);
  nl_cheng_pattern_free(sh);
  free(x);
  free(y);
  free(ys);
  return t;
}
