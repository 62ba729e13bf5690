/* verdicts.c - L3's verdict rows (verdicts.h). */
#include "verdicts.h"
#include "byexample/nl_byexample.h"

#include <stdio.h>
#include <string.h>

/* Sums of column col and of "replicates" over pt's rows of representation rep. */
static void count(const nl_table *pt, const char *rep, const char *col, int *pass, int *all)
{
  *pass = 0;
  *all = 0;
  for (size_t i = 0; i < pt->nrows; i++) {
    if (strcmp(nl_table_text(pt, i, "representation"), rep)) continue;
    *pass += (int)nl_table_value(pt, i, col);
    *all += (int)nl_table_value(pt, i, "replicates");
  }
}

nl_table *l3_verdicts(nl_harness *r, const nl_table *pt, int psize)
{
  const char *cols[] = { "quantity", "representation", "paper", "ours", "passes", "syntheses" };
  nl_table *t = nl_table_alloc(6, cols);
  int pass, all;
  count(pt, "paper10", "passes", &pass, &all);
  nl_table_append(t, "ssddii", "photo syntheses passing band power and KS", "paper10", 1.0,
                  all ? (double)pass / all : 0.0, pass, all);
  count(pt, "calibrated", "passes", &pass, &all);
  nl_table_append(t, "ssddii", "photo syntheses passing band power and KS", "calibrated", 1.0,
                  all ? (double)pass / all : 0.0, pass, all);
  count(pt, "paper10", "structure_passes", &pass, &all);
  nl_table_append(t, "ssddii", "photo syntheses keeping the photo's coherence", "paper10", 1.0,
                  all ? (double)pass / all : 0.0, pass, all);
  /* the paper's count: channels^2 + channels (10 quantiles + bands of a 512^2 exemplar) */
  nl_byexample_params p = { .channels = 3,
                            .nbands = nl_byexample_band_count(512, 512),
                            .nhist = NL_BYEXAMPLE_HIST };
  nl_table_append(t, "ssddii", "parameters of a 512 x 512 RGB texture", "paper10",
                  (double)L3_PAPER_PARAMS, (double)nl_byexample_param_count(&p), 0, 0);
  nl_harness_write_table(r, t, "claims.tsv");

  /* Passing syntheses as a fraction of all: reproduced when at least 90% pass, partly at least
   * half ("all syntheses look like their photo" read as nearly all, not as a majority). */
  nl_harness_verdict(r, "claims.tsv", t, 0, "photo syntheses passing (paper's method)", "paper",
                     "ours", NULL, "abs 0.1 0.5", "independent",
                     "fraction of photo x replicate syntheses meeting both criteria; the paper's "
                     "10 quantiles, weights by eq. 12");
  /* gains: one per channel and synthesis band, fitted to the photo's band powers (one per
   * channel and photo band; the largest photo's count) */
  int kfit = 3 * nl_byexample_band_count(psize, psize), mfit = 0;
  for (size_t i = 0; i < pt->nrows; i++) {
    int nb = (int)nl_table_value(pt, i, "coarsest_band") + 1;
    if (3 * nb > mfit) mfit = 3 * nb;
  }
  char kind[32];
  snprintf(kind, sizeof kind, "fitted %d/%d", kfit, mfit > 0 ? mfit : 1);
  nl_harness_verdict(r, "claims.tsv", t, 1, "photo syntheses passing (calibrated, not the paper's)",
                     "paper", "ours", NULL, "abs 0.1 0.5", kind,
                     "band gains fitted on the realisation to the photo's band powers and the "
                     "histogram matched by rank: the criteria's own quantities; not random-access");
  nl_harness_verdict(r, "claims.tsv", t, 2, "photo structure kept (paper's method)", "paper",
                     "ours", NULL, "abs 0.1 0.5", "independent",
                     "structure-tensor coherence of the synthesis within the band criterion's "
                     "factor of the photo's");
  nl_harness_verdict(r, "claims.tsv", t, 3, "parameters per texture (512 x 512 RGB)", "paper",
                     "ours", NULL, "abs 0 0", "by construction",
                     "3 x 3 matrix, 10 quantiles and one weight per eq. 13 band per channel");
  return t;
}
