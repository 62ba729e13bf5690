/* claims.c - L2's verdict rows (claims.h). */
#include "claims.h"
#include "byexample/nl_byexample_leak.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

void l2_trend(const double *err, const int *sizes, int nsizes, int seeds, double *mean, double *sd,
              double *p)
{
  *mean = 0;
  *sd = 0;
  *p = 1;
  if (nsizes < 2 || seeds < 1) return;
  double xm = 0, sxx = 0, m = 0, ss = 0;
  for (int i = 0; i < nsizes; i++) xm += log2(sizes[i]) / nsizes;
  for (int i = 0; i < nsizes; i++) sxx += (log2(sizes[i]) - xm) * (log2(sizes[i]) - xm);
  double b[4096];
  int k = seeds < 4096 ? seeds : 4096;
  for (int s = 0; s < k; s++) { /* slope = sum (x - xm) y / sxx */
    b[s] = 0;
    for (int i = 0; i < nsizes; i++) b[s] += (log2(sizes[i]) - xm) * err[i * seeds + s] / sxx;
    m += b[s] / k;
  }
  for (int s = 0; s < k; s++) ss += (b[s] - m) * (b[s] - m);
  *mean = m;
  if (k < 2) return;
  *sd = sqrt(ss / (k - 1));
  double se = *sd / sqrt(k);
  *p = se > 0 ? gsl_cdf_tdist_P(m / se, k - 1) : (m < 0 ? 0 : 1);
}

nl_table *l2_claims(nl_harness *r, const nl_table *et, int size, const double *err_all,
                    const double *err_fine, const int *sizes, int nsizes, int seeds, int fine,
                    nl_table **trend)
{
  const char *cols[] = { "quantity", "paper", "ours", "ours_sd", "seeds" };
  nl_table *t = nl_table_alloc(5, cols);
  char q[128];
  snprintf(q, sizeof q, "relative RMS weight error, eq. 12, %d px", size);
  for (size_t i = 0; i < et->nrows; i++)
    if ((int)nl_table_value(et, i, "size") == size &&
        !strcmp(nl_table_text(et, i, "estimator"), nl_byexample_estimator_names[0]))
      nl_table_append(t, "sdddi", q, 0.0, nl_table_value(et, i, "err_mean"),
                      nl_table_value(et, i, "err_sd"), seeds);
  nl_harness_write_table(r, t, "similar.tsv");
  if (t->nrows)
    nl_harness_verdict(r, "similar.tsv", t, 0, "estimated weights very similar (Fig. 4)", "paper",
                       "ours", "ours_sd", L2_SIMILAR_RULE, "independent",
                       "relative RMS error of eq. 12's weights over the sweep's seeds; "
                       "thresholds a tenth and a quarter, fixed before the run");

  const char *tcols[] = { "bands", "slope_mean", "slope_sd", "p_falls", "seeds", "sizes" };
  nl_table *tt = nl_table_alloc(6, tcols);
  double m, sd, p;
  l2_trend(err_all, sizes, nsizes, seeds, &m, &sd, &p);
  nl_table_append(tt, "sdddii", "all", m, sd, p, seeds, nsizes);
  l2_trend(err_fine, sizes, nsizes, seeds, &m, &sd, &p);
  snprintf(q, sizeof q, "%d finest", fine);
  nl_table_append(tt, "sdddii", q, m, sd, p, seeds, nsizes);
  nl_harness_write_table(r, tt, "trend.tsv");
  nl_harness_verdict_p(r, "trend.tsv", tt, 0, "weight error falls with image size",
                       "power converges with sample size", "slope_mean", "p_falls", "p 0.01 0.05",
                       "independent",
                       "each seed's least-squares slope on log2 side, one-sided one-sample t-test "
                       "over seeds");
  nl_harness_verdict_p(r, "trend.tsv", tt, 1, "weight error of the finest bands falls with size",
                       "power converges with sample size", "slope_mean", "p_falls", "p 0.01 0.05",
                       "independent",
                       "the same test over the bands that exist at every size of the sweep");
  *trend = tt;
  return t;
}
