/* variants.c - L3's variants of synthesis by example (sec. 5, Fig. 5
 * and 6) and one of them run over the seeds. See synthesis.h. */
#include "synthesis.h"

#include <math.h>
#include <stdlib.h>

static const char *variants[L3_NVAR] = {"pca_hist", "pca_nohist", "rgb_hist", "pca_hist_fc",
                                        "pca_hist_gauss33"};
/* {decorrelate, histogram, sigma2, tile, hist_kind, calibrate}; pca_hist_fc
 * differs from pca_hist by its spline only (l3_variant()). */
static const nl_byexample_options var_opt[L3_NVAR] = {
    {1, 1, 0, 0, NL_HIST_PAPER, 0}, {1, 0, 0, 0, NL_HIST_PAPER, 0}, {0, 1, 0, 0, NL_HIST_PAPER, 0},
    {1, 1, 0, 0, NL_HIST_PAPER, 0}, {1, 1, 0, 0, NL_HIST_GAUSS, 0}};

nl_image *l3_variant(nl_harness *r, nl_table *kt, const char *kind, int v, const nl_image *ex,
                     int size)
{
  int K = nl_harness_seeds(r);
  nl_error err;
  nl_byexample_params p;
  if (nl_byexample_analyse(ex, &var_opt[v], &p, &err))
    nl_harness_die(r, 1, "%s: %s", kind, err.msg);
  nl_byexample_spline_kind spline = v == 3 ? NL_SPLINE_FRITSCH_CARLSON : NL_SPLINE_STEFFEN;
  nl_byexample_synth_options so = {1, 0, 0, spline};
  double *ks = malloc((size_t)K * 5 * sizeof *ks);
  double *per = ks + K;
  double *cs = per + 3 * K;
  /* The K syntheses on the run's threads; sums in seed order after them. */
  nl_image *first = l3_synth_seeds(&p, &so, ex, size, K, nl_harness_seed(r),
                                   nl_harness_threads(r), ks, per, cs, &err);
  if (!first) nl_harness_die(r, 1, "%s: %s", kind, err.msg);
  double acc[3] = {0};
  double m = 0;
  double ss = 0;
  double ce = 0;
  for (int s = 0; s < K; s++) {
    for (int c = 0; c < 3; c++) acc[c] += per[3 * s + c] / K;
    ce += cs[s] / K;
    m += ks[s] / K;
  }
  double cv = 0;
  for (int s = 0; s < K; s++) {
    ss += (ks[s] - m) * (ks[s] - m);
    cv += (cs[s] - ce) * (cs[s] - ce);
  }
  nl_table_append(kt, "ssddddddidi", kind, variants[v], m, K > 1 ? sqrt(ss / (K - 1)) : 0.0,
                  acc[0], acc[1], acc[2], ce, nl_byexample_param_count(&p),
                  K > 1 ? sqrt(cv / (K - 1)) : 0.0, K);
  free(ks);
  return first;
}
