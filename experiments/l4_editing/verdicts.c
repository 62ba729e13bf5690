/* verdicts.c - L4's verdict rows (verdicts.h). */
#include "verdicts.h"
#include "stats/nl_stats.h"

#include <stdlib.h>

nl_table *l4_verdicts(const l4 *q, const l4_edit *rep)
{
  int K = q->K;
  double *v = nl_xcalloc((size_t)3 * K, sizeof *v); /* R, F, A per seed */
  for (int s = 0; s < K; s++) {
    double p = 0, pr = 0, pf = 0;
    int nb = q->nfine < rep[s].nbands ? q->nfine : rep[s].nbands;
    for (int k = 0; k < nb; k++) { /* [0]: with histogram matching */
      p += rep[s].power[0][k];
      pr += rep[s].power[0][k] * rep[s].ratio[0][k];
      pf += rep[s].power[0][k] * rep[s].floor[0][k];
    }
    v[s] = pr / p;
    v[K + s] = pf / p;
    v[2 * K + s] = (pr - pf) / (p - pf);
  }
  double m[3], sd[3];
  for (int i = 0; i < 3; i++)
    nl_stats_mean_sd(v + (size_t)i * K, K, NL_STATS_SUMMED, &m[i], &sd[i]);
  free(v);
  const char *cols[] = { "quantity", "paper", "ours", "ours_sd", "floor", "floor_sd", "seeds" };
  nl_table *t = nl_table_alloc(7, cols);
  double f2 = q->factor * q->factor;
  nl_table_append(t, "sdddddi", "edited bands' power / original", f2, m[0], sd[0], m[1], sd[1], K);
  nl_table_append(t, "sdddddi", "edited bands' own power / original (floor removed)", f2, m[2],
                  sd[2], m[1], sd[1], K);
  nl_harness_write_table(q->r, t, "edit_claims.tsv");
  nl_harness_verdict(q->r, "edit_claims.tsv", t, 0, "edited bands' power falls by factor^2",
                     "paper", "ours", "ours_sd", "factor 1.25 2", "independent",
                     "luminance power of the attenuated bands after / before the edit, histogram "
                     "matching on; the power other bands leak into them stays (column floor)");
  nl_harness_verdict(q->r, "edit_claims.tsv", t, 1, "edited bands' own power falls by factor^2",
                     "paper", "ours", "ours_sd", "sd 2 4", "independent",
                     "the same above the leakage floor measured by removing the bands: "
                     "(ratio - floor) / (1 - floor)");
  nl_harness_verdict_figure(q->r, "texture morphing by interpolating parameters",
                            "Fig. 12: a texture morphs into another", "morph.png",
                            "matrix by quaternion slerp, the rest linear");
  return t;
}
