/* claims.c - L2's verdict rows (claims.h). */
#include "claims.h"
#include "byexample/nl_byexample_leak.h"

#include "byexample/nl_byexample.h"
#include "stats/nl_stats.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_rng.h>
#include <stdlib.h>
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

void l2_random_errors(const unsigned long *seeds, int n, const int *sizes, int nsizes, int nfine,
                      double *err, double *fine)
{
  const double lo = NL_BYEXAMPLE_TRUE_WEIGHT_MIN, hi = NL_BYEXAMPLE_TRUE_WEIGHT_MAX;
  for (int j = 0; j < nsizes; j++) {
    int nb = nl_byexample_band_count(sizes[j], sizes[j]);
    for (int i = 0; i < n; i++) {
      gsl_rng *t = gsl_rng_alloc(gsl_rng_mt19937), *g = gsl_rng_alloc(gsl_rng_mt19937);
      gsl_rng_set(t, nl_seed_stream(seeds[i], "byexample.true_weights", 0)); /* the trial's */
      gsl_rng_set(g, nl_seed_stream(seeds[i], "l2.random_weights", (unsigned long)sizes[j]));
      double se = 0, st = 0, sef = 0, stf = 0;
      for (int k = 0; k < nb; k++) {
        double w = lo + (hi - lo) * gsl_rng_uniform(t), v = lo + (hi - lo) * gsl_rng_uniform(g);
        se += (v - w) * (v - w);
        st += w * w;
        if (k < nfine) {
          sef += (v - w) * (v - w);
          stf += w * w;
        }
      }
      gsl_rng_free(t);
      gsl_rng_free(g);
      err[j * n + i] = sqrt(se / st);
      fine[j * n + i] = stf > 0 ? sqrt(sef / stf) : 0;
    }
  }
}

/* l2_trend of log2 of the errors: the slope per doubling of log2 error. */
static void log_trend(const double *err, const int *sizes, int nsizes, int seeds, double *mean,
                      double *sd)
{
  size_t n = (size_t)nsizes * (size_t)seeds;
  double *l = nl_xmalloc(n * sizeof *l), p;
  for (size_t i = 0; i < n; i++) l[i] = log2(err[i]);
  l2_trend(l, sizes, nsizes, seeds, mean, sd, &p);
  free(l);
}

nl_table *l2_claims(nl_harness *r, int size, const double *err_all, const double *err_fine,
                    const int *sizes, int nsizes, int seeds, int fine, unsigned long seed0,
                    nl_table **trend)
{
  size_t n = (size_t)nsizes * (size_t)seeds;
  unsigned long *sd_seeds = nl_xmalloc((size_t)seeds * sizeof *sd_seeds);
  for (int i = 0; i < seeds; i++)
    sd_seeds[i] = nl_seed_stream(seed0, "l2.size_trial", (unsigned long)i);
  double *ra = nl_xmalloc(n * sizeof *ra), *rf = nl_xmalloc(n * sizeof *rf);
  l2_random_errors(sd_seeds, seeds, sizes, nsizes, fine, ra, rf);
  free(sd_seeds);

  const char *cols[] = { "quantity", "paper", "ours", "ours_sd", "ours_se", "seeds" };
  nl_table *t = nl_table_alloc(6, cols);
  char q[128];
  int at = -1;
  for (int j = 0; j < nsizes; j++)
    if (sizes[j] == size) at = j;
  for (int c = 0; c < 2 && at >= 0; c++) {
    double m, sd;
    nl_stats_mean_sd((c ? ra : err_all) + (size_t)at * seeds, seeds, NL_STATS_SUMMED, &m, &sd);
    snprintf(q, sizeof q, "relative RMS weight error, %s, %d px", c ? "random weights" : "eq. 12",
             size);
    nl_table_append(t, "sddddi", q, 0.0, m, sd, sd / sqrt((double)seeds), seeds);
  }
  nl_harness_write_table(r, t, "similar.tsv");
  const char *ctl = "weights drawn at random from the true weights' range";
  if (t->nrows) {
    nl_harness_verdict_equiv(r, "similar.tsv", t, 0, "estimated weights very similar (Fig. 4)",
                             "paper", "ours", "ours_se", "seeds", L2_SIMILAR_RULE, "independent",
                             "relative RMS error of eq. 12's weights over the sweep's seeds; "
                             "margin a tenth, fixed before the run");
    nl_harness_verdict_control(r, ctl, "similar.tsv", t, 1);
  }

  const char *tcols[] = { "bands",        "slope_mean",   "slope_sd",        "p_falls",
                          "log_slope_mean", "log_slope_sd", "log_slope_se",  "paper_log_slope",
                          "seeds",        "sizes" };
  nl_table *tt = nl_table_alloc(10, tcols);
  const double *src[4] = { err_all, err_fine, ra, rf };
  for (int k = 0; k < 4; k++) {
    double m, sd, p, lm, lsd;
    l2_trend(src[k], sizes, nsizes, seeds, &m, &sd, &p);
    log_trend(src[k], sizes, nsizes, seeds, &lm, &lsd);
    if (k % 2)
      snprintf(q, sizeof q, "%d finest%s", fine, k > 1 ? ", random weights" : "");
    else
      snprintf(q, sizeof q, "all%s", k > 1 ? ", random weights" : "");
    nl_table_append(tt, "sdddddddii", q, m, sd, p, lm, lsd, lsd / sqrt((double)seeds), -1.0,
                    seeds, nsizes);
  }
  free(ra);
  free(rf);
  nl_harness_write_table(r, tt, "trend.tsv");
  nl_harness_verdict_p(r, "trend.tsv", tt, 0, "weight error falls with image size",
                       "power converges with sample size", "slope_mean", "p_falls", "p 0.01 0.05",
                       "independent",
                       "each seed's least-squares slope on log2 side, one-sided one-sample t-test "
                       "over seeds");
  nl_harness_verdict_control(r, ctl, "trend.tsv", tt, 2);
  nl_harness_verdict_p(r, "trend.tsv", tt, 1, "weight error of the finest bands falls with size",
                       "power converges with sample size", "slope_mean", "p_falls", "p 0.01 0.05",
                       "independent",
                       "the same test over the bands that exist at every size of the sweep");
  nl_harness_verdict_control(r, ctl, "trend.tsv", tt, 3);
  nl_harness_verdict_equiv(r, "trend.tsv", tt, 1,
                           "weight error of the finest bands halves per doubling of the side",
                           "paper_log_slope", "log_slope_mean", "log_slope_se", "seeds",
                           L2_HALVING_RULE, "independent",
                           "each seed's slope of log2 error on log2 side: sampling error of the "
                           "band powers predicts -1");
  nl_harness_verdict_control(r, ctl, "trend.tsv", tt, 3);
  *trend = tt;
  return t;
}
