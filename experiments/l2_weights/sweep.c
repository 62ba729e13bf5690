/* sweep.c - L2's error against image size over seeds (sweep.h). */
#include "sweep.h"
#include "byexample/nl_byexample_leak.h"
#include "stats/nl_stats.h"

#include <math.h>
#include <stdlib.h>

enum { NE = NL_BYEXAMPLE_ESTIMATORS, MB = NL_WAVELET_MAX_BANDS };
#define MIN_SIZE 64 /* the sweep's smallest side: every size has the 6 finest bands */

/* Mean and sd over seeds at one size, each estimator's paired p against
 * eq. 12 (q = 0), one row per estimator; the corrected estimator's numbers
 * feed the report's summary. */
static void summarise(nl_table *et, l2_sweep *sw, const double *E, int s, int n)
{
  int k = sw->seeds;
  for (int q = 0; q < NE; q++) {
    for (int c = 0; c < 3; c++)
      nl_stats_mean_sd(E + (c * NE + q) * k, k, NL_STATS_SUMMED, &sw->m[c][q], &sw->v[c][q]);
    double p = 1;
    sw->pf = 1;
    if (q) {
      p = nl_byexample_paired_p(E + q * k, E, k);
      sw->pf = nl_byexample_paired_p(E + (NE + q) * k, E + NE * k, k);
    }
    nl_table_append(et, "iisdddddddi", s, n, nl_byexample_estimator_names[q], sw->m[0][q],
                    sw->v[0][q], sw->m[1][q], sw->v[1][q], sw->m[2][q], p, sw->pf, k);
    if (q == NL_BYEXAMPLE_CORRECTED) {
      sw->below += sw->m[0][q] < sw->m[0][0];
      sw->pmax = fmax(sw->pmax, p);
      sw->p_last = p;
    }
  }
}

nl_table *l2_size_sweep(nl_harness *r, int tile, unsigned long seed0, l2_sweep *sw,
                        nl_table **bands)
{
  const char *ecols[] = { "size",      "bands",          "estimator",   "err_mean",
                          "err_sd",    "err_fine_mean",  "err_fine_sd", "power_ratio",
                          "p_vs_eq12", "p_fine_vs_eq12", "seeds" };
  const char *bcols[] = { "size", "band", "estimator", "rmse", "bias" };
  nl_table *et = nl_table_alloc(11, ecols);
  nl_table *bt = nl_table_alloc(5, bcols);
  nl_byexample_transfer T;
  int k = sw->seeds;
  for (int s = MIN_SIZE; s <= sw->maxsize && sw->nsizes < 16; s *= 2) sw->sizes[sw->nsizes++] = s;
  sw->err_all = malloc((size_t)sw->nsizes * k * sizeof *sw->err_all);
  sw->err_fine = malloc((size_t)sw->nsizes * k * sizeof *sw->err_fine);
  double *E = malloc((size_t)3 * NE * k * sizeof *E); /* error, fine error, power */
  double rms[NE * MB], bias[NE * MB];
  unsigned long *seeds = malloc((size_t)k * sizeof *seeds);
  for (int i = 0; i < k; i++) seeds[i] = nl_seed_stream(seed0, "l2.size_trial", (unsigned long)i);
  for (int done = 0; done < sw->nsizes; done++) {
    int s = sw->sizes[done];
    int n = nl_byexample_band_count(s, s);
    nl_error err;
    if (nl_byexample_transfer_measure(&T, tile, s, s, n, sw->frac, sw->tseeds,
                                      nl_seed_stream(seed0, "l2.transfer", (unsigned long)s),
                                      nl_harness_threads(r), &err))
      nl_harness_die(r, 1, "error-against-size sweep: %s", err.msg);
    nl_byexample_trials(&T, seeds, k, sw->fine, E, rms, bias, nl_harness_threads(r));
    for (int q = 0; q < NE; q++)
      for (int b = 0; b < n; b++)
        nl_table_append(bt, "iisdd", s, b, nl_byexample_estimator_names[q], rms[q * n + b],
                        bias[q * n + b]);
    for (int b = 0; b < n && s == sw->maxsize; b++)
      sw->bbelow += rms[NL_BYEXAMPLE_CORRECTED * n + b] < rms[b];
    for (int i = 0; i < k; i++) { /* eq. 12 (estimator 0): error, fine error */
      sw->err_all[done * k + i] = E[i];
      sw->err_fine[done * k + i] = E[NE * k + i];
    }
    summarise(et, sw, E, s, n);
    nl_harness_progress(r, (done + 1.0) / sw->nsizes, "size sweep");
  }
  free(E);
  free(seeds);
  *bands = bt;
  return et;
}
